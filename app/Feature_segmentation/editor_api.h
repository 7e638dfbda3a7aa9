// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON interface of the interactive editor (`feature_segmentation edit`), apart from
// HTTP: an Editor_session holds one mesh through the Pipeline, turns each JSON edit into
// the edit script's Script_edit and applies it with the script's Edit_runner (so an
// edit means the same in a script and in the editor), keeps the session's history as a
// script, and answers the page's queries as JSON. Thread-safe: every call takes the
// session's lock, so edits run one at a time and a query never sees half an edit.
//
// Requests and answers (all JSON; face indices are triangles of the mesh as GET
// /api/mesh gives it, which is the order of segmentation.ply):
//   state      {"patches", "alpha", "cut_cost", "edit_count", "edits_from", "edits": [the
//               script lines of the last 50 edits, from edit edits_from], "can_undo",
//               "can_redo", "last_edit": {"op", "seconds", "server_seconds"} or null,
//               "vertices", "triangles", "feature_edges", "crease_edges"}
//   mesh       {"vertices": [x y z ...], "triangles": [i j k ...], "diagonal"}
//   labels     {"patches", "face_patches": [...], "vertex_patches": [...]}
//   mesh and labels with ?format=binary (what the page loads: a million faces in a few
//   megabytes, read as typed arrays without parsing), little-endian:
//     mesh     uint32 vertices V, uint32 triangles T, float64 diagonal, float32 x y z per
//              vertex, uint32 i j k per triangle (16 + 12 V + 12 T bytes)
//     labels   uint32 patches, uint32 T, uint32 V, uint32 B, then the patch of every
//              triangle and of every vertex as unsigned integers of B bytes, the fewest
//              of 1, 2 or 4 that hold the largest patch id (16 + B (T + V) bytes: a
//              million faces of a part of under 256 patches in 1 MB); with &vertices=0,
//              V is 0 and the triangles' patches end it (what the page loads)
//   labels?format=runs (what the page loads: a few hundred kilobytes for a million
//              faces stored patch by patch), little-endian: uint32 patches, uint32 T,
//              uint32 R, uint32 B, then R uint32: the end (exclusive) of each run of
//              consecutive triangles in one patch, then the R runs' patches as
//              unsigned integers of B bytes (1, 2 or 4, as above): 16 + (4 + B) R bytes
//   history    ?from=K&count=N (N in 1 .. 1000): {"edit_count", "from", "edits": [lines]}
//   features   {"ridges", "valleys", "seam_lines", "user": [[x y z ...] per line],
//               "creases": [x y z x y z per crease edge ...]}
//   boundaries {"curves": [[x y z ...] per curve, closed ones repeat their first point],
//               "smoothed", "length"}
//   restart    {"radius": X, "strength_threshold": T}: the crest-line scale, recomputed;
//               the history starts again
//   edit       {"op": "alpha", "value": A} | {"op": "refine" or "coarsen", "faces": [...],
//               "amount": D} | {"op": "scale", "faces": [...], "factor": F} |
//               {"op": "merge", "faces": [...]} | {"op": "sketch", "points": [[x, y, z],
//               ...], "alpha": A (optional, > 1)} | {"op": "undo"} | {"op": "redo"};
//               answered with the new state; with ?labels=binary or ?labels=runs (what
//               the page sends), with the state and the triangles' patches in one
//               message: uint32 J, the state's JSON in J bytes (J a multiple of 4, the
//               JSON padded with spaces), then the labels as ?format=binary&vertices=0
//               or ?format=runs gives them
// A request the editor cannot take (bad JSON, an unknown op or key, a missing or
// non-finite number, a face index out of range, nothing to undo) throws Request_error
// and changes nothing.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_EDITOR_API_H
#define CGAL_FEATURE_SEGMENTATION_APP_EDITOR_API_H

#include "edit_script.h"
#include "editor_requests.h"
#include "pipeline.h"
#include "option_table.h"

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>
#include <cmath>
#include <filesystem>
#include <algorithm>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs_app {

