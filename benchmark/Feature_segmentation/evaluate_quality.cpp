// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality evaluation of the segmentation (issue 6; paper, Sections 5.2-5.3): this
// package's correlation clustering (full vertex graph, geodesic watershed, anisotropic
// watershed) side by side with CGAL's sharp_edges_segmentation (angle swept) and CGAL's
// variational shape approximation, on the same meshes and with the metrics of
// evaluation/metrics.h:
// - every model: patch count, cut cost (Eq. 1, reference weights: alpha 0.6, pruned
//   lines), coverage of the strong feature lines by the boundaries and redundancy;
// - models with a ground truth (ABC format: NAME.obj + NAME.yml): boundary precision,
//   recall and F-score at 1% of the bounding-box diagonal, area-weighted Rand index,
//   over- and under-segmentation, recall of the sharp ground-truth curves;
// - robustness (paper, Fig. 9): normal noise of 0.1% and 0.3% of the diagonal (seeded),
//   pruned and unpruned feature lines; the Rand index of each method's result to its
//   noise-free result.
// Each parametrised method gets a "default" row (alpha 0.6; angle 90 as in CGAL's
// example) and a "best" row from a sweep, chosen by the boundary F-score when a ground
// truth exists, else by the harmonic mean of coverage and (1 - redundancy fraction).
// Each correlation-clustering variant gets two more rows "with smoothing", at the same
// two alphas: the boundaries smoothed (smooth_patch_boundaries(), 20 iterations at most),
// every face scored with the patch covering most of its area (majority_face_patches());
// the coverage and redundancy and, with a ground truth, the boundary precision/recall/
// F-score of the smoothed curves themselves too (the "curve" columns). Without smoothing, a face has the patch of the
// majority of its vertices (segment_along_features()'s face_patch_map).
// VSA is given the ground-truth patch count, or without a ground truth the patch count of
// the default segmentation.
//
// Writes OUT/table.md, OUT/table.csv, OUT/robustness.csv and OUT/scenes/MODEL.scene (the
// input of render_scenes, which draws the contact sheets: four tiles a row, the feature
// lines and the ground truth, then one row per CC variant (default, default with
// smoothing, best, best with smoothing; smoothed tiles draw the smoothed curves), then the
// CGAL baselines).
//
// Usage: evaluate_quality [--data DIR] [--out DIR] [--only NAME[,NAME...]] [--no-robustness]
//   DIR (default $FEATURE_SEGMENTATION_DATA): holds paper-models/ and abc/ (ground truth);
//   without it, fandisk alone is evaluated.

#include "evaluation/abc_ground_truth.h"
#include "evaluation/methods.h"

#include <CGAL/Feature_segmentation/IO/write_segmentation.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace fs_evaluation;
namespace fsys = std::filesystem;

