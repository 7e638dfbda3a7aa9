// SPDX-License-Identifier: GPL-3.0-or-later
//
// The weighted undirected graph on which correlation clustering is solved, together with
// the objective (the cut cost, Eq. 1 of the paper) and the canonical form of a labelling.
// The graph is deliberately independent of any mesh: the segmentation pipeline builds it
// from the dual graph of a mesh or of an oversegmentation, tests and benchmarks build it
// directly. Storage is three contiguous arrays so that solvers can read it without
// pointer chasing.

#ifndef CGAL_FEATURE_SEGMENTATION_CORRELATION_CLUSTERING_GRAPH_H
#define CGAL_FEATURE_SEGMENTATION_CORRELATION_CLUSTERING_GRAPH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/config.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/*!
  \ingroup PkgFeatureSegmentationSolvers

  \brief A weighted undirected graph, the input of every model of `CorrelationClusteringSolver`.

  Nodes are the integers `0, ..., number_of_nodes()-1`; edges are the integers
  `0, ..., number_of_edges()-1` in insertion order. A positive weight `w(e)` means that
  the two endpoints of `e` should be in the same cluster: cutting `e` costs `w(e)`. A
  negative weight means they should be separated: cutting `e` gains `-w(e)`.

  Parallel edges are allowed; every solver treats them as one edge whose weight is the
  sum of their weights (which is also what `cut_cost()` computes, since parallel edges are
  cut together). Self loops are not allowed: they are never cut, so they could only carry
  a meaningless constant.

  Solvers use 32-bit indices internally, hence the number of nodes and the number of edges
  must stay below \f$ 2^{32}-1 \f$.
*/
class Correlation_clustering_graph
{
public:
  /// creates an empty graph with no node.
  Correlation_clustering_graph() = default;

  /// creates a graph with `n` nodes and no edge.
  explicit Correlation_clustering_graph(std::size_t n)
    : m_number_of_nodes(n)
  {
    CGAL_precondition(n < max_index());
  }

  /*!
    creates a graph with `n` nodes and the edges `edges[i]` of weight `weights[i]`.

    \pre `edges.size() == weights.size()`
    \pre every endpoint is smaller than `n`, and no edge is a self loop.
  */
  Correlation_clustering_graph(std::size_t n,
                               const std::vector<std::pair<std::size_t, std::size_t> >& edges,
                               const std::vector<double>& weights)
    : m_number_of_nodes(n)
  {
    CGAL_precondition(n < max_index());
    CGAL_precondition(edges.size() == weights.size());
    reserve_edges(edges.size());
    for(std::size_t i = 0; i < edges.size(); ++i)
      add_edge(edges[i].first, edges[i].second, weights[i]);
  }

  /// adds a node and returns its index.
  std::size_t add_node()
  {
    CGAL_precondition(m_number_of_nodes + 1 < max_index());
    return m_number_of_nodes++;
  }

  /// reserves memory for `m` edges in total, to avoid reallocations in `add_edge()`.
  void reserve_edges(std::size_t m)
  {
    m_sources.reserve(m);
    m_targets.reserve(m);
    m_weights.reserve(m);
  }

  /*!
    adds the edge `{s, t}` with weight `w` and returns its index.

    \pre `s < number_of_nodes()`, `t < number_of_nodes()`, and `s != t`.
  */
  std::size_t add_edge(std::size_t s, std::size_t t, double w)
  {
    CGAL_precondition(s < m_number_of_nodes);
    CGAL_precondition(t < m_number_of_nodes);
    CGAL_precondition(s != t);
    CGAL_precondition(m_sources.size() + 1 < max_index());
    m_sources.push_back(s);
    m_targets.push_back(t);
    m_weights.push_back(w);
    return m_sources.size() - 1;
  }

  /// returns the number of nodes.
  std::size_t number_of_nodes() const { return m_number_of_nodes; }

  /// returns the number of edges, parallel edges counted separately.
  std::size_t number_of_edges() const { return m_sources.size(); }

  /// returns the first endpoint of edge `i`. \pre `i < number_of_edges()`
  std::size_t source(std::size_t i) const
  {
    CGAL_precondition(i < m_sources.size());
    return m_sources[i];
  }

  /// returns the second endpoint of edge `i`. \pre `i < number_of_edges()`
  std::size_t target(std::size_t i) const
  {
    CGAL_precondition(i < m_targets.size());
    return m_targets[i];
  }

  /// returns the weight of edge `i`. \pre `i < number_of_edges()`
  double weight(std::size_t i) const
  {
    CGAL_precondition(i < m_weights.size());
    return m_weights[i];
  }

  /// sets the weight of edge `i` to `w`, e.g.\ to re-solve after a parameter edit.
  /// \pre `i < number_of_edges()`
  void set_weight(std::size_t i, double w)
  {
    CGAL_precondition(i < m_weights.size());
    m_weights[i] = w;
  }

private:
  // Solvers store indices on 32 bits; the largest value is kept free as a sentinel.
  static std::size_t max_index() { return std::size_t((std::numeric_limits<unsigned int>::max)()); }

  std::size_t m_number_of_nodes = 0;
  std::vector<std::size_t> m_sources;
  std::vector<std::size_t> m_targets;
  std::vector<double> m_weights;
};

/*!
  \ingroup PkgFeatureSegmentationSolvers

  \brief returns the cut cost of `labels` on `g` (Eq. 1 of the paper): the sum of the
  weights of the edges whose endpoints have different labels.

  This is the objective that every model of `CorrelationClusteringSolver` minimises.

  \pre `labels.size() == g.number_of_nodes()`
*/
inline double cut_cost(const Correlation_clustering_graph& g,
                       const std::vector<std::size_t>& labels)
{
  CGAL_precondition(labels.size() == g.number_of_nodes());
  double cost = 0.;
  for(std::size_t i = 0; i < g.number_of_edges(); ++i)
    if(labels[g.source(i)] != labels[g.target(i)])
      cost += g.weight(i);
  return cost;
}

/*!
  \ingroup PkgFeatureSegmentationSolvers

  \brief relabels `labels` to `0, ..., k-1` in order of first appearance and returns `k`.

  Two labellings describe the same partition if and only if they are equal after this
  call, which makes solver outputs comparable and deterministic whatever label values
  the solver used internally.

  \param labels arbitrary label values, modified in place.
  \return the number of distinct labels.
*/
inline std::size_t normalize_labels(std::vector<std::size_t>& labels)
{
  const std::size_t unassigned = (std::numeric_limits<std::size_t>::max)();
  std::size_t max_label = 0;
  for(std::size_t l : labels)
    max_label = (std::max)(max_label, l);

  std::size_t k = 0;
  // A dense table when label values are small (the usual case), a hash table otherwise;
  // both are only queried, never iterated, so the result does not depend on hashing.
  if(max_label < 4 * labels.size() + 16)
  {
    std::vector<std::size_t> new_label(max_label + 1, unassigned);
    for(std::size_t& l : labels)
    {
      if(new_label[l] == unassigned)
        new_label[l] = k++;
      l = new_label[l];
    }
  }
  else
  {
    std::unordered_map<std::size_t, std::size_t> new_label;
    new_label.reserve(labels.size());
    for(std::size_t& l : labels)
    {
      auto inserted = new_label.emplace(l, k);
      if(inserted.second)
        ++k;
      l = inserted.first->second;
    }
  }
  return k;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_CORRELATION_CLUSTERING_GRAPH_H