/// One mesh in the editor: segmented at construction, then edited request by request.
class Editor_session
{
public:
  /// Reads and segments `options.input` (and applies `options.edits_file`, if given).
  explicit Editor_session(const Options& options) : m_run(std::make_unique<Run>(options))
  {
    Edit_script script;
    if(!options.edits_file.empty())
      script = read_edit_script(options.edits_file);
    Pipeline& p = m_run->pipeline;
    p.load();
    check_face_indices(script, m_run->results.read_report.number_of_file_faces, num_faces(p.mesh));
    p.segment();
    m_triangles.assign(faces(p.mesh).begin(), faces(p.mesh).end());
    for(const Script_edit& e : script.edits)
      record(p.edit_runner().apply(script, e), e);
  }

  std::size_t number_of_triangles() const { return m_triangles.size(); }

  /// Edits [from, from + count) of the history as edit-script lines, count at most
  /// editor_max_history_page: {"edit_count", "from", "edits"}.
  /// \throws Request_error for a count of 0 or over the page size
  nlohmann::json history(std::size_t from, std::size_t count) const
  {
    if(count == 0 || count > internal::editor_max_history_page)
      throw Request_error("history: 'count' must be in 1 .. " + std::to_string(internal::editor_max_history_page));
    std::lock_guard<std::mutex> lock(m_mutex);
    return {{"edit_count", m_history.size()}, {"from", std::min(from, m_history.size())},
            {"edits", history_lines(from, count)}};
  }

  nlohmann::json state() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return state_unlocked();
  }

  /// Applies one edit and answers with the new state.
  /// \throws Request_error if the edit is refused (nothing changes)
  nlohmann::json edit(const nlohmann::json& request)
  {
    const auto start = std::chrono::steady_clock::now();
    std::lock_guard<std::mutex> lock(m_mutex);
    edit_unlocked(request, start);
    return state_unlocked();
  }

  /// POST /api/edit?labels=binary: applies one edit and answers with the new state and
  /// the triangles' patches in one message (the layout is at the top of this file).
  /// \throws Request_error if the edit is refused (nothing changes)
  std::string edit_with_labels(const nlohmann::json& request, bool runs = false)
  {
    const auto start = std::chrono::steady_clock::now();
    std::lock_guard<std::mutex> lock(m_mutex);
    edit_unlocked(request, start);
    std::string state = state_unlocked().dump();
    state.resize((state.size() + 3) / 4 * 4, ' '); // the labels' words start 4-byte aligned
    const std::string labels = runs ? labels_runs_unlocked() : labels_binary_unlocked(false);
    internal::Little_endian_bytes out(4 + state.size() + labels.size());
    out.u32(state.size());
    out.append(state);
    out.append(labels);
    return out.take();
  }

private:
  void edit_unlocked(const nlohmann::json& request, std::chrono::steady_clock::time_point start)
  {
    Script_edit e = script_edit_from_json(request, m_triangles.size(), m_history.size() + 1);
    Edit_record r;
    try
    {
      r = m_run->pipeline.edit_runner().apply(e);
    }
    catch(const Edit_refused& refused)
    {
      throw Request_error(refused.what());
    }
    record(r, e);
    m_last_server_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

public:

  std::string mesh() const
  {
    std::vector<double> xyz;
    std::vector<std::size_t> tri;
    const double diagonal = mesh_arrays(xyz, tri);
    return nlohmann::json{{"vertices", xyz}, {"triangles", tri}, {"diagonal", diagonal}}.dump();
  }

  /// GET /api/mesh?format=binary (the layout is at the top of this file).
  std::string mesh_binary() const
  {
    std::vector<double> xyz;
    std::vector<std::size_t> tri;
    const double diagonal = mesh_arrays(xyz, tri);
    internal::Little_endian_bytes out(16 + 4 * (xyz.size() + tri.size()));
    out.u32(xyz.size() / 3);
    out.u32(tri.size() / 3);
    out.f64(diagonal);
    for(double x : xyz) out.f32(float(x));
    for(std::size_t i : tri) out.u32(i);
    return out.take();
  }

  std::string labels() const
  {
    std::vector<std::size_t> faces, vertices;
    const std::size_t patches = label_arrays(faces, vertices);
    return nlohmann::json{{"patches", patches}, {"face_patches", faces}, {"vertex_patches", vertices}}.dump();
  }

  /// GET /api/labels?format=binary (the layout is at the top of this file); with
  /// `vertices` false (?vertices=0, what the page loads), V is 0 and no vertex follows.
  /// The faces' patches are computed by the threads of the run, each face on its own
  /// (`face_patches()`), so the bytes are the same at any thread count.
  std::string labels_binary(bool vertices = true) const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return labels_binary_unlocked(vertices);
  }

  /// GET /api/labels?format=runs (the layout is at the top of this file).
  std::string labels_runs() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return labels_runs_unlocked();
  }