namespace {

struct Options
{
  std::string data;
  std::string out = "evaluation";
  std::set<std::string> only;
  bool robustness = true;
};

struct Model
{
  std::string name, path;
  bool has_ground_truth = false;
};

struct Row
{
  std::string model, method, setting, role; // role: default, best, given-count, ground truth
  bool smoothed = false;
  std::size_t faces = 0;
  Scores scores;
  double seconds = 0;
};

struct Robust_row
{
  std::string model, method, setting;
  double pruned_vs_unpruned = 0;         // Rand index on the clean mesh
  double noise[2][2] = {{0, 0}, {0, 0}}; // [level][unpruned]: Rand index to the clean result
};

const double noise_levels[2] = {0.001, 0.003};

std::string fmt(double v, int digits = 3)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

// Relabels `labels` so that each patch takes the id of the reference patch it overlaps
// most, largest patches first, when that id is still free: the tiles of one model then
// colour corresponding patches alike.
std::vector<std::size_t> match_to_reference(const std::vector<std::size_t>& labels,
                                            const std::vector<std::size_t>& reference,
                                            const std::vector<double>& area)
{
  std::map<std::size_t, std::map<std::size_t, double> > overlap;
  std::map<std::size_t, double> size;
  for(std::size_t f = 0; f < labels.size(); ++f)
  {
    overlap[labels[f]][reference[f]] += area[f];
    size[labels[f]] += area[f];
  }
  std::vector<std::pair<double, std::size_t> > order;
  for(const auto& s : size) order.emplace_back(-s.second, s.first);
  std::sort(order.begin(), order.end());
  std::set<std::size_t> taken;
  std::map<std::size_t, std::size_t> to;
  std::size_t next = *std::max_element(reference.begin(), reference.end()) + 1;
  for(const auto& o : order)
  {
    std::size_t best = 0;
    double best_area = -1;
    for(const auto& c : overlap[o.second])
      if(c.second > best_area) { best = c.first; best_area = c.second; }
    to[o.second] = taken.insert(best).second ? best : next++;
  }
  std::vector<std::size_t> result(labels.size());
  for(std::size_t f = 0; f < labels.size(); ++f) result[f] = to[labels[f]];
  return result;
}

// The input of render_scenes: the mesh once, then one tile per picture (a label, a
// colour per face, and segments to draw over the surface).
class Scene_writer
{
public:
  Scene_writer(const std::string& path, const Mesh& mesh) : m_os(path), m_mesh(mesh)
  {
    m_os << "fs_scene 1\nvertices " << mesh.number_of_vertices() << "\n" << std::setprecision(7);
    for(auto v : vertices(mesh)) m_os << mesh.point(v) << "\n";
    m_os << "faces " << mesh.number_of_faces() << "\n";
    for(auto f : faces(mesh))
    {
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) m_os << v.idx() << " ";
      m_os << "\n";
    }
  }
  bool good() const { return m_os.good(); }

  // Patches as face colours; with `curves`, the curves are drawn instead of the edges
  // between faces of different colours.
  void tile_with_patches(const std::string& label, const std::vector<std::size_t>& face_patch,
                         const Boundaries* curves = nullptr)
  {
    m_os << "tile " << label << "\ncolours\n";
    char buf[8];
    for(std::size_t f = 0; f < face_patch.size(); ++f)
    {
      const CGAL::IO::Color c = FS::segmentation_colour(face_patch[f]);
      std::snprintf(buf, sizeof(buf), "%02x%02x%02x", c.red(), c.green(), c.blue());
      m_os << buf << ((f % 16 == 15) ? "\n" : " ");
    }
    m_os << "\n";
    if(curves == nullptr)
    {
      m_os << "segments 0\n";
      return;
    }
    std::vector<std::pair<const std::array<double, 3>*, const std::array<double, 3>*> > segments;
    for(const auto& c : curves->curves())
    {
      const std::size_t n = c.points.size();
      const std::size_t m = c.is_closed() ? (n > 1 ? n : 0) : (n > 0 ? n - 1 : 0);
      for(std::size_t i = 0; i < m; ++i) segments.emplace_back(&c.points[i].point, &c.points[(i + 1) % n].point);
    }
    m_os << "face_boundaries 0\nsegments " << segments.size() << "\n";
    for(const auto& sg : segments)
      m_os << (*sg.first)[0] << " " << (*sg.first)[1] << " " << (*sg.first)[2] << " " << (*sg.second)[0] << " "
           << (*sg.second)[1] << " " << (*sg.second)[2] << " 141414 2\n";
  }

  // An empty place in the sheet, so that each CC variant keeps its own row.
  void blank_tile() { m_os << "blank\n"; }

  // Feature lines over a grey surface: strong ridges red, strong valleys blue, weaker
  // lines thinner and lighter.
  void tile_with_lines(const std::string& label, const Lines& lines)
  {
    m_os << "tile " << label << "\ncolours uniform d9d9d9\n";
    std::size_t n = 0;
    for(const auto& l : lines.lines) n += l.is_closed ? l.points.size() : (l.points.empty() ? 0 : l.points.size() - 1);
    m_os << "segments " << n << "\n";
    for(const auto& l : lines.lines)
    {
      const bool strong = l.strength >= FS::default_strong_feature_strength;
      const bool ridge = l.type == FS::Feature_line_type::RIDGE;
      const char* colour = ridge ? (strong ? "d01010" : "f08080") : (strong ? "1030d0" : "80a0f0");
      if(l.type == FS::Feature_line_type::USER) colour = "101010";
      const std::size_t m = l.is_closed ? l.points.size() : (l.points.empty() ? 0 : l.points.size() - 1);
      for(std::size_t i = 0; i < m; ++i)
        m_os << l.points[i].point(m_mesh, m_mesh.points()) << " "
             << l.points[(i + 1) % l.points.size()].point(m_mesh, m_mesh.points()) << " " << colour << " "
             << ((strong || l.type == FS::Feature_line_type::USER) ? 3 : 1) << "\n";
    }
  }

private:
  std::ofstream m_os;
  const Mesh& m_mesh;
};

