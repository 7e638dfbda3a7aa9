// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality evaluation of the segmentation (issues 6 and 13; paper, Sections 5.2-5.3), in
// three parts.
//
// The quality table: this package's correlation clustering (full vertex graph, geodesic
// watershed, anisotropic watershed) side by side with CGAL's sharp_edges_segmentation
// (angle swept) and CGAL's variational shape approximation, on fandisk, the ABC models
// and the paper's models, with the metrics of evaluation/metrics.h:
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
// F-score of the smoothed curves themselves too (the "curve" columns). Without
// smoothing, a face has the patch of the majority of its vertices
// (segment_along_features()'s face_patch_map). VSA is given the ground-truth patch
// count, or without a ground truth the patch count of the default segmentation.
// Writes OUT/table.md, OUT/table.csv, OUT/robustness.csv (evaluation/quality_tables.h)
// and OUT/scenes/MODEL.scene (evaluation/scenes.h; the input of render_scenes, which
// draws the contact sheets: four tiles a row, the feature lines and the ground truth,
// then one row per CC variant (default, default with smoothing, best, best with
// smoothing; smoothed tiles draw the smoothed curves), then the CGAL baselines).
//
// The CAD table (evaluation/cad_tables.h): the parts of DATA/cad and DATA/abc-dev (the
// development set) against their B-rep faces, and the ABC models of DATA/abc after them,
// by the boundary F-score and the Rand index: this package at its
// defaults, the paper's pipeline, sharp edges at 20/45/60 degrees and VSA with the true
// patch count, at the noise levels of --noise; OUT/cad_parts.md and OUT/cad_parts.csv.
//
// The resolution series (evaluation/resolution_series.h): fandisk flat-subdivided 0 to 3 times
// (13k to 828k faces), this package's patch counts and boundary F against the coarse
// result; OUT/resolution.md and OUT/resolution.csv.
//
// Usage: evaluate_quality [--data DIR] [--out DIR] [--only NAME[,NAME...]] [--parts NAME[,NAME...]]
//                         [--no-robustness] [--methods NAME[,NAME...]]
//                         [--noise X,Y,...] [--noise-seeds N] [--alpha A] [--strength-threshold S]
//                         [--crease-filter N] [--no-tangent] [--crest-lines | --no-crest-lines]
//   DIR (default $FEATURE_SEGMENTATION_DATA): holds paper-models/, abc/ (ground truth)
//   and cad/; without it, fandisk alone is evaluated and the CAD table is skipped.
//   --only names models of the quality table, "cad" (the CAD table) and "resolution"
//   (the resolution series): `--only cad` is the CAD table alone. The options from
//   --noise on set the CAD table and the resolution series; --methods keeps some of the
//   CAD table's columns (`--methods default` for a quick look at the package alone);
//   --noise-seeds N scores every noisy level on N noise realisations and gives their
//   means (on one realisation a part's F moves by 0.1 or more between nearly equal
//   settings).
//   --help tells more.

#include "evaluation/abc_ground_truth.h"
#include "evaluation/cad_tables.h"
#include "evaluation/resolution_series.h"
#include "evaluation/methods.h"
#include "evaluation/quality_tables.h"
#include "evaluation/report.h"
#include "evaluation/scenes.h"
#include "provenance.h"
#include "evaluate_quality_options.h"

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <boost/program_options.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

using namespace fs_evaluation;
namespace fsys = std::filesystem;

namespace {

struct Model
{
  std::string name, path;
  bool has_ground_truth = false;
};

const double noise_levels[2] = {0.001, 0.003};

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
void evaluate(const Model& model, const Evaluation_options& opt, std::vector<Row>& rows, std::vector<Robust_row>& robust)
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

// The models of the quality table: fandisk, then, from the data folder, the ABC models
// and the paper's models.
std::vector<Model> quality_models(const Evaluation_options& opt)
{
  std::vector<Model> models;
  models.push_back({"fandisk", std::string(FS_MESH_DIR) + "/fandisk.off", false});
  std::error_code ec;
  if(opt.data.empty() || !fsys::is_directory(opt.data, ec))
  {
    std::cerr << "evaluate_quality: no data folder (set FEATURE_SEGMENTATION_DATA or --data): fandisk only"
              << std::endl;
    return models;
  }
  for(const auto& p : ground_truth_models(fsys::path(opt.data) / "abc"))
    models.push_back({"abc_" + p.stem().string(), p.string(), true});
  std::vector<fsys::path> paper;
  const fsys::path dir = fsys::path(opt.data) / "paper-models";
  if(fsys::is_directory(dir, ec))
    for(const auto& e : fsys::directory_iterator(dir, ec))
      if(e.path().extension() == ".off" || e.path().extension() == ".obj") paper.push_back(e.path());
  std::sort(paper.begin(), paper.end());
  for(const auto& p : paper) models.push_back({p.stem().string(), p.string(), false});
  return models;
}

// The quality table of the models selected; false when none could be evaluated.
bool run_quality_table(const Evaluation_options& opt, const std::string& machine)
{
  std::vector<Row> rows;
  std::vector<Robust_row> robust;
  for(const Model& m : quality_models(opt))
  {
    if(!opt.selected(m.name)) continue;
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
    return false;
  }
  write_outputs(opt.out, rows, robust, machine);
  std::cout << "evaluate_quality: wrote " << (fsys::path(opt.out) / "table.md").string() << ", table.csv, "
            << "robustness.csv and scenes/ (" << rows.size() << " rows)" << std::endl;
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  Evaluation_options opt;
  if(const char* env = std::getenv("FEATURE_SEGMENTATION_DATA")) opt.data = env;
  if(const std::optional<int> status = read_command_line(argc, argv, opt)) return *status;
  std::error_code ec;
  fsys::create_directories(opt.out, ec);
  if(ec)
  {
    std::cerr << "evaluate_quality: cannot create " << opt.out << ": " << ec.message() << std::endl;
    return 1;
  }
  const std::string machine = machine_description();
  const bool quality_evaluated = !opt.quality_table() || run_quality_table(opt, machine);
  if(opt.selected("cad")) run_cad_table(opt.data, opt.out, opt.cad_options, machine, opt.parts, opt.generated);
  if(opt.selected("resolution"))
    run_resolution_series(std::string(FS_MESH_DIR) + "/fandisk.off", opt.out, opt.cad_options, machine);
  for(const char* csv : {"table.csv", "cad_parts.csv", "resolution.csv"})
    fs_bench::write_provenance(fsys::path(opt.out) / csv, argc, argv);
  return quality_evaluated ? 0 : 1;
}
