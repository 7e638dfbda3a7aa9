// SPDX-License-Identifier: GPL-3.0-or-later
// The quality table of evaluate_quality (paper models, fandisk, ABC ground truth): its
// rows, and its files OUT/table.md, OUT/table.csv and OUT/robustness.csv.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_QUALITY_TABLES_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_QUALITY_TABLES_H

#include "methods.h"
#include "report.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs_evaluation {

/// One segmentation of one model, scored.
struct Row
{
  std::string model, method, setting, role; // role: default, best, given-count, ground truth
  bool smoothed = false;
  std::size_t faces = 0;
  Scores scores;
  double seconds = 0;
};

/// One method's stability on one model (paper, Fig. 9).
struct Robust_row
{
  std::string model, method, setting;
  double pruned_vs_unpruned = 0;         // Rand index on the clean mesh
  double noise[2][2] = {{0, 0}, {0, 0}}; // [level][unpruned]: Rand index to the clean result
};

// "alpha 0.6, smoothed (default)"
inline std::string setting_text(const Row& r)
{
  return r.setting + (r.smoothed ? ", smoothed" : "") + (r.role.empty() ? "" : " (" + r.role + ")");
}

/// Writes OUT/table.csv, OUT/robustness.csv and OUT/table.md (`out_folder` exists).
inline void write_outputs(const std::string& out_folder, const std::vector<Row>& rows,
                          const std::vector<Robust_row>& robust, const std::string& machine)
{
  const std::filesystem::path out(out_folder);
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
     << "its area (majority_face_patches); without it, the same rule under the unsmoothed boundaries (the face_patch_map of segment_along_features). Every "
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

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_QUALITY_TABLES_H