bool read_model(const Model& model, Mesh& mesh, std::string& error)
{
  if(model.has_ground_truth) return read_mesh_in_file_order(model.path, mesh, error);
  if(!PMP::IO::read_polygon_mesh(model.path, mesh) || is_empty(mesh))
  {
    error = "unreadable";
    return false;
  }
  if(!CGAL::is_triangle_mesh(mesh))
  {
    error = "not a triangle mesh";
    return false;
  }
  return true;
}

// Two lines (montage reads the two characters \n as a line break): the method and its
// setting, then the scores.
std::string tile_label(const Row& r)
{
  std::string s = r.method + ", " + r.setting + (r.role.empty() ? "" : " (" + r.role + ")") +
                  (r.smoothed ? ", smoothed" : "") + "\\n" + std::to_string(r.scores.patches) + " patches";
  if(r.scores.has_curve_scores)
    s += ", F " + fmt(r.scores.boundary.f_score, 2) + " (curves " + fmt(r.scores.curve_boundary.f_score, 2) +
         "), RI " + fmt(r.scores.partition.rand_index, 3);
  else if(r.scores.has_ground_truth)
    s += ", F " + fmt(r.scores.boundary.f_score, 2) + ", RI " + fmt(r.scores.partition.rand_index, 3);
  else
    s += ", cov " + fmt(r.scores.lines.coverage, 2) + ", red " + fmt(r.scores.lines.redundancy_fraction(), 2);
  return s;
}

