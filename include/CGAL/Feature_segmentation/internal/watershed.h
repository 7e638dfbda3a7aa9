// SPDX-License-Identifier: GPL-3.0-or-later
// The oversegmentation's building blocks on an abstract graph (in the package: the dual
// graph of the triangles): multi-source shortest distances with the Boost Graph
// Library's Dijkstra, and the watershed by immersion of Vincent and Soille (1991).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_WATERSHED_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_WATERSHED_H

#include <CGAL/Feature_segmentation/internal/compact_index.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/iterator/iterator_facade.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <deque>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// An undirected graph in compressed rows: the neighbours of node i are
// target[begin[i] .. begin[i+1]), with edge lengths in length[]. Ids in 32 bits.
struct Csr_graph
{
  std::vector<Compact_index> begin;  // size n + 1
  std::vector<Compact_index> target;
  std::vector<double> length;
  std::size_t number_of_nodes() const { return begin.empty() ? 0 : begin.size() - 1; }

  // From an undirected edge list (pairs of node ids); each edge is stored in both
  // directions.
  template <typename EdgeList>
  static Csr_graph from_edges(std::size_t n, const EdgeList& edges, const std::vector<double>& lengths)
  {
    check_compact_index_range(std::max(n + 1, 2 * edges.size()));
    Csr_graph g;
    std::vector<std::size_t> fill(n + 1, 0);
    for(const auto& e : edges) { ++fill[std::size_t(e.first) + 1]; ++fill[std::size_t(e.second) + 1]; }
    for(std::size_t i = 0; i < n; ++i) fill[i + 1] += fill[i];
    g.begin.assign(fill.begin(), fill.end());
    g.target.resize(fill[n]);
    g.length.resize(fill[n]);
    for(std::size_t k = 0; k < edges.size(); ++k)
    {
      const std::size_t a = edges[k].first, b = edges[k].second;
      g.target[fill[a]] = b; g.length[fill[a]++] = lengths[k];
      g.target[fill[b]] = a; g.length[fill[b]++] = lengths[k];
    }
    return g;
  }
};

// The arcs (source, target) of a Csr_graph in their order, which is sorted by source:
// what BGL's compressed_sparse_row_graph is built from, without a copy of the list.
class Csr_arc_iterator
  : public boost::iterator_facade<Csr_arc_iterator, std::pair<std::uint32_t, std::uint32_t>,
                                  boost::forward_traversal_tag, std::pair<std::uint32_t, std::uint32_t> >
{
public:
  Csr_arc_iterator() = default;
  Csr_arc_iterator(const Csr_graph& g, std::size_t k) : m_g(&g), m_k(k) { skip(); }

private:
  friend class boost::iterator_core_access;
  void skip()
  {
    while(m_node + 1 < m_g->begin.size() && m_k >= std::size_t(m_g->begin[m_node + 1])) ++m_node;
  }
  void increment() { ++m_k; skip(); }
  bool equal(const Csr_arc_iterator& o) const { return m_k == o.m_k; }
  std::pair<std::uint32_t, std::uint32_t> dereference() const
  {
    return { std::uint32_t(m_node), std::uint32_t(std::size_t(m_g->target[m_k])) };
  }

  const Csr_graph* m_g = nullptr;
  std::size_t m_k = 0, m_node = 0;
};

// Shortest distance from the nearest source to every node (infinity if unreachable),
// by BGL's multi-source Dijkstra.
inline std::vector<double> multi_source_distances(const Csr_graph& g, const std::vector<char>& is_source)
{
  typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property,
                                             boost::property<boost::edge_weight_t, double>, boost::no_property,
                                             std::uint32_t, std::uint32_t> Graph;
  typedef boost::graph_traits<Graph>::vertex_descriptor Vertex;
  const std::size_t n = g.number_of_nodes();
  std::vector<double> dist(n, 0.);
  if(n == 0) return dist;
  const Graph bg(boost::edges_are_sorted, Csr_arc_iterator(g, 0), Csr_arc_iterator(g, g.target.size()),
                 g.length.begin(), Graph::vertices_size_type(n), Graph::edges_size_type(g.target.size()));
  std::vector<Vertex> sources;
  for(std::size_t i = 0; i < n; ++i) if(is_source[i]) sources.push_back(Vertex(i));
  const double inf = (std::numeric_limits<double>::max)();
  boost::dijkstra_shortest_paths(bg, sources.begin(), sources.end(), boost::dummy_property_map(),
                                 boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, bg)),
                                 get(boost::edge_weight, bg), get(boost::vertex_index, bg), std::less<double>(),
                                 boost::closed_plus<double>(inf), inf, 0., boost::default_dijkstra_visitor());
  for(double& d : dist)
    if(d == inf) d = std::numeric_limits<double>::infinity();
  return dist;
}

