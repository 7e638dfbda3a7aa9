// SPDX-License-Identifier: GPL-3.0-or-later
// The stages of the program `feature_segmentation` that its subcommands share: reading
// the mesh and segmenting it (Pipeline), and the outputs (boundaries, smoothing, refined
// mesh, patch files, summary.json). The timing of the stages and what summary.json holds
// are in run_report.h.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_PIPELINE_H
#define CGAL_FEATURE_SEGMENTATION_APP_PIPELINE_H

#include "edit_runner.h"
#include "edit_script.h"
#include "option_table.h"
#include "read_input_mesh.h"
#include "read_user_feature_lines.h"
#include "run_report.h"
#include "typed_polylines.h"

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/IO/write_boundaries.h>
#include <CGAL/Feature_segmentation/IO/write_feature_lines.h>
#include <CGAL/Feature_segmentation/IO/write_refined_segmentation.h>
#include <CGAL/Feature_segmentation/IO/write_segmentation.h>
#include <CGAL/Feature_segmentation/Watershed_distance.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/face_patches.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>

#include <CGAL/property_map.h>

#include <boost/range/counting_range.hpp>

#include <unistd.h> // getpid: names of temporary output files

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fs_app {

// Writes a file through `write`, atomically: into a temporary file next to it, renamed
// over `path` once complete, so that an interrupted run never leaves a half-written file
// under the final name. Fails with a clear message when it cannot.
template <typename Write>
inline void write_file(const std::filesystem::path& path, Write&& write)
{
  std::filesystem::path temporary = path;
  temporary += ".partial-" + std::to_string(static_cast<long long>(::getpid()));
  try
  {
    std::ofstream out(temporary);
    if(!out)
      throw std::runtime_error(path.string() + ": cannot be opened for writing");
    write(out);
    out.close();
    if(!out)
      throw std::runtime_error(path.string() + ": write failed (disk full?)");
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if(ec)
      throw std::runtime_error(path.string() + ": cannot be written (" + ec.message() + ")");
  }
  catch(...)
  {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

/// One mesh through the pipeline: read (`load()`), segmented (`segment()`), edited (the
/// segmentation is public, and `edit_runner()` applies script edits to it), and written
/// (`write_outputs()`). Shared by the subcommands `segment` and `edit`. Not copyable: the
/// segmentation refers to the mesh.
class Pipeline
{
public:
  typedef FS::Feature_aligned_segmentation<Mesh> Segmentation;

  Pipeline(const Options& options, Stage_timer& timer, Results& results)
    : m_options(options), m_timer(timer), m_results(results)
  {}
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  /// Reads the input mesh (stage "load").
  /// \throws Input_error on a file that cannot be read or repaired
  void load()
  {
    m_results.read_report = m_timer.run("load", [&]() {
      return read_input_mesh(m_options.input, mesh, correspondence);
    });
    loaded();
  }

  /// Makes the mesh from a polygon soup in memory (stage "load"), with the repairs of the
  /// file readers; `name` names it in messages.
  /// \throws Input_error if the soup cannot be made a mesh the pipeline can process
  void load(Mesh_soup& soup, const std::string& name)
  {
    m_results.read_report = m_timer.run("load", [&]() {
      return mesh_from_soup(name, soup, mesh, correspondence);
    });
    loaded();
  }

private:
  void loaded()
  {
    Results& results = m_results;
    if(!m_options.quiet)
      for(const std::string& notice : results.read_report.notices)
        std::cerr << "notice: " << m_options.input << ": " << notice << '\n';
    results.number_of_vertices = num_vertices(mesh);
    results.number_of_edges = num_edges(mesh);
    results.number_of_faces = num_faces(mesh);
    if(!m_options.quiet)
      std::cerr << "mesh: " << results.number_of_vertices << " vertices, "
                << results.number_of_faces << " faces" << std::endl;
  }

public:
  /// Runs the automatic segmentation (stages "curvature" and "feature_lines" with
  /// --feature-edges, then "segmentation").
  void segment()
  {
    const Options& options = m_options;
    Results& results = m_results;
    Stage_timer& timer = m_timer;
    // The segmentation class detects the curvature and the crest lines itself, on the
    // mesh cut open along its creases (working_mesh()), where the fits see one side of a
    // crease at a time. User feature lines (--feature-edges) are located on the input mesh
    // and added to the lines detected there, as before creases existed.
    const auto common = FS::parameters::alpha(options.alpha)
                          .gamma(options.gamma)
                          .crease_angle(options.crease_angle)
                          .crease_filter_iterations(options.crease_filter)
                          .tangent_discontinuities(options.tangent_discontinuities)
                          .crest_lines_on_clean_tessellations(options.crest_lines_on_clean_tessellations)
                          .neighborhood_rings(options.rings)
                          .neighborhood_radius(options.radius)
                          .strength_threshold(options.strength_threshold ? *options.strength_threshold
                                                                         : FS::default_strength_threshold)
                          .detect_ridges(options.ridges)
                          .detect_valleys(options.valleys)
                          .solver(Timed_solver(options.solver, last_solver_seconds))
                          .use_oversegmentation(!options.full_graph)
                        .concurrency_tag(CGAL::Parallel_if_available_tag())
                          .watershed_distance(options.watershed == "geodesic" ? FS::Watershed_distance::GEODESIC
                                                                              : FS::Watershed_distance::ANISOTROPIC);
    if(!options.feature_edges_file.empty())
    {
      auto curvature_map =
        mesh.add_property_map<Mesh::Vertex_index, FS::Principal_curvatures<K> >("v:fs_principal_curvatures").first;
      timer.run("curvature", [&]() {
        FS::estimate_principal_curvatures(mesh, curvature_map, FS::parameters::neighborhood_rings(options.rings)
                                                               .neighborhood_radius(options.radius)
                                                               .concurrency_tag(CGAL::Parallel_if_available_tag()));
      });
      FS::Feature_lines<Mesh> lines = timer.run("feature_lines", [&]() {
        FS::Feature_lines<Mesh> detected;
        if(options.ridges || options.valleys)
          detected = FS::detect_crest_lines(
            mesh, curvature_map,
            FS::parameters::strength_threshold(options.strength_threshold ? *options.strength_threshold
                                                                          : FS::default_strength_threshold)
              .detect_ridges(options.ridges)
              .detect_valleys(options.valleys));
        results.number_of_user_lines = fs_app::read_user_feature_lines(options.feature_edges_file, mesh, detected);
        return detected;
      });
      timer.run("segmentation", [&]() {
        segmentation.emplace(mesh, common.principal_curvature_map(curvature_map).feature_lines(std::cref(lines)));
      });
    }
    else
      timer.run("segmentation", [&]() { segmentation.emplace(mesh, common); });
    segmentation->set_undo_memory_limit(options.undo_memory_mib << 20);
    const FS::Feature_lines<Mesh>& lines = segmentation->feature_lines();
    results.number_of_ridges = lines.number_of_lines(FS::Feature_line_type::RIDGE);
    results.number_of_valleys = lines.number_of_lines(FS::Feature_line_type::VALLEY);
    results.number_of_seam_crossings = lines.number_of_lines(FS::Feature_line_type::SEAM);
    results.number_of_lines = lines.lines.size();
    results.number_of_feature_edges = segmentation->number_of_feature_edges();
    results.number_of_crease_edges = segmentation->number_of_crease_edges();
    if(!options.quiet)
      std::cerr << "feature lines: " << results.number_of_ridges << " ridges, "
                << results.number_of_valleys << " valleys, " << results.number_of_seam_crossings
                << " seam lines, " << results.number_of_user_lines << " user; "
                << results.number_of_crease_edges << " crease edges; " << results.number_of_feature_edges
                << " feature edges" << std::endl;
    results.solver_seconds = last_solver_seconds;
    results.segmentation_stages = segmentation->stage_times();
    // the patches that hold a face (a patch of the vertex labels may win no face's majority)
    results.number_of_automatic_patches = results.number_of_patches = number_of_face_patches();
    results.automatic_cut_cost = results.cut_cost = segmentation->cut_cost();
    results.number_of_oversegments = segmentation->number_of_oversegments();
    if(!options.quiet)
      std::cerr << "segmentation: " << results.number_of_patches << " patches, cut cost "
                << results.cut_cost << ", " << results.number_of_oversegments << " oversegments"
                << " (solver " << options.solver << ": " << std::fixed << std::setprecision(3)
                << results.solver_seconds << " s)" << std::defaultfloat << std::endl;
  }

  /// Applies script edits to the segmentation, timing each.
  Edit_runner<Mesh, K>& edit_runner()
  {
    if(!m_runner) m_runner = std::make_unique<Edit_runner<Mesh, K> >(mesh, correspondence, *segmentation, last_solver_seconds);
    return *m_runner;
  }

  /// The edits that an `undo` would take back, and those a `redo` would make again.
  std::size_t number_of_undoable_edits() const { return m_runner ? m_runner->number_of_undoable_edits() : 0; }
  std::size_t number_of_redoable_edits() const { return m_runner ? m_runner->number_of_redoable_edits() : 0; }

  // What the editor and the Python module show, in plain coordinates (x y z x y z ...).

  /// The points of a feature line (on the working mesh); a closed one repeats its first.
  std::vector<double> line_coordinates(const FS::Feature_line<Mesh>& line) const
  {
    const Mesh& wm = segmentation->working_mesh();
    std::vector<double> xyz;
    for(const auto& p : line.points)
    {
      const K::Point_3 q = p.point(wm, get(CGAL::vertex_point, wm));
      xyz.insert(xyz.end(), {q.x(), q.y(), q.z()});
    }
    if(line.is_closed && !xyz.empty()) xyz.insert(xyz.end(), xyz.begin(), xyz.begin() + 3);
    return xyz;
  }

  /// The crease edges, two points each.
  std::vector<double> crease_segments() const
  {
    std::vector<double> xyz;
    for(Mesh::Edge_index e : mesh.edges())
      if(segmentation->is_crease_edge(e))
        for(Mesh::Vertex_index v : {mesh.source(mesh.halfedge(e)), mesh.target(mesh.halfedge(e))})
          xyz.insert(xyz.end(), {mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    return xyz;
  }

  /// The patch boundaries, smoothed as the outputs are (`smooth`) or not.
  FS::Patch_boundaries<Mesh> boundaries(bool smooth) const
  {
    FS::Patch_boundaries<Mesh> b = segmentation->patch_boundaries();
    if(smooth)
      FS::smooth_patch_boundaries(b, FS::parameters::smoothing_iterations(
                                       m_options.smoothing_iterations ? *m_options.smoothing_iterations
                                                                      : default_smoothing_iterations));
    return b;
  }

  /// The patch of every point and face of the input file, in file order (-1: a point no
  /// face uses), in the boundaries `b` of the current segmentation (see
  /// Feature_aligned_segmentation::face_patches(b, map) and vertex_patches(b, map)).
  struct File_patches
  {
    std::vector<long> vertices, faces;
  };
  File_patches file_patches(const FS::Patch_boundaries<Mesh>& b) const
  {
    auto vertex_patch = get(CGAL::dynamic_vertex_property_t<long>(), mesh);
    auto face_patch = get(CGAL::dynamic_face_property_t<long>(), mesh);
    segmentation->vertex_patches(b, vertex_patch);
    segmentation->face_patches(b, face_patch);
    File_patches file;
    for(Mesh::Vertex_index v : correspondence.vertex_of_file_point)
      file.vertices.push_back(v == Mesh::null_vertex() ? -1L : get(vertex_patch, v));
    for(Mesh::Face_index f : correspondence.face_of_file_face) file.faces.push_back(get(face_patch, f));
    return file;
  }

  /// The number of distinct ids >= 0 in `ids`.
  template <typename Id>
  static std::size_t number_of_distinct_ids(const std::vector<Id>& ids)
  {
    std::vector<Id> sorted;
    for(Id i : ids) if(i >= 0) sorted.push_back(i);
    std::sort(sorted.begin(), sorted.end());
    return std::size_t(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
  }

  /// The number of patches of the current segmentation that hold a face (face_patches()).
  std::size_t number_of_face_patches() const { return fs_app::number_of_face_patches(mesh, *segmentation); }

  /// The points of a boundary curve; a closed one repeats its first.
  static std::vector<double> curve_coordinates(const FS::Boundary_curve<Mesh>& c)
  {
    std::vector<double> xyz;
    for(const auto& p : c.points) xyz.insert(xyz.end(), p.point.begin(), p.point.end());
    if(c.is_closed() && !xyz.empty()) xyz.insert(xyz.end(), xyz.begin(), xyz.begin() + 3);
    return xyz;
  }

  /// Writes `history` as output_dir/edits.txt, headed by the options of its replay.
  void write_edits_file(const std::vector<Script_edit>& history, const std::string& made_by) const
  {
    write_file(std::filesystem::path(m_options.output_dir) / "edits.txt", [&](std::ostream& os) {
      os << "# " << history.size() << " edits of " << made_by << "\n"
         << "# replay: feature_segmentation MESH" << segmentation_options_text(m_options) << " --edits edits.txt\n";
      write_edit_script(os, history);
    });
  }

  /// Writes every output of the current segmentation into `options.output_dir` (stages
  /// "boundaries", "smoothing", "refinement", "write"), summary.json last.
  void write_outputs()
  {
    const Options& options = m_options;
    Results& results = m_results;
    Stage_timer& timer = m_timer;
    namespace sfs = std::filesystem;
    std::error_code ec;
    // The boundaries of the final patches, in the metric of the weights, from the
    // segmentation's own precomputation (which knows the sketches' feature points).
    FS::Patch_boundaries<Mesh> boundaries =
      timer.run("boundaries", [&]() { return segmentation->patch_boundaries(); });
    results.number_of_curves = boundaries.curves().size();
    results.number_of_junctions = boundaries.number_of_junctions();
    results.length_before = boundaries.length();
    results.anisotropic_length_before = boundaries.anisotropic_length();
    const FS::Boundary_smoothing_report smoothing = timer.run("smoothing", [&]() {
      return options.smoothing_iterations
               ? FS::smooth_patch_boundaries(
                   boundaries, FS::parameters::smoothing_iterations(*options.smoothing_iterations))
               : FS::smooth_patch_boundaries(boundaries);
    });
    results.smoothing_seconds = timer.seconds_of("smoothing");
    results.smoothing_iterations_run = smoothing.number_of_iterations;
    results.smoothing_vertex_moves = smoothing.number_of_vertex_moves;
    results.length_after = boundaries.length();
    results.anisotropic_length_after = boundaries.anisotropic_length();

    // The patches of the final (smoothed) boundaries: every face has the patch covering
    // most of its area, every vertex its patch after the smoothing.
    auto face_patch = mesh.add_property_map<Mesh::Face_index, long>("f:fs_patch", -1).first;
    segmentation->face_patches(boundaries, face_patch);
    const File_patches file = file_patches(boundaries);

    // Every feature used, typed, and every boundary between two patches
    const std::vector<Typed_polyline> features = typed_feature_lines(mesh, *segmentation);
    const std::vector<Typed_polyline> boundary_lines = typed_boundary_lines(mesh, *segmentation, boundaries, face_patch);
    results.number_of_crease_lines = number_of_polylines(features, "crease");
    results.number_of_seam_lines = number_of_polylines(features, "seam");
    results.number_of_crease_curves = number_of_polylines(boundary_lines, "crease");
    if(!options.quiet)
      std::cerr << "boundaries: " << results.number_of_crease_curves << " curves on creases (exact), "
                << results.number_of_curves << " inside faces, length " << results.length_before << " -> "
                << results.length_after << " (smoothing: " << results.smoothing_vertex_moves
                << " vertex moves in " << results.smoothing_iterations_run << " of at most "
                << (options.smoothing_iterations ? *options.smoothing_iterations : default_smoothing_iterations)
                << " iterations)" << std::endl;

    const sfs::path dir(options.output_dir);
    // summary.json marks a complete set of outputs: a previous run's goes first, and the
    // new one is written last.
    sfs::remove(dir / "summary.json", ec);
    // The refined mesh goes to its file straight from the refinement (stage
    // "refinement"): the mesh itself would double the memory the refinement takes.
    const FS::Refined_segmentation_sizes refined = timer.run("refinement", [&]() {
      FS::Refined_segmentation_sizes sizes;
      write_file(dir / "segmentation_refined.ply",
                 [&](std::ostream& os) { sizes = FS::write_PLY_refined_segmentation(os, boundaries); });
      return sizes;
    });
    results.number_of_split_faces = refined.number_of_split_faces;
    results.number_of_refined_vertices = refined.number_of_vertices;
    results.number_of_refined_faces = refined.number_of_faces;

    results.number_of_patches = number_of_distinct_ids(file.faces);
    results.cut_cost = segmentation->cut_cost();
    // The other files are independent: written by TBB's threads, one file per task.
    const std::vector<std::pair<const char*, std::function<void(std::ostream&)> > > files = {
      { "feature_lines.polylines.txt", [&](std::ostream& os) { write_typed_polylines(os, features); } },
      { "feature_lines.types.txt", [&](std::ostream& os) { write_polyline_types(os, features); } },
      { "feature_lines.obj", [&](std::ostream& os) { write_typed_OBJ_lines(os, features); } },
      { "segmentation.ply", [&](std::ostream& os) { FS::write_PLY_segmentation(os, mesh, face_patch); } },
      { "boundaries.polylines.txt", [&](std::ostream& os) { write_typed_polylines(os, boundary_lines); } },
      { "boundaries.types.txt", [&](std::ostream& os) { write_polyline_types(os, boundary_lines); } },
      { "face_patches.txt",
        [&](std::ostream& os) {
          FS::write_patch_ids(os, boost::counting_range(std::size_t(0), file.faces.size()),
                              CGAL::make_property_map(file.faces));
        } },
      { "vertex_patches.txt",
        [&](std::ostream& os) {
          FS::write_patch_ids(os, boost::counting_range(std::size_t(0), file.vertices.size()),
                              CGAL::make_property_map(file.vertices));
        } } };
    timer.run("write", [&]() {
#ifdef CGAL_LINKED_WITH_TBB
      // the first error of a task is rethrown here (TBB cancels the others)
      tbb::parallel_for(std::size_t(0), files.size(), [&](std::size_t i) { write_file(dir / files[i].first, files[i].second); });
#else
      for(const auto& f : files) write_file(dir / f.first, f.second);
#endif
    });
    // Written last, so that it holds the time of every stage.
    write_file(dir / "summary.json",
               [&](std::ostream& os) { write_summary(os, options, results, timer.seconds(), timer.peak_mib()); });
  }

  Mesh mesh;                                   ///< the input, repaired and triangulated
  Input_correspondence<Mesh> correspondence;   ///< input file <-> mesh
  std::optional<Segmentation> segmentation;    ///< after segment()
  double last_solver_seconds = 0;              ///< written by the solver at each solve

private:
  const Options& m_options;
  Stage_timer& m_timer;
  Results& m_results;
  std::unique_ptr<Edit_runner<Mesh, K> > m_runner;
};

// Creates the output folder, or fails with a clear message before any time is spent on
// the mesh.
inline void create_output_dir(const Options& options)
{
  std::error_code ec;
  std::filesystem::create_directories(options.output_dir, ec);
  if(ec || !std::filesystem::is_directory(options.output_dir))
    throw std::runtime_error(options.output_dir + ": cannot create the output folder" +
                             (ec ? " (" + ec.message() + ")" : std::string()));
}

/// The subcommand `segment` on one mesh: reads it, segments it, applies --edits, writes
/// every output. Returns what it measured.
inline Results segment_and_write(const Options& options)
{
  Stage_timer timer(options.quiet);
  Results results;
  create_output_dir(options);

  // A mistake in the edit script is found before the mesh is read; face indices are
  // checked against the file as soon as it is read.
  Edit_script script;
  if(!options.edits_file.empty())
    script = read_edit_script(options.edits_file);

  Pipeline pipeline(options, timer, results);
  pipeline.load();
  check_face_indices(script, results.read_report.number_of_file_faces, num_faces(pipeline.mesh));
  pipeline.segment();

  if(!script.edits.empty())
  {
    Edit_runner<Mesh, K>& runner = pipeline.edit_runner();
    runner.count_face_patches = true; // the summary's and the printed lines' count
    timer.run("edits", [&]() {
      for(const Script_edit& e : script.edits)
      {
        results.edits.push_back(runner.apply(script, e));
        const Edit_record& r = results.edits.back();
        if(!options.quiet)
          std::cerr << "edit " << options.edits_file << ":" << r.line << ": " << r.verb << ": "
                    << r.patches << " patches, cut cost " << r.cut_cost << " (" << std::fixed
                    << std::setprecision(3) << r.seconds << " s)" << std::defaultfloat << std::endl;
      }
    });
  }
  pipeline.write_outputs();
  return results;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_PIPELINE_H
