// SPDX-License-Identifier: GPL-3.0-or-later
//
// Compressed adjacency (CSR) of a Correlation_clustering_graph in which parallel edges
// have been summed. Both solvers start from it: they reason about one weight per pair of
// nodes, and a CSR gives them the neighbours of a node in one contiguous range.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_SIMPLE_ADJACENCY_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_SIMPLE_ADJACENCY_H

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// 32-bit node and edge indices halve the memory traffic of the solvers compared to
// std::size_t; Correlation_clustering_graph guarantees that they fit.
typedef std::uint32_t Cc_index;

// Neighbours of node i are neighbors[offsets[i] .. offsets[i+1]), in the order in which
// their first connecting edge appears in the input graph, so that everything built on
// top of it is deterministic.
struct Simple_adjacency
{
  std::vector<std::size_t> offsets;
  std::vector<Cc_index> neighbors;
  std::vector<double> weights;

  std::size_t number_of_nodes() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::size_t begin(std::size_t i) const { return offsets[i]; }
  std::size_t end(std::size_t i) const { return offsets[i + 1]; }
};

inline void build_simple_adjacency(const Correlation_clustering_graph& g, Simple_adjacency& adj)
{
  const std::size_t n = g.number_of_nodes();
  const std::size_t m = g.number_of_edges();

  adj.offsets.assign(n + 1, 0);
  for(std::size_t e = 0; e < m; ++e)
  {
    ++adj.offsets[g.source(e) + 1];
    ++adj.offsets[g.target(e) + 1];
  }
  for(std::size_t i = 0; i < n; ++i)
    adj.offsets[i + 1] += adj.offsets[i];

  adj.neighbors.resize(2 * m);
  adj.weights.resize(2 * m);
  {
    std::vector<std::size_t> cursor(adj.offsets.begin(), adj.offsets.end() - 1);
    for(std::size_t e = 0; e < m; ++e)
    {
      const std::size_t s = g.source(e), t = g.target(e);
      const double w = g.weight(e);
      adj.neighbors[cursor[s]] = Cc_index(t);
      adj.weights[cursor[s]++] = w;
      adj.neighbors[cursor[t]] = Cc_index(s);
      adj.weights[cursor[t]++] = w;
    }
  }

  // Sum parallel edges in place: the write cursor never overtakes the read cursor.
  // seen[j] == i+1 marks that j is already a neighbour of i, at position slot[j].
  std::vector<Cc_index> seen(n, 0);
  std::vector<std::size_t> slot(n);
  std::size_t write = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t read_begin = adj.offsets[i], read_end = adj.offsets[i + 1];
    adj.offsets[i] = write;
    for(std::size_t k = read_begin; k < read_end; ++k)
    {
      const Cc_index j = adj.neighbors[k];
      if(seen[j] == Cc_index(i + 1))
      {
        adj.weights[slot[j]] += adj.weights[k];
      }
      else
      {
        seen[j] = Cc_index(i + 1);
        slot[j] = write;
        adj.neighbors[write] = j;
        adj.weights[write++] = adj.weights[k];
      }
    }
  }
  adj.offsets[n] = write;
  adj.neighbors.resize(write);
  adj.weights.resize(write);
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_SIMPLE_ADJACENCY_H
