// SPDX-License-Identifier: GPL-3.0-or-later
// The oversegmentation's building blocks on an abstract graph (in the package: the dual
// graph of the triangles): multi-source shortest distances with the Boost Graph
// Library's Dijkstra, and the watershed by immersion of Vincent and Soille (1991).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_WATERSHED_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_WATERSHED_H

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// An undirected graph in compressed rows: the neighbours of node i are
// target[begin[i] .. begin[i+1]), with edge lengths in length[].
struct Csr_graph
{
  std::vector<std::size_t> begin;  // size n + 1
  std::vector<std::size_t> target;
  std::vector<double> length;
  std::size_t number_of_nodes() const { return begin.empty() ? 0 : begin.size() - 1; }

  // From an undirected edge list; each edge is stored in both directions.
  static Csr_graph from_edges(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t> >& edges,
                              const std::vector<double>& lengths)
  {
    Csr_graph g;
    g.begin.assign(n + 1, 0);
    for(const auto& e : edges) { ++g.begin[e.first + 1]; ++g.begin[e.second + 1]; }
    for(std::size_t i = 0; i < n; ++i) g.begin[i + 1] += g.begin[i];
    g.target.resize(g.begin[n]);
    g.length.resize(g.begin[n]);
    std::vector<std::size_t> fill(g.begin.begin(), g.begin.end() - 1);
    for(std::size_t k = 0; k < edges.size(); ++k)
    {
      const auto& e = edges[k];
      g.target[fill[e.first]] = e.second; g.length[fill[e.first]++] = lengths[k];
      g.target[fill[e.second]] = e.first; g.length[fill[e.second]++] = lengths[k];
    }
    return g;
  }
};

// Shortest distance from the nearest source to every node (infinity if unreachable),
// by BGL's Dijkstra from a virtual node joined to every source by a zero-length edge.
inline std::vector<double> multi_source_distances(const Csr_graph& g, const std::vector<char>& is_source)
{
  typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property,
                                             boost::property<boost::edge_weight_t, double> > Graph;
  const std::size_t n = g.number_of_nodes();
  std::vector<std::pair<std::size_t, std::size_t> > arcs;
  std::vector<double> w;
  arcs.reserve(g.target.size() + n);
  w.reserve(g.target.size() + n);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = g.begin[i]; k < g.begin[i + 1]; ++k)
    {
      arcs.emplace_back(i, g.target[k]);
      w.push_back(g.length[k]);
    }
  for(std::size_t i = 0; i < n; ++i)
    if(is_source[i]) { arcs.emplace_back(n, i); w.push_back(0.); }
  Graph bg(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(), w.begin(), n + 1);
  std::vector<double> dist(n + 1, 0.);
  boost::dijkstra_shortest_paths(
    bg, std::size_t(n),
    boost::distance_map(boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, bg)))
      .distance_inf((std::numeric_limits<double>::max)()));
  dist.pop_back();
  for(double& d : dist)
    if(d == (std::numeric_limits<double>::max)()) d = std::numeric_limits<double>::infinity();
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