private:
  std::string labels_runs_unlocked() const
  {
    const std::vector<std::uint32_t> ids = face_patch_ids();
    std::vector<std::uint32_t> end, patch;
    std::uint32_t largest = 0;
    for(std::size_t i = 0; i < ids.size(); ++i)
    {
      if(i + 1 == ids.size() || ids[i + 1] != ids[i])
      {
        end.push_back(std::uint32_t(i + 1));
        patch.push_back(ids[i]);
        largest = (std::max)(largest, ids[i]);
      }
    }
    const unsigned width = internal::Little_endian_bytes::id_width(largest);
    internal::Little_endian_bytes out(16 + (4 + width) * end.size());
    out.u32(m_run->pipeline.segmentation->number_of_patches());
    out.u32(ids.size());
    out.u32(end.size());
    out.u32(width);
    for(std::uint32_t e : end) out.u32(e);
    char* const block = out.id_block(patch.size(), width);
    for(std::size_t r = 0; r < patch.size(); ++r) internal::Little_endian_bytes::write_id(block + width * r, patch[r], width);
    return out.take();
  }

  std::string labels_binary_unlocked(bool vertices) const
  {
    const Mesh& m = m_run->pipeline.mesh;
    const auto& seg = *m_run->pipeline.segmentation;
    const std::size_t nt = m_triangles.size(), nv = vertices ? std::size_t(m.number_of_vertices()) : 0;
    std::vector<std::uint32_t> ids = face_patch_ids();
    ids.resize(nt + nv);
    if(vertices)
    {
      std::size_t i = nt;
      for(Mesh::Vertex_index v : m.vertices()) ids[i++] = std::uint32_t(seg.patch(v));
    }
    const std::uint32_t largest = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end());
    const unsigned width = internal::Little_endian_bytes::id_width(largest);
    internal::Little_endian_bytes out(16 + width * ids.size());
    out.u32(seg.number_of_patches());
    out.u32(nt);
    out.u32(nv);
    out.u32(width);
    char* const block = out.id_block(ids.size(), width);
    FS::internal::for_each_range(ids.size(), true, 65536, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i) internal::Little_endian_bytes::write_id(block + width * i, ids[i], width);
    });
    return out.take();
  }

  // The vertices' coordinates and the triangles' corners as the page draws them; returns
  // the bounding box's diagonal.
  double mesh_arrays(std::vector<double>& xyz, std::vector<std::size_t>& tri) const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const Mesh& m = m_run->pipeline.mesh;
    xyz.reserve(3 * num_vertices(m));
    std::vector<std::size_t> index(m.number_of_vertices() + m.number_of_removed_vertices(), 0);
    std::size_t n = 0;
    for(Mesh::Vertex_index v : m.vertices())
    {
      index[v] = n++;
      const K::Point_3& p = m.point(v);
      xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    }
    tri.reserve(3 * m_triangles.size());
    for(Mesh::Face_index f : m_triangles)
      for(Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m))
        tri.push_back(index[v]);
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(m);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    return diagonal;
  }

  // The patch of every triangle, in the order of m_triangles (the segmentation's
  // face_patches(), on the run's threads); the caller holds the lock.
  std::vector<std::uint32_t> face_patch_ids() const
  {
    const Mesh& m = m_run->pipeline.mesh;
    std::vector<std::uint32_t> by_index(m.number_of_faces() + m.number_of_removed_faces());
    m_run->pipeline.segmentation->face_patches(boost::make_iterator_property_map(by_index.begin(), get(CGAL::face_index, m)));
    std::vector<std::uint32_t> ids(m_triangles.size());
    for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = by_index[m_triangles[i]];
    return ids;
  }

  // The patch of every triangle and vertex; returns the number of patches.
  std::size_t label_arrays(std::vector<std::size_t>& faces, std::vector<std::size_t>& vertices) const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const Mesh& m = m_run->pipeline.mesh;
    const auto& seg = *m_run->pipeline.segmentation;
    const std::vector<std::uint32_t> ids = face_patch_ids();
    faces.assign(ids.begin(), ids.end());
    vertices.reserve(m.number_of_vertices());
    for(Mesh::Vertex_index v : m.vertices()) vertices.push_back(seg.patch(v));
    return seg.number_of_patches();
  }

