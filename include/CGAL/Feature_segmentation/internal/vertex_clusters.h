// SPDX-License-Identifier: GPL-3.0-or-later
// Connected clusters of the vertices of a fine mesh and the graph between them, over
// which the curvature fits find their neighbours when the neighbourhood radius spans
// many rings (curvature_fitting.h).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_VERTEX_CLUSTERS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_VERTEX_CLUSTERS_H

#include <CGAL/Feature_segmentation/internal/breadth_first_clusters.h>

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
  template <typename Neighbour>
  void build(const std::vector<std::size_t>& adj_begin, const std::vector<Neighbour>& adj, std::size_t size)
  {
    const std::size_t nv = adj_begin.size() - 1;
    {
      Breadth_first_clusters grown;
      grown.grow(nv, size, [&](std::uint32_t x, const auto& visit) {
        for(std::size_t k = adj_begin[x]; k < adj_begin[x + 1]; ++k) visit(std::uint32_t(adj[k]));
      });
      cluster_of.swap(grown.cluster_of);
      representative.resize(grown.size());
      for(std::size_t c = 0; c < grown.size(); ++c) representative[c] = grown.seed(c);
    }
    // the graph: the distinct clusters across the vertices' edges, in increasing order;
    // counted, filled, then each cluster's run sorted and compacted in place
    const std::size_t nc = representative.size();
    std::vector<std::size_t> begin(nc + 1, 0);
    for(std::size_t v = 0; v < nv; ++v)
      for(std::size_t k = adj_begin[v]; k < adj_begin[v + 1]; ++k)
        if(cluster_of[adj[k]] != cluster_of[v]) ++begin[cluster_of[v] + 1];
    for(std::size_t c = 0; c < nc; ++c) begin[c + 1] += begin[c];
    neighbours.resize(begin[nc]);
    {
      std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
      for(std::size_t v = 0; v < nv; ++v)
        for(std::size_t k = adj_begin[v]; k < adj_begin[v + 1]; ++k)
          if(cluster_of[adj[k]] != cluster_of[v]) neighbours[fill[cluster_of[v]]++] = cluster_of[adj[k]];
    }
    neighbour_begin.assign(nc + 1, 0);
    std::size_t out = 0;
    for(std::size_t c = 0; c < nc; ++c)
    {
      auto first = neighbours.begin() + std::ptrdiff_t(begin[c]), last = neighbours.begin() + std::ptrdiff_t(begin[c + 1]);
      std::sort(first, last);
      last = std::unique(first, last);
      // moved down to `out` (std::copy allows the overlap: its destination starts before
      // the run, never inside it); a run already at `out` stays
      if(out != begin[c]) std::copy(first, last, neighbours.begin() + std::ptrdiff_t(out));
      out += std::size_t(last - first);
      neighbour_begin[c + 1] = out;
    }
    neighbours.resize(out);
    neighbours.shrink_to_fit();
  }
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_VERTEX_CLUSTERS_H
