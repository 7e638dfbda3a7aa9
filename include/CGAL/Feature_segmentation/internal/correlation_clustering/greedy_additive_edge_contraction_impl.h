// SPDX-License-Identifier: GPL-3.0-or-later
//
// The work behind Greedy_additive_edge_contraction: a graph that supports contracting an
// edge in time proportional to the smaller of the two merged neighbourhoods, plus the
// greedy loop that contracts the heaviest positive edge until none is left.
//
// Data layout: every node owns a slice of one shared pool of (neighbour, edge) entries,
// and every edge remembers its position in the slices of both endpoints, so removing an
// entry is a swap with the last entry of the slice. A full slice is moved to the end of
// the pool with doubled capacity, so nothing is allocated per edge. Nodes whose slice
// grows beyond a small threshold also get a Neighbor_index, so that the common neighbours
// of two merged clusters are found in time proportional to the smaller neighbourhood.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_GREEDY_ADDITIVE_EDGE_CONTRACTION_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_GREEDY_ADDITIVE_EDGE_CONTRACTION_IMPL_H

#include <CGAL/assertions.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Lazy_max_heap.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Neighbor_index.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Simple_adjacency.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Greedy_additive_edge_contraction_impl
{
public:
  // Writes in `labels` the representative node of the cluster of every node (not
  // normalised).
  void run(const Simple_adjacency& adj, std::vector<std::size_t>& labels)
  {
    initialize(adj);

    Lazy_max_heap::Entry top;
    while(m_heap.pop(top))
    {
      // Only positive weights are ever pushed, and a weight update bumps the version.
      CGAL_assertion(top.priority > 0.);
      contract(top.item);
    }

    const std::size_t n = m_lists.size();
    labels.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      labels[i] = find_root(Cc_index(i));
  }

private:
  struct Entry
  {
    Cc_index neighbor;
    Cc_index edge;
  };

  struct Edge
  {
    Cc_index end[2];
    Cc_index pos[2]; // position of this edge in the slice of end[k]
  };

  struct Slice
  {
    std::size_t begin;
    Cc_index size;
    Cc_index capacity;
  };

  void initialize(const Simple_adjacency& adj)
  {
    const std::size_t n = adj.number_of_nodes();
    m_lists.resize(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t degree = adj.end(i) - adj.begin(i);
      m_lists[i] = Slice{adj.begin(i), 0, Cc_index(degree)};
    }
    // Room for growth, so that the first relocations do not reallocate the pool.
    m_pool.reserve(adj.neighbors.size() + adj.neighbors.size() / 2 + 16);
    m_pool.resize(adj.neighbors.size());

    m_edges.clear();
    m_edges.reserve(adj.neighbors.size() / 2);
    m_weights.clear();
    m_weights.reserve(adj.neighbors.size() / 2);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t k = adj.begin(i); k < adj.end(i); ++k)
      {
        const Cc_index j = adj.neighbors[k];
        if(j < i)
          continue;
        const Cc_index e = Cc_index(m_edges.size());
        Edge edge;
        edge.end[0] = Cc_index(i);
        edge.end[1] = j;
        edge.pos[0] = push_initial(Cc_index(i), Entry{j, e});
        edge.pos[1] = push_initial(j, Entry{Cc_index(i), e});
        m_edges.push_back(edge);
        m_weights.push_back(adj.weights[k]);
      }

    m_heap.reset(m_edges.size());
    for(std::size_t e = 0; e < m_edges.size(); ++e)
      if(m_weights[e] > 0.)
        m_heap.append_initial(Cc_index(e), m_weights[e]);
    m_heap.sort_initial();

    m_parent.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      m_parent[i] = Cc_index(i);
    m_index_of.assign(n, no_index());
    m_indices.clear();
    m_mark.assign(n, 0);
    m_mark_edge.resize(n);
    m_time = 0;
  }

  Cc_index push_initial(Cc_index node, const Entry& entry)
  {
    Slice& s = m_lists[node];
    m_pool[s.begin + s.size] = entry;
    return s.size++;
  }

  static int side(const Edge& edge, Cc_index node) { return edge.end[0] == node ? 0 : 1; }

  Cc_index append(Cc_index node, const Entry& entry)
  {
    Slice& s = m_lists[node];
    if(s.size == s.capacity)
    {
      const Cc_index capacity = (std::max)(Cc_index(4), Cc_index(2 * s.capacity));
      const std::size_t begin = m_pool.size();
      m_pool.resize(begin + capacity);
      std::copy(m_pool.begin() + s.begin, m_pool.begin() + s.begin + s.size,
                m_pool.begin() + begin);
      s.begin = begin;
      s.capacity = capacity;
    }
    const Cc_index pos = s.size++;
    m_pool[s.begin + pos] = entry;
    if(m_index_of[node] != no_index())
      m_indices[m_index_of[node]].assign(entry.neighbor, pos);
    else if(s.size > index_threshold())
      build_index(node);
    return pos;
  }

  void build_index(Cc_index node)
  {
    const Slice& s = m_lists[node];
    m_index_of[node] = Cc_index(m_indices.size());
    m_indices.emplace_back();
    Neighbor_index& index = m_indices.back();
    index.reset(2 * s.size);
    for(Cc_index k = 0; k < s.size; ++k)
      index.assign(m_pool[s.begin + k].neighbor, k);
  }

  void remove(Cc_index node, Cc_index pos)
  {
    Slice& s = m_lists[node];
    const Cc_index last = s.size - 1;
    const Cc_index index = m_index_of[node];
    if(index != no_index())
      m_indices[index].erase(m_pool[s.begin + pos].neighbor);
    if(pos != last)
    {
      const Entry moved = m_pool[s.begin + last];
      m_pool[s.begin + pos] = moved;
      Edge& edge = m_edges[moved.edge];
      edge.pos[side(edge, node)] = pos;
      if(index != no_index())
        m_indices[index].assign(moved.neighbor, pos);
    }
    --s.size;
  }

  // The entry of `node` at `pos` now leads to `neighbor` (same edge).
  void rename(Cc_index node, Cc_index pos, Cc_index neighbor)
  {
    Entry& entry = m_pool[m_lists[node].begin + pos];
    const Cc_index index = m_index_of[node];
    if(index != no_index())
    {
      m_indices[index].erase(entry.neighbor);
      m_indices[index].assign(neighbor, pos);
    }
    entry.neighbor = neighbor;
  }

  // Contracts edge e: the endpoint with the shorter slice (v) is merged into the other (u).
  void contract(Cc_index e)
  {
    const Edge contracted = m_edges[e];
    int keep = m_lists[contracted.end[0]].size >= m_lists[contracted.end[1]].size ? 0 : 1;
    const Cc_index u = contracted.end[keep], v = contracted.end[1 - keep];
    m_heap.invalidate(e);
    remove(u, contracted.pos[keep]);
    m_parent[v] = u;

    // The common neighbours of u and v are found by looking them up in the index of u if
    // u has one, else by marking the neighbours of u (fewer than the index threshold) or
    // by scanning the slice of every neighbour of v, whichever is cheaper.
    const Slice sv = m_lists[v];
    const Cc_index u_index = m_index_of[u];
    bool marking = false;
    if(u_index == no_index())
    {
      const std::size_t cost_marking = m_lists[u].size;
      std::size_t cost_scanning = 0;
      for(Cc_index k = 0; k < sv.size && cost_scanning <= cost_marking; ++k)
        cost_scanning += m_lists[m_pool[sv.begin + k].neighbor].size;
      marking = cost_scanning > cost_marking;
    }
    if(marking)
    {
      ++m_time;
      const Slice su = m_lists[u];
      for(Cc_index k = 0; k < su.size; ++k)
      {
        const Entry& entry = m_pool[su.begin + k];
        m_mark[entry.neighbor] = m_time;
        m_mark_edge[entry.neighbor] = entry.edge;
      }
    }

    for(Cc_index k = 0; k < sv.size; ++k)
    {
      const Entry entry = m_pool[sv.begin + k];
      if(entry.edge == e)
        continue;
      const Cc_index c = entry.neighbor;
      const Cc_index f = entry.edge;

      Cc_index common = no_edge();
      if(u_index != no_index())
      {
        const Cc_index pos = m_indices[u_index].find(c);
        if(pos != Neighbor_index::not_found())
          common = m_pool[m_lists[u].begin + pos].edge;
      }
      else if(marking)
      {
        if(m_mark[c] == m_time)
          common = m_mark_edge[c];
      }
      else
      {
        const Slice sc = m_lists[c];
        for(Cc_index j = 0; j < sc.size; ++j)
          if(m_pool[sc.begin + j].neighbor == u)
          {
            common = m_pool[sc.begin + j].edge;
            break;
          }
      }

      Edge& edge = m_edges[f];
      const int c_side = side(edge, c);
      if(common != no_edge())
      {
        // Parallel edges after contraction: sum them into the edge already at u.
        m_weights[common] += m_weights[f];
        if(m_weights[common] > 0.)
          m_heap.update(common, m_weights[common]);
        else
          m_heap.invalidate(common);
        m_heap.invalidate(f);
        remove(c, edge.pos[c_side]);
      }
      else
      {
        // Redirect f from v to u; its weight, hence its heap entry, stays valid.
        rename(c, edge.pos[c_side], u);
        edge.end[1 - c_side] = u;
        edge.pos[1 - c_side] = append(u, Entry{c, f});
      }
    }
    m_lists[v].size = 0;
    if(m_index_of[v] != no_index())
      m_indices[m_index_of[v]].release();
  }

  Cc_index find_root(Cc_index i)
  {
    Cc_index root = i;
    while(m_parent[root] != root)
      root = m_parent[root];
    while(m_parent[i] != root)
    {
      const Cc_index next = m_parent[i];
      m_parent[i] = root;
      i = next;
    }
    return root;
  }

  static Cc_index no_edge() { return Cc_index(-1); }
  static Cc_index no_index() { return Cc_index(-1); }
  // Below this degree, scanning a slice is faster than hashing.
  static Cc_index index_threshold() { return 32; }

  std::vector<Entry> m_pool;
  std::vector<Slice> m_lists;
  std::vector<Edge> m_edges;
  std::vector<double> m_weights;
  std::vector<Cc_index> m_index_of;
  std::vector<Neighbor_index> m_indices;
  Lazy_max_heap m_heap;
  std::vector<Cc_index> m_parent;
  std::vector<Cc_index> m_mark;
  std::vector<Cc_index> m_mark_edge;
  Cc_index m_time = 0;
};

// GAEC on `g`: fills `adj` (for a solver that goes on from the result on the same
// adjacency) and `labels`, normalised; returns the number of clusters.
inline std::size_t greedy_additive_edge_contraction(const Correlation_clustering_graph& g, Simple_adjacency& adj,
                                                    std::vector<std::size_t>& labels)
{
  build_simple_adjacency(g, adj);
  Greedy_additive_edge_contraction_impl().run(adj, labels);
  return normalize_labels(labels);
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_GREEDY_ADDITIVE_EDGE_CONTRACTION_IMPL_H
