// SPDX-License-Identifier: GPL-3.0-or-later
// The seconds of each stage of a segmentation and of its last edit (wall clock), which
// the editing class reports for benchmarks and programs.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_STAGE_TIMES_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_STAGE_TIMES_H

#include <chrono>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Stage_times
{
  // construction
  double mesh_check_and_indexing = 0; // check_input_mesh() and the indexing of the input
  double creases = 0;                 // crease detection, the cut copy and its indexing
  double curvature = 0;               // the principal curvatures (0 when given)
  double feature_lines = 0;           // crest lines and feature edges
  double weight_terms = 0;            // metrics, dual vertices, Similarity and Award
  double oversegmentation = 0;        // the watershed and G' (of the construction or last sketch)
  // the last solve (construction or edit)
  double graph = 0;                   // the weights of the graph solved (G' or G)
  double solve = 0;                   // the correlation clustering solver
  double labels = 0;                  // the patch ids of the oversegments from the clusters
  double last_edit = 0;               // the whole last edit, all its stages (0 before any edit)
};

// Adds the seconds since its construction to `*target` when destroyed (null: nothing).
class Stage_timer
{
public:
  explicit Stage_timer(double* target) : m_target(target), m_start(std::chrono::steady_clock::now()) {}
  ~Stage_timer()
  {
    if(m_target != nullptr) *m_target += std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }
  Stage_timer(const Stage_timer&) = delete;
  Stage_timer& operator=(const Stage_timer&) = delete;

private:
  double* m_target;
  std::chrono::steady_clock::time_point m_start;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_STAGE_TIMES_H