// Evaluates one model; appends its rows.
void evaluate(const Model& model, const Options& opt, std::vector<Row>& rows, std::vector<Robust_row>& robust)
{
  Mesh mesh;
  std::string error;
  if(!read_model(model, mesh, error))
  {
    std::cerr << "evaluate_quality: skipping " << model.path << ": " << error << std::endl;
    return;
  }
  std::vector<int> gt;
  Abc_ground_truth truth;
  Lines sharp;
  if(model.has_ground_truth)
  {
    try
    {
      truth = read_abc_ground_truth(fsys::path(model.path).replace_extension(".yml").string(),
                                    mesh.number_of_vertices(), mesh.number_of_faces());
    }
    catch(const std::exception& e)
    {
      std::cerr << "evaluate_quality: skipping " << model.path << ": " << e.what() << std::endl;
      return;
    }
    gt = truth.face_patch;
    sharp = curves_as_lines(mesh, truth.curves, truth.curve_is_sharp);
  }
  std::cerr << "evaluate_quality: " << model.name << " (" << mesh.number_of_faces() << " faces)" << std::endl;
  const Prepared_mesh pm(mesh);

  // The contact sheet's tiles after the header row, four a row; an empty row is a blank tile.
  std::vector<std::pair<Row, Segmentation> > shown;
  auto blank = [&]() { shown.emplace_back(Row(), Segmentation()); };
  auto add = [&](const Segmentation& s, const std::string& role, bool show) {
    Row r;
    r.model = model.name;
    r.faces = mesh.number_of_faces();
    r.method = s.method;
    r.setting = s.setting;
    r.role = role;
    r.smoothed = s.is_smoothed();
    r.seconds = s.seconds;
    r.scores = score(pm, s, gt, model.has_ground_truth ? &sharp : nullptr);
    rows.push_back(r);
    if(show) shown.emplace_back(r, s);
    return r;
  };
  auto best_of = [&](const std::vector<Segmentation>& runs) {
    std::size_t best = 0;
    double best_score = -1;
    for(std::size_t i = 0; i < runs.size(); ++i)
    {
      const double x = selection_score(score(pm, runs[i], gt, model.has_ground_truth ? &sharp : nullptr));
      if(x > best_score + 1e-12) { best = i; best_score = x; }
    }
    return best;
  };

  // This package, three variants, alpha swept; the default and the best alpha also with
  // smoothing. A row of the sheet per variant: default, default smoothed, best, best smoothed.
  std::size_t default_patches = 0;
  std::vector<std::size_t> default_labels;
  Cc_variant variants[3] = {Cc_variant::ANISOTROPIC_WATERSHED, Cc_variant::GEODESIC_WATERSHED, Cc_variant::FULL_GRAPH};
  for(Cc_variant v : variants)
  {
    std::vector<Segmentation> runs;
    std::size_t def = 0;
    for(double a : alpha_sweep())
    {
      if(std::abs(a - default_alpha) < 1e-9) def = runs.size();
      runs.push_back(run_cc(pm, v, a));
    }
    const std::size_t best = best_of(runs);
    const Segmentation smoothed_default = smooth_cc(pm, runs[def]);
    const bool same = best == def;
    add(runs[def], "default", true);
    add(smoothed_default, "default", true);
    add(runs[best], "best", !same);
    add(same ? smoothed_default : smooth_cc(pm, runs[best]), "best", !same);
    if(same)
    {
      for(std::size_t i = shown.size() - 2; i < shown.size(); ++i) shown[i].first.role = "default and best";
      blank();
      blank();
    }
    if(v == Cc_variant::ANISOTROPIC_WATERSHED)
    {
      default_labels = runs[def].face_patch;
      default_patches = FS::number_of_patches(mesh, boost::make_function_property_map<face_descriptor>(
        [&](face_descriptor f) { return default_labels[f.idx()]; }));
    }
  }

  // CGAL's sharp-edge segmentation, angle swept.
  std::vector<Segmentation> pmp_runs;
  std::size_t pmp_def = 0;
  for(double a : angle_sweep())
  {
    if(std::abs(a - default_sharp_angle) < 1e-9) pmp_def = pmp_runs.size();
    pmp_runs.push_back(run_sharp_edges(mesh, a));
  }
  const std::size_t pmp_best = best_of(pmp_runs);
  const double best_angle = angle_sweep()[pmp_best];
  add(pmp_runs[pmp_def], "default", true);
  add(pmp_runs[pmp_best], "best", pmp_best != pmp_def);

  // VSA with the ground-truth count (else the default segmentation's count).
  const std::size_t k = model.has_ground_truth ? truth.number_of_patches() : (std::max<std::size_t>)(default_patches, 2);
  add(run_vsa(mesh, k), model.has_ground_truth ? "ground-truth count" : "count of CC default", true);

  // Contact-sheet scene.
  fsys::create_directories(fsys::path(opt.out) / "scenes");
  Scene_writer scene((fsys::path(opt.out) / "scenes" / (model.name + ".scene")).string(), mesh);
  std::vector<std::size_t> reference(mesh.number_of_faces());
  if(model.has_ground_truth)
    for(std::size_t f = 0; f < reference.size(); ++f) reference[f] = static_cast<std::size_t>(gt[f] < 0 ? 0 : gt[f]);
  else
    reference = default_labels;
  scene.tile_with_lines("feature lines, pruned (" + std::to_string(pm.pruned.lines.size()) + " lines; strong dark)",
                        pm.pruned);
  scene.tile_with_lines("feature lines, unpruned (" + std::to_string(pm.unpruned.lines.size()) + " lines)", pm.unpruned);
  if(model.has_ground_truth)
  {
    scene.tile_with_lines("ground-truth sharp curves (" + std::to_string(sharp.lines.size()) + ")", sharp);
    scene.tile_with_patches("ground truth: " + std::to_string(truth.number_of_patches()) + " patches", reference);
  }
  else
  {
    scene.blank_tile();
    scene.blank_tile();
  }
  for(const auto& rs : shown)
  {
    if(rs.first.method.empty())
      scene.blank_tile();
    else
      scene.tile_with_patches(tile_label(rs.first), match_to_reference(rs.second.face_patch, reference, pm.face_area),
                              rs.second.curves.get());
  }
  if(!scene.good()) std::cerr << "evaluate_quality: cannot write the scene of " << model.name << std::endl;

  if(!opt.robustness) return;
  // Robustness: each method at a fixed setting, on the clean and the noisy meshes.
  struct Fixed
  {
    std::string method, setting;
    std::function<Segmentation(const Prepared_mesh&, bool)> run;
  };
  std::vector<Fixed> fixed;
  for(Cc_variant v : variants)
    fixed.push_back({name(v), "alpha " + fmt(default_alpha, 1),
                     [v](const Prepared_mesh& p, bool pruned) { return run_cc(p, v, default_alpha, pruned); }});
  fixed.push_back({"PMP sharp edges", "angle " + fmt(best_angle, 0) + " (best)",
                   [best_angle](const Prepared_mesh& p, bool) { return run_sharp_edges(p.mesh, best_angle); }});
  fixed.push_back({"VSA", std::to_string(k) + " proxies",
                   [k](const Prepared_mesh& p, bool) { return run_vsa(p.mesh, k); }});
  std::vector<Segmentation> clean[2];
  for(const auto& m : fixed)
    for(int u = 0; u < 2; ++u) clean[u].push_back(m.run(pm, u == 0));
  std::vector<Robust_row> out(fixed.size());
  for(std::size_t i = 0; i < fixed.size(); ++i)
  {
    out[i].model = model.name;
    out[i].method = fixed[i].method;
    out[i].setting = fixed[i].setting;
    out[i].pruned_vs_unpruned = FS::rand_index(clean[0][i].face_patch, clean[1][i].face_patch, pm.face_area);
  }
  for(int level = 0; level < 2; ++level)
  {
    const Mesh noisy = add_normal_noise(mesh, noise_levels[level], 20170601u + 7u * static_cast<unsigned>(level));
    const Prepared_mesh pn(noisy);
    for(std::size_t i = 0; i < fixed.size(); ++i)
      for(int u = 0; u < 2; ++u)
        out[i].noise[level][u] = FS::rand_index(clean[u][i].face_patch, fixed[i].run(pn, u == 0).face_patch, pm.face_area);
  }
  robust.insert(robust.end(), out.begin(), out.end());
}

