// SPDX-License-Identifier: GPL-3.0-or-later
// The report of a run of the program `feature_segmentation`: the timing of its stages
// (Stage_timer), the solver timed on its own (Timed_solver), what the run measured
// (Results) and summary.json, which writes it all (write_summary()).

#ifndef CGAL_FEATURE_SEGMENTATION_APP_RUN_REPORT_H
#define CGAL_FEATURE_SEGMENTATION_APP_RUN_REPORT_H

#include "edit_runner.h"
#include "peak_memory.h"
#include "option_table.h"
#include "read_input_mesh.h"

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Greedy_additive_edge_contraction.h>
#include <CGAL/Feature_segmentation/Kernighan_lin_with_joins.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>
#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/internal/stage_times.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fs_app {

// Wall-clock seconds of each stage, in the order the stages ran.
class Stage_timer
{
public:
  explicit Stage_timer(bool quiet) : m_quiet(quiet) {}

  template <typename F>
  auto run(const std::string& name, F&& f)
  {
    if(!m_quiet)
      std::cerr << "progress: " << name << " ..." << std::endl;
    reset_peak_resident();
    const auto start = std::chrono::steady_clock::now();
    auto finish = [&]() {
      const std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
      // a stage run again (the editor saves more than once) keeps its place, new figures
      auto it = std::find_if(m_seconds.begin(), m_seconds.end(), [&](const auto& s) { return s.first == name; });
      if(it != m_seconds.end()) it->second = d.count();
      else m_seconds.emplace_back(name, d.count());
      const double peak = peak_resident_mib();
      auto pm = std::find_if(m_peak_mib.begin(), m_peak_mib.end(), [&](const auto& s) { return s.first == name; });
      if(pm != m_peak_mib.end()) pm->second = peak;
      else m_peak_mib.emplace_back(name, peak);
      if(!m_quiet)
        std::cerr << "progress: " << name << " done in " << std::fixed << std::setprecision(3)
                  << d.count() << " s" << std::defaultfloat << std::endl;
    };
    if constexpr(std::is_void_v<decltype(f())>)
    {
      f();
      finish();
    }
    else
    {
      auto result = f();
      finish();
      return result;
    }
  }

  const std::vector<std::pair<std::string, double> >& seconds() const { return m_seconds; }
  /// The peak resident memory of each stage, MiB (-1 where unknown).
  const std::vector<std::pair<std::string, double> >& peak_mib() const { return m_peak_mib; }

  /// The last time of stage `name` (0 if it never ran).
  double seconds_of(const std::string& name) const
  {
    for(const auto& s : m_seconds)
      if(s.first == name) return s.second;
    return 0;
  }

private:
  bool m_quiet;
  std::vector<std::pair<std::string, double> > m_seconds;
  std::vector<std::pair<std::string, double> > m_peak_mib;
};

// The solver chosen with --solver, timed on its own: the segmentation stage also builds
// the graph and its weights, and the summary reports both times.
class Timed_solver
{
public:
  Timed_solver(const std::string& name, double& seconds) : m_name(name), m_seconds(&seconds) {}

  std::size_t operator()(const FS::Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    const auto start = std::chrono::steady_clock::now();
    std::size_t n = 0;
    if(m_name == "gaec")
      n = FS::Greedy_additive_edge_contraction()(g, labels);
    else if(m_name == "klj")
    {
      labels.clear(); // from singletons
      FS::Kernighan_lin_with_joins solver;
      solver.set_parallel(true);
      n = solver(g, labels);
    }
    else
    {
      // Kernighan-Lin's rounds on the run's threads: the same labels at any count
      FS::Default_correlation_clustering_solver solver;
      solver.second().set_parallel(true);
      n = solver(g, labels);
    }
    const std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
    *m_seconds = d.count();
    return n;
  }

private:
  std::string m_name;
  double* m_seconds; // the solver is copied by the segmentation: the time lives with the caller
};

struct Results
{
  fs_app::Read_report read_report;
  std::size_t number_of_vertices = 0;
  std::size_t number_of_edges = 0;
  std::size_t number_of_faces = 0;
  std::size_t number_of_feature_edges = 0;
  std::size_t number_of_crease_edges = 0;
  std::size_t number_of_ridges = 0;
  std::size_t number_of_valleys = 0;
  std::size_t number_of_user_lines = 0;
  std::size_t number_of_lines = 0;
  std::size_t number_of_crease_lines = 0;  // polylines of feature_lines.* typed "crease"
  std::size_t number_of_seam_lines = 0;    // ... typed "seam" (curvature discontinuities)
  std::size_t number_of_seam_crossings = 0; // feature lines typed "seam_line" (through faces)
  std::size_t number_of_patches = 0;       // after the edits, the patches holding a face
  double cut_cost = 0;                     // after the edits
  std::size_t number_of_automatic_patches = 0; // before the edits
  double automatic_cut_cost = 0;           // before the edits
  std::size_t number_of_oversegments = 0;
  double solver_seconds = 0;               // of the automatic segmentation
  FS::internal::Stage_times segmentation_stages; // the seconds inside the stage "segmentation"
  std::vector<fs_app::Edit_record> edits;
  // The boundaries and their smoothing.
  std::size_t number_of_curves = 0;        // inside faces (smoothed)
  std::size_t number_of_crease_curves = 0; // on creases between two patches (exact)
  std::size_t number_of_junctions = 0;
  std::size_t smoothing_iterations_run = 0;
  std::size_t smoothing_vertex_moves = 0;
  double length_before = 0, length_after = 0;
  double anisotropic_length_before = 0, anisotropic_length_after = 0;
  double smoothing_seconds = 0;
  std::size_t number_of_refined_vertices = 0;
  std::size_t number_of_refined_faces = 0;
  std::size_t number_of_split_faces = 0;
};