public:

  std::string features() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const Pipeline& p = m_run->pipeline;
    nlohmann::json ridges = nlohmann::json::array(), valleys = nlohmann::json::array(),
                   seams = nlohmann::json::array(), user = nlohmann::json::array();
    for(const auto& line : p.segmentation->feature_lines().lines)
      (line.type == FS::Feature_line_type::RIDGE    ? ridges
       : line.type == FS::Feature_line_type::VALLEY ? valleys
       : line.type == FS::Feature_line_type::SEAM   ? seams
                                                    : user).push_back(p.line_coordinates(line));
    return nlohmann::json{{"ridges", ridges}, {"valleys", valleys}, {"seam_lines", seams}, {"user", user},
                          {"creases", p.crease_segments()}}
      .dump();
  }

  /// The patch boundaries, smoothed as the outputs are (`smooth`) or not.
  std::string boundaries(bool smooth) const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const FS::Patch_boundaries<Mesh> b = m_run->pipeline.boundaries(smooth);
    nlohmann::json curves = nlohmann::json::array();
    for(const auto& c : b.curves()) curves.push_back(Pipeline::curve_coordinates(c));
    return nlohmann::json{{"curves", curves}, {"smoothed", smooth}, {"length", b.length()}}.dump();
  }

  /// Starts again at another crest-line scale (the authors' Q/W/E keys):
  /// {"radius": X, "strength_threshold": T}, either or both, as the options --radius
  /// (0 <= X <= 1) and --strength-threshold (T >= 0). The curvature, the feature lines
  /// and the oversegmentation are computed anew, which no edit does: the history starts
  /// again (edits.txt then names these options for its replay).
  /// \throws Request_error if the request is not valid (nothing changes)
  nlohmann::json restart(const nlohmann::json& request)
  {
    if(!request.is_object() || request.empty())
      throw Request_error("restart: give \"radius\" and/or \"strength_threshold\"");
    internal::json_keys(request, "restart", {"radius", "strength_threshold"});
    std::lock_guard<std::mutex> lock(m_mutex);
    Options options = m_run->options;
    options.edits_file.clear();
    if(request.contains("radius"))
    {
      options.radius = internal::json_finite(request, "radius", "restart");
      if(!(options.radius >= 0 && options.radius <= 1))
        throw Request_error("restart: 'radius' must be in [0, 1]");
    }
    if(request.contains("strength_threshold"))
    {
      options.strength_threshold = internal::json_finite(request, "strength_threshold", "restart");
      if(!(*options.strength_threshold >= 0))
        throw Request_error("restart: 'strength_threshold' must be >= 0");
    }
    auto run = std::make_unique<Run>(options);
    run->pipeline.load();
    run->pipeline.segment();
    m_run = std::move(run);
    m_history.clear();
    m_last.reset();
    return state_unlocked();
  }

  /// Writes the outputs of the program and edits.txt into `--output-dir`.
  nlohmann::json save()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const Options& options = m_run->options;
    const std::filesystem::path dir(options.output_dir);
    m_run->pipeline.write_edits_file(m_history, "feature_segmentation edit on " + options.input);
    m_run->pipeline.write_outputs();
    nlohmann::json files = nlohmann::json::array();
    for(const char* f : {"segmentation.ply", "segmentation_refined.ply", "face_patches.txt", "vertex_patches.txt",
                         "boundaries.polylines.txt", "feature_lines.polylines.txt", "feature_lines.obj",
                         "summary.json", "edits.txt"})
      files.push_back(f);
    return nlohmann::json{{"output_dir", std::filesystem::absolute(dir).string()}, {"files", files},
                          {"edits", m_history.size()}};
  }

