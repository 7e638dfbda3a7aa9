// SPDX-License-Identifier: GPL-3.0-or-later
// The CAD part of the quality evaluation (issue 13), run by evaluate_quality.
//
// The CAD table. The parts of DATA/cad (NAME.obj, a closed triangle mesh meshed from a
// B-rep, and NAME.labels, the B-rep face of every triangle, in the OBJ's face order),
// scored by the boundary F-score at 1% of the bounding-box diagonal (compare_boundaries()
// of metrics.h, on the face patches, against the B-rep faces) for:
// - this package at its defaults: creases at 20 degrees, normals filtered before the
//   creases are found (none on a clean mesh), curvature discontinuities, alpha 0.6 (the
//   command line may change alpha, the strength threshold, the filter, the
//   discontinuities and the crest lines: Cad_options);
// - the paper's pipeline (crease_angle 180: crest lines only; fitted on rings alone,
//   neighborhood_radius 0), alpha 0.6 and the default strength threshold;
// - CGAL's sharp_edges_segmentation at 20, 45 and 60 degrees;
// - CGAL's variational shape approximation given the true patch count (seeded);
// each at the noise levels asked (Gaussian, along the vertex normals, standard deviation
// relative to the diagonal, seed 1; by default 0, 0.1% and 0.3%). For every part it
// also gives the share of true boundary length whose dihedral angle is below 20 degrees
// (tangent-continuous: a fillet meeting a plane), which no crease threshold can see. The
// ABC models of DATA/abc (NAME.obj with NAME.yml, e.g. the hex nut) follow the CAD
// parts, outside their mean. Written to OUT/cad_parts.md (the means, then a table per
// noise level) and OUT/cad_parts.csv (a row per part, noise level and method, then the
// means), the markdown printed.
//
// The resolution series. Fandisk at its 13k faces and flat-subdivided (each triangle into
// four by its edge midpoints, CGAL's PTQ with the linear mask: the geometry unchanged)
// once, twice and three times (52k, 207k, 828k faces), segmented by this package at the
// settings of the CAD table's first column: the patch count of each, and the boundary
// precision, recall and F-score of each result against the coarse result's boundaries.
// The meshes differ, so the boundaries are compared as 3D segments
// (compare_boundaries_across_meshes()). Written to OUT/resolution.md and
// OUT/resolution.csv, the markdown printed.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PARTS_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PARTS_H

#include "abc_ground_truth.h"
#include "methods.h"
#include "report.h"
#include "scenes.h"

#include "read_input_mesh.h" // the program's reader: the parts are read as a user's files are

#include <unistd.h> // getpid: a temporary file per process
#include <zlib.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fs_evaluation {

/// The settings of the CAD table and of the resolution series: the noise levels, and the
/// parameters of this package's first column (the library's defaults unless the command
/// line changes them). The paper's column shares the filter, the discontinuities and the
/// crest-line switch, but keeps the paper's alpha and strength threshold.
struct Cad_options
{
  std::vector<double> noise = {0., 0.001, 0.003}; ///< standard deviations, fractions of the diagonal
  int crease_filter = FS::default_crease_filter_iterations;
  double alpha = FS::default_alpha;
  double strength_threshold = FS::default_strength_threshold;
  bool tangent = FS::default_tangent_discontinuities;
  bool crest_lines = FS::default_crest_lines_on_clean_tessellations;
  std::set<std::string> methods; ///< the CSV names of cad_methods() to run; empty: all
  /// Whether the method of cad_methods() at `k` runs.
  bool runs(std::size_t k) const;
};

/// The settings of the first column, for the reports.
inline std::string settings_text(const Cad_options& o)
{
  return "alpha " + plain(o.alpha) + ", strength threshold " + plain(o.strength_threshold) + ", crease filter " +
         std::to_string(o.crease_filter) + " rounds, curvature discontinuities " + (o.tangent ? "on" : "off") +
         ", crest lines on clean tessellations " + (o.crest_lines ? "on" : "off");
}

/// The number of distinct labels.
template <typename Label>
std::size_t number_of_distinct(const std::vector<Label>& labels)
{
  return std::set<Label>(labels.begin(), labels.end()).size();
}

/// A part with its ground truth: the patch (B-rep face, ABC surface) of every face.
struct Cad_part
{
  std::string name;
  Mesh mesh;
  std::vector<int> labels;
};

/// The kinds of ground-truth files: NAME.obj with NAME.labels (DATA/cad), NAME.obj.gz
/// with NAME.labels (DATA/abc-dev: native ABC meshes, gzipped), NAME.obj with NAME.yml
/// (DATA/abc: the ABC feature format); NAME.obj with NAME.labels made by gmsh from the
/// scripts of benchmark/Feature_segmentation/generated (the build's generated parts).
enum class Part_format { OBJ_LABELS, GZIPPED_OBJ_LABELS, ABC_YML, GENERATED_OBJ_LABELS };