// "alpha 0.6, smoothed (default)"
std::string setting_text(const Row& r)
{
  return r.setting + (r.smoothed ? ", smoothed" : "") + (r.role.empty() ? "" : " (" + r.role + ")");
}

void write_outputs(const Options& opt, const std::vector<Row>& rows, const std::vector<Robust_row>& robust,
                   const std::string& machine)
{
  const fsys::path out(opt.out);
  {
    std::ofstream csv(out / "table.csv");
    csv << "model,faces,method,setting,role,patches,cut_cost,coverage,redundant_length,redundancy_fraction,"
           "precision,recall,f_score,rand_index,over_segmentation,under_segmentation,sharp_curve_recall,seconds,"
           "smoothed,curve_precision,curve_recall,curve_f_score,curve_coverage,curve_redundancy_fraction\n";
    for(const Row& r : rows)
    {
      const Scores& s = r.scores;
      csv << r.model << "," << r.faces << "," << r.method << ",\"" << r.setting << "\"," << r.role << "," << s.patches
          << "," << s.cut_cost << "," << s.lines.coverage << "," << s.lines.redundant_length << ","
          << s.lines.redundancy_fraction() << ",";
      if(s.has_ground_truth)
        csv << s.boundary.precision << "," << s.boundary.recall << "," << s.boundary.f_score << ","
            << s.partition.rand_index << "," << s.partition.over_segmentation << "," << s.partition.under_segmentation
            << "," << s.sharp_curve_recall;
      else
        csv << ",,,,,,";
      csv << "," << r.seconds << "," << (r.smoothed ? 1 : 0) << ",";
      if(s.has_curve_scores)
        csv << s.curve_boundary.precision << "," << s.curve_boundary.recall << "," << s.curve_boundary.f_score;
      else
        csv << ",,";
      csv << ",";
      if(s.is_smoothed) csv << s.curve_lines.coverage << "," << s.curve_lines.redundancy_fraction();
      else csv << ",";
      csv << "\n";
    }
  }
  {
    std::ofstream csv(out / "robustness.csv");
    csv << "model,method,setting,ri_pruned_vs_unpruned,ri_noise_0.1%_pruned,ri_noise_0.1%_unpruned,"
           "ri_noise_0.3%_pruned,ri_noise_0.3%_unpruned\n";
    for(const Robust_row& r : robust)
      csv << r.model << "," << r.method << ",\"" << r.setting << "\"," << r.pruned_vs_unpruned << "," << r.noise[0][0]
          << "," << r.noise[0][1] << "," << r.noise[1][0] << "," << r.noise[1][1] << "\n";
  }
  std::ofstream md(out / "table.md");
  md << "# Segmentation quality\n\nMachine: " << machine << ". Produced by `scripts/run_evaluation.sh` "
     << "(`evaluate_quality`); tolerance 1% of the bounding-box diagonal; cut cost with the reference weights "
     << "(alpha 0.6, pruned lines; lower is better); \"default\": alpha 0.6, angle 90 (CGAL's example); \"best\": "
     << "the best of the sweep (alpha 0.4-1.2, angle 10-90) by boundary F-score with a ground truth, else by the "
     << "harmonic mean of coverage and 1 - redundancy. \"smoothed\": the same segmentation with its boundaries "
     << "smoothed (smooth_patch_boundaries, 20 iterations at most) and every face given the patch covering most of "
     << "its area (majority_face_patches); without it, a face has the patch of the majority of its vertices. Every "
     << "score is computed on the face patches (the boundary is the chain of mesh edges between faces of different "
     << "patches), except the cut cost (on the vertex patches) and the curve columns, computed on the smoothed curves "
     << "themselves (their segments cross the triangles).\n\n";
  md << "## Against the ground truth\n\n"
     << "| model | method | setting | patches | boundary P | boundary R | boundary F | Rand index | over | under | "
        "sharp-curve recall | cut cost | curve P | curve R | curve F |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(const Row& r : rows)
    if(r.scores.has_ground_truth)
    {
      const Scores& s = r.scores;
      md << "| " << r.model << " | " << r.method << " | " << setting_text(r)
         << " | " << s.patches << " | " << fmt(s.boundary.precision) << " | " << fmt(s.boundary.recall) << " | **"
         << fmt(s.boundary.f_score) << "** | **" << fmt(s.partition.rand_index) << "** | "
         << s.partition.over_segmentation << " | " << s.partition.under_segmentation << " | "
         << fmt(s.sharp_curve_recall) << " | " << fmt(s.cut_cost, 2) << " | ";
      if(s.has_curve_scores)
        md << fmt(s.curve_boundary.precision) << " | " << fmt(s.curve_boundary.recall) << " | **"
           << fmt(s.curve_boundary.f_score) << "** |\n";
      else
        md << "- | - | - |\n";
    }
  md << "\n## Against the feature lines (every model, no ground truth needed)\n\n"
     << "Coverage: share of the strong feature-line length (strength >= 10) within the tolerance of a patch "
        "boundary. Redundancy: share of the boundary length farther than the tolerance from every detected line. "
        "Both on the face patches' boundary edges, and for smoothed rows on the smoothed curves too (curve "
        "columns).\n\n"
     << "| model | faces | method | setting | patches | coverage | redundancy | curve coverage | curve redundancy | "
        "cut cost | seconds |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(const Row& r : rows)
    md << "| " << r.model << " | " << r.faces << " | " << r.method << " | " << setting_text(r) << " | "
       << r.scores.patches << " | " << fmt(r.scores.lines.coverage) << " | " << fmt(r.scores.lines.redundancy_fraction())
       << " | " << (r.scores.is_smoothed ? fmt(r.scores.curve_lines.coverage) : std::string("-")) << " | "
       << (r.scores.is_smoothed ? fmt(r.scores.curve_lines.redundancy_fraction()) : std::string("-")) << " | "
       << fmt(r.scores.cut_cost, 2) << " | " << fmt(r.seconds, 3) << " |\n";
  if(!robust.empty())
  {
    md << "\n## Robustness (paper, Fig. 9)\n\nRand index of each method's result to its own noise-free result "
          "(1 = unchanged), vertices moved along their normals by a seeded normal deviate of standard deviation "
          "0.1% and 0.3% of the diagonal, with pruned (default, strength >= 1) and unpruned feature lines; and "
          "the Rand index between the pruned and unpruned results on the clean mesh. The CGAL baselines do not "
          "use feature lines (their two columns are the same run).\n\n"
       << "| model | method | setting | pruned vs unpruned | 0.1% pruned | 0.1% unpruned | 0.3% pruned | "
          "0.3% unpruned |\n|---|---|---|---|---|---|---|---|\n";
    for(const Robust_row& r : robust)
      md << "| " << r.model << " | " << r.method << " | " << r.setting << " | " << fmt(r.pruned_vs_unpruned) << " | "
         << fmt(r.noise[0][0]) << " | " << fmt(r.noise[0][1]) << " | " << fmt(r.noise[1][0]) << " | "
         << fmt(r.noise[1][1]) << " |\n";
  }
}