private:
  // The edit (of line e.line) went through: it joins the history that edits.txt replays.
  void record(const Edit_record& r, Script_edit e)
  {
    e.line = m_history.size() + 1;
    m_history.push_back(e);
    m_run->results.edits.push_back(r);
    m_run->results.edits.back().line = e.line;
    m_last = r;
    m_last_server_seconds = r.seconds + r.prepare_seconds;
  }

  // The edit script's lines of the edits [from, from + count) of the history.
  std::vector<std::string> history_lines(std::size_t from, std::size_t count) const
  {
    from = std::min(from, m_history.size());
    const std::size_t to = from + std::min(count, m_history.size() - from);
    return edit_script_lines(std::vector<Script_edit>(m_history.begin() + std::ptrdiff_t(from),
                                                      m_history.begin() + std::ptrdiff_t(to)));
  }

  nlohmann::json state_unlocked() const
  {
    const auto& seg = *m_run->pipeline.segmentation;
    nlohmann::json last = nullptr;
    if(m_last)
      last = {{"op", m_last->verb}, {"seconds", m_last->seconds}, {"prepare_seconds", m_last->prepare_seconds},
              {"server_seconds", m_last_server_seconds}, {"patches", m_last->patches}};
    // the segmentation's count: an edit's answer makes no pass over the faces
    return {{"patches", seg.number_of_patches()},
            {"alpha", seg.alpha()},
            {"cut_cost", seg.cut_cost()},
            {"edit_count", m_history.size()},
            {"edits_from", m_history.size() - std::min(m_history.size(), internal::editor_state_edits)},
            {"edits", internal::abbreviated(history_lines(m_history.size() - std::min(m_history.size(), internal::editor_state_edits),
                                                          internal::editor_state_edits))},
            {"can_undo", m_run->pipeline.number_of_undoable_edits() > 0},
            {"can_redo", m_run->pipeline.number_of_redoable_edits() > 0},
            {"last_edit", last},
            {"vertices", num_vertices(m_run->pipeline.mesh)},
            {"triangles", m_triangles.size()},
            {"feature_edges", seg.number_of_feature_edges()},
            {"crease_edges", seg.number_of_crease_edges()},
            {"radius", m_run->options.radius},
            {"strength_threshold", m_run->options.strength_threshold ? *m_run->options.strength_threshold
                                                                     : FS::default_strength_threshold}};
  }

  // The options, timer, results and pipeline of one run (a restart makes another).
  struct Run
  {
    explicit Run(const Options& o) : options(o), timer(o.quiet), pipeline(options, timer, results) {}
    Options options;
    Stage_timer timer;
    Results results;
    Pipeline pipeline;
  };

  mutable std::mutex m_mutex;
  std::unique_ptr<Run> m_run;
  std::vector<Mesh::Face_index> m_triangles;
  std::vector<Script_edit> m_history;
  std::optional<Edit_record> m_last;
  double m_last_server_seconds = 0;
};

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_EDITOR_API_H
