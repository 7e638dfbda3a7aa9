// SPDX-License-Identifier: GPL-3.0-or-later
// Connected clusters of a graph's nodes grown breadth first, the coarse levels that the
// curvature fits (vertex_clusters.h) and the crease gap search (crease_gap_test.h)
// walk instead of single nodes. Each cluster grows from the first node not yet in a
// cluster, in index order, until it holds `max_size` nodes or runs out of neighbours: the
// same clusters on every run and at any thread count.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_BREADTH_FIRST_CLUSTERS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_BREADTH_FIRST_CLUSTERS_H

#include <CGAL/Feature_segmentation/internal/compact_index.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Breadth_first_clusters
{
  static constexpr std::uint32_t none = std::uint32_t(-1);

  std::vector<std::uint32_t> cluster_of; // per node
  std::vector<std::uint32_t> order;      // the nodes, cluster by cluster, each from its seed
  std::vector<std::uint32_t> first;      // per cluster: its first node in `order`; then order.size()

  std::size_t size() const { return first.size() - 1; }
  std::uint32_t seed(std::size_t c) const { return order[first[c]]; }

  // Clusters of up to `max_size` of the nodes 0 .. n-1; for_each_neighbour(x, f) calls
  // f(y) for every neighbour y of node x (`none` is skipped).
  // \throws std::length_error if n does not fit 32 bits
  template <typename ForEachNeighbour>
  void grow(std::size_t n, std::size_t max_size, ForEachNeighbour for_each_neighbour)
  {
    check_compact_index_range(n); // node ids are kept in 32 bits
    cluster_of.assign(n, none);
    order.clear();
    order.reserve(n);
    first.assign(1, 0);
    for(std::size_t s = 0; s < n; ++s)
    {
      if(cluster_of[s] != none) continue;
      const std::uint32_t c = std::uint32_t(first.size() - 1);
      const std::size_t begin = order.size();
      cluster_of[s] = c;
      order.push_back(std::uint32_t(s));
      for(std::size_t j = begin; j < order.size() && order.size() - begin < max_size; ++j)
        for_each_neighbour(order[j], [&](std::uint32_t y) {
          if(y != none && cluster_of[y] == none && order.size() - begin < max_size)
          {
            cluster_of[y] = c;
            order.push_back(y);
          }
        });
      first.push_back(std::uint32_t(order.size()));
    }
  }
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_BREADTH_FIRST_CLUSTERS_H
