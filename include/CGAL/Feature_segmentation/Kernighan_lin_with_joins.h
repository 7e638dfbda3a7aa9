// SPDX-License-Identifier: GPL-3.0-or-later
//
// Kernighan-Lin with joins (KLj), the model of CorrelationClusteringSolver that improves a
// given partition by local moves. It is the second stage of
// Default_correlation_clustering_solver and the solver to use when re-solving from a
// previous result, e.g. after the user edited a weight parameter. The move sequences
// live in internal/correlation_clustering/.

#ifndef CGAL_FEATURE_SEGMENTATION_KERNIGHAN_LIN_WITH_JOINS_H
#define CGAL_FEATURE_SEGMENTATION_KERNIGHAN_LIN_WITH_JOINS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Simple_adjacency.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/kernighan_lin_with_joins_impl.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/*!
  \ingroup PkgFeatureSegmentationSolvers

  \brief Kernighan-Lin with joins, after Keuper et al., "Efficient decomposition of image
  and mesh graphs by lifted multicuts", ICCV 2015.

  The solver improves an initial partition in rounds. In each round, for every pair of
  adjacent clusters, it runs a Kernighan-Lin sequence: starting from the nodes on the
  common boundary, it repeatedly moves the node whose move between the two clusters
  decreases the cut cost most (or increases it least), each node at most once, and keeps
  the best prefix of the sequence. It compares this with joining the two clusters and
  applies the better of the two if it decreases the cut cost by more than `epsilon()`.
  A sequence stops early after `moves_without_improvement()` moves that did not improve
  its best prefix; without this bound, a cluster covering most of the graph would be
  swept entirely for each of its neighbours.
  Then, for every cluster, it runs the same kind of sequence towards a new, empty
  cluster, which is how new clusters appear. Clusters that a move disconnected are split
  into their connected components. A round only revisits pairs of clusters of which at
  least one changed in the previous round. The solver stops after a round that improved
  the cut cost by at most `epsilon()`, or after `number_of_iterations()` rounds.

  With `set_parallel(true)` and TBB, the pairs of a round are improved by TBB's threads:
  two pairs without a common cluster do not see each other's moves, and each pair runs
  after the earlier pairs that share a cluster with it, so that the result is that of
  one thread, at any thread count.

  Every applied change decreases the cut cost, and the solver checks the final cost
  against the initial one, so the result is never worse than the initial partition.
  Without an initial partition it starts from singletons, which gives acceptable but
  slower results than starting from `Greedy_additive_edge_contraction`
  (see `Default_correlation_clustering_solver`). Ties are broken by node index, so the
  result is deterministic.

  \cgalModels{CorrelationClusteringSolver}
*/
class Kernighan_lin_with_joins
{
public:
  /*!
    creates the solver.

    \param number_of_iterations the maximal number of rounds.
    \param epsilon the smallest decrease of the cut cost that counts as an improvement;
           it keeps rounding errors from being taken for improvements.
    \param moves_without_improvement the number of consecutive moves that do not improve
           the best prefix after which a move sequence stops (at least 1).
  */
  explicit Kernighan_lin_with_joins(std::size_t number_of_iterations = 100,
                                    double epsilon = 1e-9,
                                    std::size_t moves_without_improvement = 100)
    : m_number_of_iterations(number_of_iterations), m_epsilon(epsilon),
      m_moves_without_improvement(moves_without_improvement)
  {}

  /// returns the maximal number of rounds.
  std::size_t number_of_iterations() const { return m_number_of_iterations; }
  /// sets the maximal number of rounds.
  void set_number_of_iterations(std::size_t n) { m_number_of_iterations = n; }
  /// returns the smallest decrease of the cut cost that counts as an improvement.
  double epsilon() const { return m_epsilon; }
  /// sets the smallest decrease of the cut cost that counts as an improvement.
  void set_epsilon(double epsilon) { m_epsilon = epsilon; }
  /// returns the number of non-improving moves after which a move sequence stops.
  std::size_t moves_without_improvement() const { return m_moves_without_improvement; }
  /// sets the number of non-improving moves after which a move sequence stops.
  void set_moves_without_improvement(std::size_t n) { m_moves_without_improvement = n; }
  /// returns whether the pairs of a round are improved by TBB's threads (default: no).
  bool parallel() const { return m_parallel; }
  /// sets whether the pairs of a round are improved by TBB's threads (the same result;
  /// without TBB, one thread).
  void set_parallel(bool parallel) { m_parallel = parallel; }

  /*!
    improves the partition `labels` of `g`.

    \param g the graph.
    \param labels on entry, either empty (start from singletons) or an initial partition
           with arbitrary label values; on exit, a partition whose cut cost is at most
           that of the initial one, normalised as by `normalize_labels()`.
    \return the number of clusters.

    \pre `labels.empty() || labels.size() == g.number_of_nodes()`
  */
  std::size_t operator()(const Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    CGAL_precondition(labels.empty() || labels.size() == g.number_of_nodes());
    if(labels.size() != g.number_of_nodes())
    {
      labels.resize(g.number_of_nodes());
      for(std::size_t i = 0; i < labels.size(); ++i)
        labels[i] = i;
    }
    normalize_labels(labels);

    internal::Simple_adjacency adj;
    internal::build_simple_adjacency(g, adj);
    internal::Kernighan_lin_with_joins_impl impl(m_number_of_iterations, m_epsilon,
                                                 m_moves_without_improvement, m_parallel);
    impl.run(adj, labels);
    return normalize_labels(labels);
  }

private:
  std::size_t m_number_of_iterations;
  double m_epsilon;
  std::size_t m_moves_without_improvement;
  bool m_parallel = false;
};

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_KERNIGHAN_LIN_WITH_JOINS_H
