// SPDX-License-Identifier: GPL-3.0-or-later
// A loop over the indices 0 .. n-1 in ranges, run by TBB's threads when asked for and
// available (CGAL_LINKED_WITH_TBB), else in one range on the calling thread. For loops
// whose iterations write distinct elements: the result is the same at any thread count.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_PARALLEL_FOR_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_PARALLEL_FOR_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// Calls body(first, last) on ranges that cover 0 .. n-1 once, each of about `grain`
// indices or more when `parallel`.
template <typename Body>
void for_each_range(std::size_t n, bool parallel, std::size_t grain, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && n > grain)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    return;
  }
#endif
  (void)parallel;
  (void)grain;
  body(std::size_t(0), n);
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_PARALLEL_FOR_H
