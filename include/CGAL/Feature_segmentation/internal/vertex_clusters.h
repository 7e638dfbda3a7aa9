// SPDX-License-Identifier: GPL-3.0-or-later
// Connected clusters of the vertices of a fine mesh and the graph between them, over
// which the curvature fits find their neighbours when the neighbourhood radius spans
// many rings (curvature_fitting.h).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_VERTEX_CLUSTERS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_VERTEX_CLUSTERS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Vertex_clusters
{
  std::vector<std::uint32_t> cluster_of;     // per vertex
  std::vector<std::size_t> representative;   // per cluster: the vertex it grew from
  std::vector<std::size_t> neighbour_begin;  // CSR over `neighbours`
  std::vector<std::uint32_t> neighbours;     // the clusters sharing an edge with each cluster

  std::size_t size() const { return representative.size(); }

  // Clusters of up to `size` vertices, each grown breadth first over the graph
  // (adj_begin, adj: CSR of the vertices' neighbours) from the first vertex not yet in a
  // cluster, in index order: the same clusters on every run and at any thread count.
  void build(const std::vector<std::size_t>& adj_begin, const std::vector<std::size_t>& adj, std::size_t size)
  {
    const std::size_t nv = adj_begin.size() - 1;
    const std::uint32_t none = std::uint32_t(-1);
    cluster_of.assign(nv, none);
    representative.clear();
    std::vector<std::size_t> queue;
    for(std::size_t seed = 0; seed < nv; ++seed)
    {
      if(cluster_of[seed] != none) continue;
      const std::uint32_t c = std::uint32_t(representative.size());
      representative.push_back(seed);
      cluster_of[seed] = c;
      queue.assign(1, seed);
      for(std::size_t j = 0; j < queue.size() && queue.size() < size; ++j)
        for(std::size_t k = adj_begin[queue[j]]; k < adj_begin[queue[j] + 1] && queue.size() < size; ++k)
          if(cluster_of[adj[k]] == none) { cluster_of[adj[k]] = c; queue.push_back(adj[k]); }
    }
    // the graph: the distinct clusters across the vertices' edges, in increasing order
    const std::size_t nc = representative.size();
    std::vector<std::vector<std::uint32_t> > around(nc);
    for(std::size_t v = 0; v < nv; ++v)
      for(std::size_t k = adj_begin[v]; k < adj_begin[v + 1]; ++k)
        if(cluster_of[adj[k]] != cluster_of[v]) around[cluster_of[v]].push_back(cluster_of[adj[k]]);
    neighbour_begin.assign(nc + 1, 0);
    neighbours.clear();
    for(std::size_t c = 0; c < nc; ++c)
    {
      std::sort(around[c].begin(), around[c].end());
      around[c].erase(std::unique(around[c].begin(), around[c].end()), around[c].end());
      neighbours.insert(neighbours.end(), around[c].begin(), around[c].end());
      neighbour_begin[c + 1] = neighbours.size();
    }
  }
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_VERTEX_CLUSTERS_H
