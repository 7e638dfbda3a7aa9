// SPDX-License-Identifier: GPL-3.0-or-later
// A debug counter of the passes over the input mesh: how many times a mesh is checked
// (check_input_mesh()) and indexed (Mesh_indexing), so that a test can assert that one
// segmentation checks and indexes its mesh once. Compiled in only with
// CGAL_FEATURE_SEGMENTATION_COUNT_MESH_PASSES defined (for a whole program: the test
// that counts is an executable of its own); otherwise it costs nothing.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_PASS_COUNTS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_PASS_COUNTS_H

#include <cstddef>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Mesh_pass_counts
{
  std::size_t checks = 0;    // calls of check_input_mesh()
  std::size_t indexings = 0; // Mesh_indexing objects built from a mesh (copies not counted)
};

#ifdef CGAL_FEATURE_SEGMENTATION_COUNT_MESH_PASSES
inline Mesh_pass_counts& mesh_pass_counts()
{
  static Mesh_pass_counts counts;
  return counts;
}
#define CGAL_FEATURE_SEGMENTATION_COUNT_PASS(what) (++::CGAL::Feature_segmentation::internal::mesh_pass_counts().what)
#else
#define CGAL_FEATURE_SEGMENTATION_COUNT_PASS(what) ((void)0)
#endif

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_PASS_COUNTS_H