std::string machine_description()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, cpu = "unknown CPU";
  while(std::getline(cpuinfo, line))
    if(line.rfind("model name", 0) == 0)
    {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores (one used)";
}

} // namespace

int main(int argc, char** argv)
{
  Options opt;
  if(const char* env = std::getenv("FEATURE_SEGMENTATION_DATA")) opt.data = env;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if((a == "--data" || a == "--out" || a == "--only") && i + 1 < argc)
    {
      const std::string v = argv[++i];
      if(a == "--data") opt.data = v;
      else if(a == "--out") opt.out = v;
      else
      {
        std::stringstream ss(v);
        std::string n;
        while(std::getline(ss, n, ',')) opt.only.insert(n);
      }
    }
    else if(a == "--no-robustness") opt.robustness = false;
    else
    {
      std::cerr << "usage: evaluate_quality [--data DIR] [--out DIR] [--only NAME[,NAME...]] [--no-robustness]\n";
      return 2;
    }
  }

  std::vector<Model> models;
  models.push_back({"fandisk", std::string(FS_MESH_DIR) + "/fandisk.off", false});
  std::error_code ec;
  if(opt.data.empty() || !fsys::is_directory(opt.data, ec))
    std::cerr << "evaluate_quality: no data folder (set FEATURE_SEGMENTATION_DATA or --data): fandisk only"
              << std::endl;
  else
  {
    for(const auto& p : ground_truth_models(fsys::path(opt.data) / "abc"))
      models.push_back({"abc_" + p.stem().string(), p.string(), true});
    std::vector<fsys::path> paper;
    const fsys::path dir = fsys::path(opt.data) / "paper-models";
    if(fsys::is_directory(dir, ec))
      for(const auto& e : fsys::directory_iterator(dir, ec))
        if(e.path().extension() == ".off" || e.path().extension() == ".obj") paper.push_back(e.path());
    std::sort(paper.begin(), paper.end());
    for(const auto& p : paper) models.push_back({p.stem().string(), p.string(), false});
  }

  std::vector<Row> rows;
  std::vector<Robust_row> robust;
  fsys::create_directories(opt.out, ec);
  for(const Model& m : models)
  {
    if(!opt.only.empty() && !opt.only.count(m.name)) continue;
    try
    {
      evaluate(m, opt, rows, robust);
    }
    catch(const std::exception& e)
    {
      std::cerr << "evaluate_quality: " << m.name << " failed: " << e.what() << std::endl;
    }
  }
  if(rows.empty())
  {
    std::cerr << "evaluate_quality: no model evaluated" << std::endl;
    return 1;
  }
  write_outputs(opt, rows, robust, machine_description());
  std::cout << "evaluate_quality: wrote " << (fsys::path(opt.out) / "table.md").string() << ", table.csv, "
            << "robustness.csv and scenes/ (" << rows.size() << " rows)" << std::endl;
  return 0;
}