/// The options of the run, as summary.json records them: the segmentation's options of
/// option_table.h, the edit script and the threads, by keyword (a library default where
/// the option was not given; null for no file).
inline nlohmann::ordered_json options_json(const Options& options)
{
  typedef nlohmann::ordered_json Json;
  Json j = Json::object();
  for(const Option_entry& e : option_table())
  {
    if(!e.segmentation && e.keyword != "edits" && e.keyword != "threads") continue;
    const std::string v = e.effective_value(options);
    if(e.kind == Option_kind::SWITCH) j[e.keyword] = v == "true";
    else if(e.kind == Option_kind::INTEGER) j[e.keyword] = std::stoll(v);
    else if(e.kind == Option_kind::NUMBER) j[e.keyword] = std::stod(v);
    else j[e.keyword] = v.empty() ? Json(nullptr) : Json(v);
  }
  return j;
}

// `peak_mib`: the peak resident memory of each stage (the write's without this summary,
// written last), "peak_memory_mib" in the summary.
inline void write_summary(std::ostream& os, const Options& options, const Results& r,
                          const std::vector<std::pair<std::string, double> >& seconds,
                          const std::vector<std::pair<std::string, double> >& peak_mib = {})
{
  typedef nlohmann::ordered_json Json;
  Json edits = Json::array();
  for(const Edit_record& e : r.edits)
  {
    Json j{{"line", e.line}, {"verb", e.verb}, {"patches", e.patches}, {"cut_cost", e.cut_cost}};
    if(e.verb == "undo") j["undone_line"] = e.undone_line;
    else if(e.verb == "redo") j["redone_line"] = e.redone_line;
    else if(e.verb == "sketch") j["points"] = e.points;
    else if(e.verb != "alpha") j["faces"] = e.faces;
    j["seconds"] = e.seconds;
    j["solver_seconds"] = e.solver_seconds;
    j["prepare_seconds"] = e.prepare_seconds;
    edits.push_back(j);
  }
  Json stages = Json::object();
  double total = 0;
  for(const auto& s : seconds)
  {
    stages[s.first] = s.second;
    total += s.second;
  }
  stages["total"] = total;
  Json peaks = Json::object();
  for(const auto& s : peak_mib)
    if(s.second >= 0) peaks[s.first] = s.second;
  const Json summary{
    {"program", program_name},
    {"input", options.input},
    {"options", options_json(options)},
    {"input_file",
     {{"format", r.read_report.format},
      {"vertices", r.read_report.number_of_file_points},
      {"faces", r.read_report.number_of_file_faces},
      {"removed_vertices", r.read_report.number_of_merged_points},
      {"removed_faces", r.read_report.number_of_removed_faces},
      {"duplicated_vertices", r.read_report.number_of_duplicated_points},
      {"triangulated_faces", r.read_report.number_of_triangulated_faces}}},
    {"mesh",
     {{"vertices", r.number_of_vertices},
      {"edges", r.number_of_edges},
      {"faces", r.number_of_faces},
      {"border_edges", r.read_report.number_of_border_edges}}},
    {"feature_lines",
     {{"total", r.number_of_lines},
      {"ridges", r.number_of_ridges},
      {"valleys", r.number_of_valleys},
      {"user", r.number_of_user_lines},
      {"creases", r.number_of_crease_lines},
      {"seams", r.number_of_seam_lines},
      {"seam_lines", r.number_of_seam_crossings}}},
    {"feature_edges", r.number_of_feature_edges},
    {"crease_edges", r.number_of_crease_edges},
    {"segmentation",
     {{"patches", r.number_of_patches},
      {"cut_cost", r.cut_cost},
      {"automatic_patches", r.number_of_automatic_patches},
      {"automatic_cut_cost", r.automatic_cut_cost},
      {"oversegments", r.number_of_oversegments},
      {"solver_seconds", r.solver_seconds},
      {"stage_seconds",
       {{"mesh_check_and_indexing", r.segmentation_stages.mesh_check_and_indexing},
        {"creases", r.segmentation_stages.creases},
        {"curvature", r.segmentation_stages.curvature},
        {"feature_lines", r.segmentation_stages.feature_lines},
        {"weight_terms", r.segmentation_stages.weight_terms},
        {"oversegmentation", r.segmentation_stages.oversegmentation},
        {"graph", r.segmentation_stages.graph},
        {"solve", r.segmentation_stages.solve},
        {"labels", r.segmentation_stages.labels}}}}},
    {"edits", edits},
    {"boundaries",
     {{"curves", r.number_of_curves},
      {"crease_curves", r.number_of_crease_curves},
      {"junctions", r.number_of_junctions},
      {"length_before", r.length_before},
      {"length_after", r.length_after},
      {"anisotropic_length_before", r.anisotropic_length_before},
      {"anisotropic_length_after", r.anisotropic_length_after},
      {"smoothing_iterations", r.smoothing_iterations_run},
      {"vertex_moves", r.smoothing_vertex_moves},
      {"smoothing_seconds", r.smoothing_seconds},
      {"refined_vertices", r.number_of_refined_vertices},
      {"refined_faces", r.number_of_refined_faces},
      {"split_faces", r.number_of_split_faces}}},
    {"seconds", stages},
    {"peak_memory_mib", peaks}};
  os << summary.dump(2) << '\n';
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_RUN_REPORT_H