/// The set a part belongs to, named as in the tables.
inline std::string part_set(Part_format format)
{
  switch(format)
  {
    case Part_format::OBJ_LABELS: return "cad";
    case Part_format::GZIPPED_OBJ_LABELS: return "abc-dev";
    case Part_format::GENERATED_OBJ_LABELS: return "generated";
    default: return "abc";
  }
}

/// Unpacks the gzip file `gz` into the file `out`. Returns false with `error` set on failure.
inline bool gunzip_file(const std::filesystem::path& gz, const std::filesystem::path& out, std::string& error)
{
  gzFile in = gzopen(gz.string().c_str(), "rb");
  if(in == nullptr)
  {
    error = "cannot open " + gz.string();
    return false;
  }
  std::ofstream file(out, std::ios::binary);
  std::vector<char> buffer(1 << 16);
  int n = 0;
  while((n = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0)
    file.write(buffer.data(), n);
  int code = Z_OK;
  const char* message = gzerror(in, &code);
  gzclose(in);
  if(n < 0 || code != Z_OK || !file)
  {
    error = "cannot unpack " + gz.string() + (n < 0 ? std::string(": ") + message : std::string());
    return false;
  }
  return true;
}

/// The file's labels, one per face of the file, put on the mesh faces the program's
/// reader made of them (a duplicate face of the file keeps its first occurrence's face).
inline bool read_labels_of_file_faces(const std::filesystem::path& path,
                                      const fs_app::Input_correspondence<Mesh>& correspondence,
                                      std::size_t number_of_faces, std::vector<int>& labels, std::string& error)
{
  std::ifstream in(path);
  std::vector<int> file_labels;
  int label;
  while(in >> label) file_labels.push_back(label);
  if(file_labels.size() != correspondence.face_of_file_face.size())
  {
    error = path.string() + ": " + std::to_string(file_labels.size()) + " labels for " +
            std::to_string(correspondence.face_of_file_face.size()) + " faces";
    return false;
  }
  labels.assign(number_of_faces, -1);
  std::vector<face_descriptor> mesh_faces;
  for(std::size_t f = file_labels.size(); f-- > 0;) // the first occurrence wins
  {
    mesh_faces.clear();
    correspondence.mesh_faces_of_file_face(f, mesh_faces);
    for(face_descriptor m : mesh_faces) labels[m.idx()] = file_labels[f];
  }
  return true;
}

/// Reads a part (Part_format): a NAME.obj or NAME.obj.gz (unpacked into a temporary file)
/// with the program's reader, which repairs as it does for a user (duplicates, edges of
/// more than two faces), and NAME.labels; or NAME.obj with NAME.yml (the name gets "abc_"
/// before it). Returns false with `error` set when the mesh or its labels cannot be read,
/// or when a face has no label.
inline bool read_cad_part(const std::filesystem::path& path, Part_format format, Cad_part& part, std::string& error)
{
  namespace fsys = std::filesystem;
  if(format == Part_format::ABC_YML)
  {
    if(!read_mesh_in_file_order(path.string(), part.mesh, error)) return false;
    part.name = "abc_" + path.stem().string();
    try
    {
      part.labels = read_abc_ground_truth(fsys::path(path).replace_extension(".yml").string(),
                                          part.mesh.number_of_vertices(), part.mesh.number_of_faces())
                      .face_patch;
    }
    catch(const std::exception& e)
    {
      error = e.what();
      return false;
    }
  }
  else
  {
    fsys::path obj = path, stem = fsys::path(path).replace_extension(); // NAME.obj.gz -> NAME.obj
    if(format == Part_format::GZIPPED_OBJ_LABELS)
    {
      std::error_code ec;
      obj = fsys::temp_directory_path(ec) / ("fs_evaluation_" + std::to_string(::getpid()) + "_" +
                                             stem.filename().string());
      if(!gunzip_file(path, obj, error)) return false;
    }
    stem.replace_extension();
    part.name = stem.filename().string();
    fs_app::Input_correspondence<Mesh> correspondence;
    bool ok = true;
    try
    {
      const fs_app::Read_report report = fs_app::read_input_mesh(obj.string(), part.mesh, correspondence);
      for(const std::string& notice : report.notices)
        std::cerr << "evaluate_quality: " << part.name << ": " << notice << std::endl;
    }
    catch(const std::exception& e)
    {
      error = e.what();
      ok = false;
    }
    if(format == Part_format::GZIPPED_OBJ_LABELS)
    {
      std::error_code ec;
      fsys::remove(obj, ec);
    }
    if(!ok) return false;
    if(!read_labels_of_file_faces(fsys::path(stem).replace_extension(".labels"), correspondence,
                                  part.mesh.number_of_faces(), part.labels, error))
      return false;
  }
  const std::size_t faces = part.mesh.number_of_faces();
  if(part.labels.size() != faces || *std::min_element(part.labels.begin(), part.labels.end()) < 0)
  {
    error = "not one label >= 0 per face (" + std::to_string(part.labels.size()) + " labels, " +
            std::to_string(faces) + " faces)";
    return false;
  }
  return true;
}

/// The share of the true boundary length (edges between faces of different labels) whose
/// dihedral angle is below 20 degrees: tangent-continuous boundaries, which no crease
/// threshold finds.
inline double tangent_continuous_share(const Mesh& mesh, const std::vector<int>& labels)
{
  double low = 0, total = 0;
  for(auto e : edges(mesh))
  {
    if(is_border(e, mesh)) continue;
    const auto h = halfedge(e, mesh);
    const auto f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    if(labels[f.idx()] == labels[g.idx()]) continue;
    const double length = std::sqrt(CGAL::squared_distance(mesh.point(source(h, mesh)), mesh.point(target(h, mesh))));
    const double c = PMP::compute_face_normal(f, mesh) * PMP::compute_face_normal(g, mesh);
    total += length;
    if(std::acos((std::max)(-1., (std::min)(1., c))) * 180. / CGAL_PI < 20.) low += length;
  }
  return total > 0 ? low / total : 0.;
}

/// This package on `mesh` at the settings of `options` or, with `paper`, the paper's
/// pipeline (crease_angle 180: crest lines only, fitted on rings alone; the library's
/// alpha and strength threshold). Face patches only.
inline Segmentation run_package(const Mesh& mesh, const Cad_options& options, bool paper)
{
  const FS::internal::Segmentation_options library;
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  auto fp = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const auto t0 = std::chrono::steady_clock::now();
  FS::segment_along_features(mesh, vp,
                             FS::parameters::crease_angle(paper ? 180. : library.crease_angle)
                               .alpha(paper ? library.alpha : options.alpha)
                               .strength_threshold(paper ? FS::default_strength_threshold : options.strength_threshold)
                               .crease_filter_iterations(options.crease_filter)
                               .tangent_discontinuities(options.tangent)
                               .crest_lines_on_clean_tessellations(options.crest_lines)
                               .neighborhood_radius(paper ? 0. : FS::default_neighborhood_radius)
                               .face_patch_map(fp));
  Segmentation s;
  s.seconds = seconds_since(t0);
  s.method = paper ? "paper's pipeline" : "this package";
  s.setting = paper ? "crease angle 180, radius 0" : settings_text(options);
  s.face_patch.resize(mesh.number_of_faces());
  for(auto f : faces(mesh)) s.face_patch[f.idx()] = get(fp, f);
  return s;
}

/// A method's result on a part: its patch count and boundary scores against the labels.
struct Cad_score
{
  std::size_t patches = 0;
  std::size_t small_patches = 0; ///< patches under 0.1% of the area (small_patch_share)
  FS::Boundary_scores boundary;
  double seconds = 0;
  bool ran = true; ///< false: the method was not selected (Cad_options::methods)
};

/// The area share under which a patch counts as small in the tables (confetti).
constexpr double small_patch_share = 0.001;

/// The number of patches of `face_patch` whose area is below `share` of the whole area.
inline std::size_t number_of_small_patches(const Mesh& mesh, const std::vector<std::size_t>& face_patch,
                                           double share = small_patch_share)
{
  std::map<std::size_t, double> area;
  double total = 0;
  for(auto f : faces(mesh))
  {
    const double a = PMP::face_area(f, mesh);
    area[face_patch[f.idx()]] += a;
    total += a;
  }
  std::size_t n = 0;
  for(const auto& pa : area) n += pa.second < share * total ? 1 : 0;
  return n;
}

/// The columns of the CAD table, in the order of run_cad_methods(): (CSV name, header).
inline const std::vector<std::pair<std::string, std::string> >& cad_methods()
{
  static const std::vector<std::pair<std::string, std::string> > methods = {
    {"default", "this package (defaults)"}, {"paper", "paper's pipeline"}, {"sharp20", "sharp edges 20"},
    {"sharp45", "sharp edges 45"},          {"sharp60", "sharp edges 60"}, {"ransac", "Efficient RANSAC"},
    {"vsa", "VSA (true count)"}};
  return methods;
}

inline bool Cad_options::runs(std::size_t k) const { return methods.empty() || methods.count(cad_methods()[k].first) > 0; }

/// Runs the methods of cad_methods() that `options` selects on `mesh` (a part, maybe
/// noisy) and scores them against `labels` at 1% of `mesh`'s diagonal; the others get a
/// score of zero (Cad_score::ran false).
inline std::vector<Cad_score> run_cad_methods(const Mesh& mesh, const std::vector<int>& labels,
                                              std::size_t true_patches, const Cad_options& options)
{
  const std::function<Segmentation()> method[] = {
    [&] { return run_package(mesh, options, false); }, [&] { return run_package(mesh, options, true); },
    [&] { return run_sharp_edges(mesh, 20.); },        [&] { return run_sharp_edges(mesh, 45.); },
    [&] { return run_sharp_edges(mesh, 60.); },        [&] { return run_efficient_ransac(mesh); },
    [&] { return run_vsa(mesh, true_patches); }};
  auto truth =
    boost::make_function_property_map<face_descriptor>([&labels](face_descriptor f) { return labels[f.idx()]; });
  std::vector<Cad_score> scores;
  for(std::size_t k = 0; k < cad_methods().size(); ++k)
  {
    if(!options.runs(k))
    {
      scores.emplace_back();
      scores.back().ran = false;
      continue;
    }
    const Segmentation s = method[k]();
    auto patches = boost::make_function_property_map<face_descriptor>(
      [&s](face_descriptor f) { return s.face_patch[f.idx()]; });
    Cad_score r;
    r.patches = number_of_distinct(s.face_patch);
    r.small_patches = number_of_small_patches(mesh, s.face_patch);
    r.boundary = FS::compare_boundaries(mesh, patches, truth, FS::default_boundary_tolerance(mesh));
    r.seconds = s.seconds;
    scores.push_back(r);
  }
  return scores;
}

/// The results on one part.
struct Cad_result
{
  std::string name;
  std::string set; ///< part_set(): "cad" and "abc-dev" make the development set, "abc" follows it
  std::size_t faces = 0, true_patches = 0;
  double tangent_share = 0;
  std::vector<std::vector<Cad_score> > scores; ///< [noise level][method]
  std::filesystem::path path;                   ///< the part's file, read again for its scene
  Part_format format = Part_format::OBJ_LABELS;
};

/// Reads a part (read_cad_part()) and runs the methods at every noise level.
inline bool evaluate_cad_part(const std::filesystem::path& path, Part_format format, const Cad_options& options,
                              Cad_result& result, std::string& error)
{
  Cad_part part;
  if(!read_cad_part(path, format, part, error)) return false;
  result.name = part.name;
  result.path = path;
  result.format = format;
  result.set = part_set(format);
  result.faces = part.mesh.number_of_faces();
  result.true_patches = number_of_distinct(part.labels);
  result.tangent_share = tangent_continuous_share(part.mesh, part.labels);
  std::cerr << "evaluate_quality: CAD part " << part.name << " (" << result.faces << " faces)" << std::endl;
  for(double sigma : options.noise)
  {
    // seed 1 at every level, as the CAD numbers of the manual were measured
    const Mesh mesh = sigma > 0 ? add_normal_noise(part.mesh, sigma, 1) : part.mesh;
    result.scores.push_back(run_cad_methods(mesh, part.labels, result.true_patches, options));
  }
  return true;
}

/// Writes `text` to `path` and prints it.
inline void write_and_print(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream file(path);
  file << text;
  std::cout << "\n" << text << std::flush;
  if(file) std::cout << "evaluate_quality: wrote " << path.string() << " and its .csv" << std::endl;
  else std::cerr << "evaluate_quality: cannot write " << path.string() << std::endl;
}

/// The groups whose means the tables give: (name, sets in it).
inline const std::vector<std::pair<std::string, std::vector<std::string> > >& cad_groups()
{
  static const std::vector<std::pair<std::string, std::vector<std::string> > > groups = {
    {"development (cad + abc-dev)", {"cad", "abc-dev"}}, {"cad", {"cad"}}, {"abc-dev", {"abc-dev"}},
    {"generated", {"generated"}}};
  return groups;
}

/// The mean boundary F of each method at noise level `l` over the parts of `sets`, and
/// the number of those parts.
inline std::pair<std::vector<double>, std::size_t> mean_f(const std::vector<Cad_result>& results,
                                                          const std::vector<std::string>& sets, std::size_t l)
{
  std::vector<double> mean(cad_methods().size(), 0.);
  std::size_t parts = 0;
  for(const Cad_result& r : results)
    if(std::find(sets.begin(), sets.end(), r.set) != sets.end())
    {
      ++parts;
      for(std::size_t k = 0; k < mean.size(); ++k) mean[k] += r.scores[l][k].boundary.f_score;
    }
  for(double& x : mean) x = parts > 0 ? x / double(parts) : 0.;
  return {mean, parts};
}

/// Writes OUT/cad_parts.md and OUT/cad_parts.csv, and prints the markdown.
inline void write_cad_tables(const std::string& out, const Cad_options& options, const std::vector<Cad_result>& results,
                             const std::string& machine)
{
  const auto& methods = cad_methods();
  const std::size_t levels = options.noise.size();

  Text_table csv;
  csv.header = {"set", "part", "faces", "true_patches", "tangent_share", "noise", "method",
                "patches", "small_patches", "precision", "recall", "f", "seconds"};
  for(const Cad_result& r : results)
    for(std::size_t l = 0; l < levels; ++l)
      for(std::size_t k = 0; k < methods.size(); ++k)
      {
        if(!options.runs(k)) continue;
        const Cad_score& s = r.scores[l][k];
        csv.rows.push_back({r.set, r.name, std::to_string(r.faces), std::to_string(r.true_patches),
                            fmt(r.tangent_share, 6), plain(options.noise[l]), methods[k].first,
                            std::to_string(s.patches), std::to_string(s.small_patches), fmt(s.boundary.precision, 6),
                            fmt(s.boundary.recall, 6), fmt(s.boundary.f_score, 6), fmt(s.seconds, 3)});
      }
  for(const auto& group : cad_groups())
    for(std::size_t l = 0; l < levels; ++l)
    {
      const auto m = mean_f(results, group.second, l);
      if(m.second == 0) continue;
      for(std::size_t k = 0; k < methods.size(); ++k)
        if(options.runs(k))
          csv.rows.push_back({"mean " + group.first, "", "", "", "", plain(options.noise[l]), methods[k].first, "", "",
                            "", "", fmt(m.first[k], 6), ""});
    }
  std::ofstream csv_file(std::filesystem::path(out) / "cad_parts.csv");
  csv.write_csv(csv_file);

  std::ostringstream md;
  md << "# CAD parts\n\nMachine: " << machine << ". Produced by `evaluate_quality` (evaluation/cad_parts.h). "
     << "Boundary F-score at 1% of the bounding-box diagonal against the true patches (the B-rep faces; the ABC "
        "surfaces), on the face patches, the patch count in parentheses and, after a slash, the number of patches "
        "under 0.1% of the area. Sets: \"cad\", Fusion 360 parts meshed by gmsh; \"abc-dev\", native ABC meshes "
        "(read by the program's reader, which separates the faces of non-manifold edges); \"abc\", the ABC models "
        "with a YAML ground truth, outside the means. \"this package (defaults)\": segment_along_features() with "
     << settings_text(options)
     << "; \"paper's pipeline\": crease_angle 180 (crest lines only), neighborhood_radius 0, alpha 0.6; \"sharp "
        "edges N\": CGAL's sharp_edges_segmentation at N degrees; \"Efficient RANSAC\": CGAL's shape detection "
        "(planes, cylinders, cones, spheres, tori) on the face centroids and normals, a patch per connected set of "
        "faces of one shape (evaluation/ransac.h); \"VSA (true count)\": CGAL's variational shape "
        "approximation with the true patch count (L21, hierarchical seeding, seeded). \"tang.\": the share of the "
        "true boundary length whose dihedral angle is below 20 degrees (tangent-continuous), on the clean mesh. "
        "Noise: every vertex moved along its normal by a normal deviate of the given standard deviation (seed 1).\n";
  for(const auto& group : cad_groups())
  {
    if(mean_f(results, group.second, 0).second == 0) continue;
    md << "\n## Mean boundary F: " << group.first << ", " << mean_f(results, group.second, 0).second
       << " parts\n\n";
    Text_table means;
    means.header = {"noise (of the diagonal)"};
    for(std::size_t k = 0; k < methods.size(); ++k)
      if(options.runs(k)) means.header.push_back(methods[k].second);
    for(std::size_t l = 0; l < levels; ++l)
    {
      means.rows.push_back({plain(100 * options.noise[l]) + "%"});
      const std::vector<double> f = mean_f(results, group.second, l).first;
      for(std::size_t k = 0; k < methods.size(); ++k)
        if(options.runs(k)) means.rows.back().push_back(fmt(f[k]));
    }
    means.write_markdown(md);
  }
  for(std::size_t l = 0; l < levels; ++l)
  {
    md << "\n## Noise " << plain(100 * options.noise[l]) << "% of the diagonal\n\n";
    Text_table t;
    t.header = {"set", "part", "faces", "true patches", "tang."};
    for(std::size_t k = 0; k < methods.size(); ++k)
      if(options.runs(k)) t.header.push_back(methods[k].second);
    for(const Cad_result& r : results)
    {
      t.rows.push_back({r.set, r.name, std::to_string(r.faces), std::to_string(r.true_patches), fmt(r.tangent_share)});
      for(const Cad_score& s : r.scores[l])
        if(s.ran)
          t.rows.back().push_back(fmt(s.boundary.f_score) + " (" + std::to_string(s.patches) + "/" +
                                  std::to_string(s.small_patches) + ")");
    }
    for(const auto& group : cad_groups())
    {
      const auto m = mean_f(results, group.second, l);
      if(m.second == 0) continue;
      t.rows.push_back({"", "mean " + group.first + " (" + std::to_string(m.second) + ")", "", "", ""});
      for(std::size_t k = 0; k < methods.size(); ++k)
        if(options.runs(k)) t.rows.back().push_back("**" + fmt(m.first[k]) + "**");
    }
    t.write_markdown(md);
  }
  write_and_print(std::filesystem::path(out) / "cad_parts.md", md.str());
}

/// Writes OUT/scenes/worst_K_NAME.scene (render_scenes' input; scripts/run_evaluation.sh
/// lays them out in OUT/contact_sheets/cad_worst_five.png) for the `count` parts of the
/// development and generated sets whose boundary F at the defaults, clean, is lowest:
/// their ground truth, this package at `options`, sharp edges at 20 degrees and Efficient
/// RANSAC, each method's patches coloured like the true patches they overlap most.
inline void write_worst_part_scenes(const std::string& out, const Cad_options& options,
                                    const std::vector<Cad_result>& results, std::size_t count = 5)
{
  const auto clean = std::find(options.noise.begin(), options.noise.end(), 0.);
  if(clean == options.noise.end()) return; // no clean run to rank the parts by
  if(!options.runs(0)) return;             // nor the package's scores
  const std::size_t l = std::size_t(clean - options.noise.begin());
  std::vector<const Cad_result*> parts;
  for(const Cad_result& r : results)
    if(r.set == "cad" || r.set == "abc-dev" || r.set == "generated") parts.push_back(&r);
  std::stable_sort(parts.begin(), parts.end(), [l](const Cad_result* a, const Cad_result* b) {
    return a->scores[l][0].boundary.f_score < b->scores[l][0].boundary.f_score;
  });
  if(parts.size() > count) parts.resize(count);
  const std::filesystem::path folder = std::filesystem::path(out) / "scenes";
  std::filesystem::create_directories(folder);
  for(std::size_t k = 0; k < parts.size(); ++k)
  {
    Cad_part part;
    std::string error;
    if(!read_cad_part(parts[k]->path, parts[k]->format, part, error))
    {
      std::cerr << "evaluate_quality: " << parts[k]->path.string() << ": " << error << std::endl;
      continue;
    }
    const std::vector<std::size_t> truth(part.labels.begin(), part.labels.end());
    std::vector<double> area(part.mesh.number_of_faces());
    for(auto f : faces(part.mesh)) area[f.idx()] = PMP::face_area(f, part.mesh);
    Scene_writer scene((folder / ("worst_" + std::to_string(k + 1) + "_" + part.name + ".scene")).string(),
                       part.mesh);
    const auto label = [](const std::string& method, const Segmentation& s, const Cad_score* score) {
      std::ostringstream text;
      text << method << ": " << number_of_distinct(s.face_patch) << " patches";
      if(score) text << ", F " << std::fixed << std::setprecision(3) << score->boundary.f_score;
      return text.str();
    };
    scene.tile_with_patches("ground truth: " + std::to_string(parts[k]->true_patches) + " patches", truth);
    const Cad_score* scores = parts[k]->scores[l].data(); // cad_methods(): 0 default, 2 sharp20, 5 ransac
    const std::pair<std::size_t, Segmentation> runs[] = {{0, run_package(part.mesh, options, false)},
                                                         {2, run_sharp_edges(part.mesh, 20.)},
                                                         {5, run_efficient_ransac(part.mesh)}};
    for(const auto& run : runs)
      scene.tile_with_patches(label(cad_methods()[run.first].second, run.second,
                                    scores[run.first].ran ? &scores[run.first] : nullptr),
                              match_to_reference(run.second.face_patch, truth, area));
    if(!scene.good()) std::cerr << "evaluate_quality: cannot write the scene of " << part.name << std::endl;
  }
}

/// The CAD table: evaluates the parts of DATA/cad (NAME.obj), DATA/abc-dev (NAME.obj.gz),
/// DATA/abc (NAME.obj with NAME.yml) and `generated` (NAME.obj, the gmsh parts made by
/// the build), each with its ground truth, at every noise level of `options`;
/// `only_parts`, if not empty, keeps the parts named in it. Writes OUT/cad_parts.md and
/// OUT/cad_parts.csv and prints the markdown. Without any of these folders, says so on
/// the standard output and returns false (nothing written).
inline bool run_cad_table(const std::string& data, const std::string& out, const Cad_options& options,
                          const std::string& machine, const std::set<std::string>& only_parts = {},
                          const std::string& generated = {})
{
  namespace fsys = std::filesystem;
  std::error_code ec;
  const fsys::path cad = fsys::path(data) / "cad", abc_dev = fsys::path(data) / "abc-dev";
  const bool has_data = !data.empty() && (fsys::is_directory(cad, ec) || fsys::is_directory(abc_dev, ec));
  if(!has_data)
    std::cout << "evaluate_quality: no development parts ("
              << (data.empty() ? "no data folder: set FEATURE_SEGMENTATION_DATA or --data"
                               : cad.string() + " and " + abc_dev.string() + " absent")
              << ")" << std::endl;
  const bool has_generated = !generated.empty() && fsys::is_directory(generated, ec);
  if(!has_generated)
    std::cout << "evaluate_quality: no generated parts ("
              << (generated.empty() ? "no folder given: --generated DIR" : generated + " absent: build the target generated_parts")
              << ")" << std::endl;
  if(!has_data && !has_generated)
  {
    std::cout << "evaluate_quality: CAD table skipped" << std::endl;
    return false;
  }
  const auto files = [&ec](const fsys::path& folder, const std::string& ending) {
    std::vector<fsys::path> result;
    if(fsys::is_directory(folder, ec))
      for(const auto& e : fsys::directory_iterator(folder, ec))
      {
        const std::string name = e.path().filename().string();
        if(name.size() > ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0)
          result.push_back(e.path());
      }
    std::sort(result.begin(), result.end());
    return result;
  };
  std::vector<std::pair<fsys::path, Part_format> > inputs;
  for(const fsys::path& p : files(cad, ".obj")) inputs.emplace_back(p, Part_format::OBJ_LABELS);
  for(const fsys::path& p : files(abc_dev, ".obj.gz")) inputs.emplace_back(p, Part_format::GZIPPED_OBJ_LABELS);
  if(has_data)
    for(const fsys::path& p : ground_truth_models(fsys::path(data) / "abc")) inputs.emplace_back(p, Part_format::ABC_YML);
  if(has_generated)
    for(const fsys::path& p : files(generated, ".obj")) inputs.emplace_back(p, Part_format::GENERATED_OBJ_LABELS);
  std::vector<Cad_result> results;
  for(const auto& input : inputs)
  {
    std::string stem = input.first.filename().string();
    stem = stem.substr(0, stem.find('.'));
    if(input.second == Part_format::ABC_YML) stem = "abc_" + stem;
    if(!only_parts.empty() && only_parts.count(stem) == 0) continue;
    Cad_result r;
    std::string error;
    bool ok = false;
    try
    {
      ok = evaluate_cad_part(input.first, input.second, options, r, error);
    }
    catch(const std::exception& e)
    {
      error = e.what();
    }
    if(ok) results.push_back(r);
    else std::cout << "evaluate_quality: " << input.first.string() << " skipped: " << error << std::endl;
  }
  write_cad_tables(out, options, results, machine);
  write_worst_part_scenes(out, options, results);
  return true;
}

typedef FS::internal::Evaluation_segment Boundary_segment;

/// The patch boundary of a face labelling of `mesh` as 3D segments: the edges between two
/// faces of different patches (border edges are not boundaries).
inline std::vector<Boundary_segment> boundary_segments(const Mesh& mesh, const std::vector<std::size_t>& face_patch)
{
  auto patches = boost::make_function_property_map<face_descriptor>(
    [&face_patch](face_descriptor f) { return face_patch[f.idx()]; });
  return FS::internal::patch_boundary_segments(mesh, patches, get(CGAL::vertex_point, mesh));
}

/// Boundary precision, recall and F-score of the segments `boundary` against the segments
/// `reference`, which may lie on different meshes of one surface (one part at two
/// resolutions), where compare_boundaries() of metrics.h compares two labellings of one
/// mesh edge by edge. Both boundaries are first cut into pieces no longer than half the
/// tolerance, so that the points sampled, the pieces' midpoints (each weighing its
/// piece's length), are as dense along a coarse edge as along a fine one. A piece is
/// matched when its midpoint lies within `tolerance` of the other boundary; precision is
/// the matched share of `boundary`'s length, recall that of `reference`'s.
inline FS::Boundary_scores compare_boundaries_across_meshes(const std::vector<Boundary_segment>& boundary,
                                                            const std::vector<Boundary_segment>& reference,
                                                            double tolerance)
{
  const auto pieces = [tolerance](const std::vector<Boundary_segment>& segments) {
    std::vector<Boundary_segment> result;
    for(const Boundary_segment& s : segments)
    {
      const double length = std::sqrt(s.squared_length());
      const std::size_t n =
        tolerance > 0 ? (std::max)(std::size_t(1), std::size_t(std::ceil(length / (0.5 * tolerance)))) : 1;
      const auto step = (s.target() - s.source()) / double(n);
      for(std::size_t i = 0; i < n; ++i)
        result.emplace_back(s.source() + double(i) * step, s.source() + double(i + 1) * step);
    }
    return result;
  };
  return FS::internal::compare_boundary_segments(pieces(boundary), pieces(reference), tolerance);
}

/// Subdivides `mesh` flat once: every triangle into four by its edge midpoints (CGAL's PTQ
/// with the linear mask), the geometry unchanged.
inline void subdivide_flat(Mesh& mesh)
{
  CGAL::Subdivision_method_3::PTQ(mesh, CGAL::Linear_mask_3<Mesh>(&mesh, get(CGAL::vertex_point, mesh)),
                                  CGAL::parameters::number_of_iterations(1));
}

/// Fandisk's resolution series: the mesh of `fandisk` and its `levels` flat subdivisions,
/// each segmented by run_package() at `options`, scored against the coarse result; writes
/// OUT/resolution.md and OUT/resolution.csv and prints the markdown. Returns false,
/// having said why, when the mesh cannot be read.
inline bool run_resolution_series(const std::string& fandisk, const std::string& out, const Cad_options& options,
                                  const std::string& machine, int levels = 3)
{
  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(fandisk, mesh) || is_empty(mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cout << "evaluate_quality: " << fandisk << " is not a readable triangle mesh: resolution series skipped"
              << std::endl;
    return false;
  }
  const double tolerance = FS::default_boundary_tolerance(mesh); // the geometry, hence the diagonal, stays
  std::vector<Boundary_segment> coarse;
  Text_table md, csv;
  md.header = {"subdivisions", "faces", "patches", "boundary P", "boundary R", "boundary F", "seconds"};
  csv.header = {"subdivisions", "faces", "patches", "precision", "recall", "f", "seconds"};
  for(int level = 0; level <= levels; ++level)
  {
    if(level > 0) subdivide_flat(mesh);
    std::cerr << "evaluate_quality: fandisk subdivided " << level << " times (" << mesh.number_of_faces() << " faces)"
              << std::endl;
    const Segmentation s = run_package(mesh, options, false);
    const std::vector<Boundary_segment> boundary = boundary_segments(mesh, s.face_patch);
    if(level == 0) coarse = boundary;
    const FS::Boundary_scores b = compare_boundaries_across_meshes(boundary, coarse, tolerance);
    const std::string faces = std::to_string(mesh.number_of_faces());
    const std::string patches = std::to_string(number_of_distinct(s.face_patch));
    md.rows.push_back({std::to_string(level) + (level == 0 ? " (reference)" : ""), faces, patches, fmt(b.precision),
                       fmt(b.recall), "**" + fmt(b.f_score) + "**", fmt(s.seconds, 2)});
    csv.rows.push_back({std::to_string(level), faces, patches, fmt(b.precision, 6), fmt(b.recall, 6),
                        fmt(b.f_score, 6), fmt(s.seconds, 3)});
  }
  std::ofstream csv_file(std::filesystem::path(out) / "resolution.csv");
  csv.write_csv(csv_file);
  std::ostringstream text;
  text << "# Resolution series (fandisk)\n\nMachine: " << machine << ". Produced by `evaluate_quality` "
       << "(evaluation/cad_parts.h): " << fandisk << " and its flat subdivisions (each triangle into four by its "
       << "edge midpoints, CGAL's PTQ with Linear_mask_3: the geometry unchanged), segmented by this package with "
       << settings_text(options) << ". Boundary precision, recall and F-score of each result against the boundary "
       << "of the coarse result, tolerance 1% of the diagonal, the two boundaries compared as 3D segments cut in "
       << "pieces of at most half the tolerance (compare_boundaries_across_meshes()).\n\n";
  md.write_markdown(text);
  write_and_print(std::filesystem::path(out) / "resolution.md", text.str());
  return true;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PARTS_H