// Label of a node on the watershed (a dam between two basins).
constexpr long watershed_label = -1;

// Vincent-Soille immersion: nodes are sorted by height and flooded level by level from
// the minima; at each level the nodes reached from labelled neighbours are processed in
// order of their distance to them (FIFO, so a plateau is split at its geodesic middle),
// a node reached from two basins becomes watershed, and what is not reached starts a new
// basin (a new minimum). Basins are numbered 0, 1, ... in order of creation, which is
// deterministic: ties in height are ordered by node index.
inline std::vector<long> immersion_watershed(const Csr_graph& g, const std::vector<double>& height,
                                             std::size_t* number_of_basins = nullptr)
{
  const std::size_t n = g.number_of_nodes();
  constexpr long INIT = -3, MASK = -2, WSHED = watershed_label;
  std::vector<long> lab(n, INIT);
  std::vector<std::size_t> dist(n, 0);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return height[a] < height[b]; });
  long current = -1;
  const std::size_t fictitious = n;
  std::deque<std::size_t> fifo;
  for(std::size_t lo = 0; lo < n;)
  {
    std::size_t hi = lo;
    while(hi < n && height[order[hi]] == height[order[lo]]) ++hi;
    // mask the level; queue the nodes next to an already labelled node
    for(std::size_t i = lo; i < hi; ++i)
    {
      const std::size_t p = order[i];
      lab[p] = MASK;
      for(std::size_t k = g.begin[p]; k < g.begin[p + 1]; ++k)
      {
        const long lq = lab[g.target[k]];
        if(lq >= 0 || lq == WSHED) { dist[p] = 1; fifo.push_back(p); break; }
      }
    }
    std::size_t curdist = 1;
    fifo.push_back(fictitious);
    for(;;)
    {
      std::size_t p = fifo.front();
      fifo.pop_front();
      if(p == fictitious)
      {
        if(fifo.empty()) break;
        fifo.push_back(fictitious);
        ++curdist;
        p = fifo.front();
        fifo.pop_front();
      }
      for(std::size_t k = g.begin[p]; k < g.begin[p + 1]; ++k)
      {
        const std::size_t q = g.target[k];
        if(dist[q] < curdist && (lab[q] >= 0 || lab[q] == WSHED))
        {
          if(lab[q] >= 0)
          {
            if(lab[p] == MASK || lab[p] == WSHED) lab[p] = lab[q];
            else if(lab[p] != lab[q]) lab[p] = WSHED;
          }
          else if(lab[p] == MASK)
            lab[p] = WSHED;
        }
        else if(lab[q] == MASK && dist[q] == 0)
        {
          dist[q] = curdist + 1;
          fifo.push_back(q);
        }
      }
    }
    // new minima: what the flood did not reach
    for(std::size_t i = lo; i < hi; ++i)
    {
      const std::size_t p = order[i];
      dist[p] = 0;
      if(lab[p] != MASK) continue;
      lab[p] = ++current;
      fifo.push_back(p);
      while(!fifo.empty())
      {
        const std::size_t q = fifo.front();
        fifo.pop_front();
        for(std::size_t k = g.begin[q]; k < g.begin[q + 1]; ++k)
          if(lab[g.target[k]] == MASK) { lab[g.target[k]] = current; fifo.push_back(g.target[k]); }
      }
    }
    lo = hi;
  }
  if(number_of_basins != nullptr) *number_of_basins = std::size_t(current + 1);
  return lab;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_WATERSHED_H
