// SPDX-License-Identifier: GPL-3.0-or-later
//
// Composition of correlation clustering solvers, and the solver the segmentation uses
// when the user does not choose one: a fast constructive solver followed by a local
// improvement solver gives most of the quality of the latter at a fraction of its cost.

#ifndef CGAL_FEATURE_SEGMENTATION_SOLVER_SEQUENCE_H
#define CGAL_FEATURE_SEGMENTATION_SOLVER_SEQUENCE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Greedy_additive_edge_contraction.h>
#include <CGAL/Feature_segmentation/Kernighan_lin_with_joins.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/*!
  \ingroup PkgFeatureSegmentationSolvers

  \brief runs the solver `First`, then the solver `Second` starting from the labels
  computed by `First`.

  \tparam First a model of `CorrelationClusteringSolver`.
  \tparam Second a model of `CorrelationClusteringSolver`, usually one that improves its
          initial partition, such as `Kernighan_lin_with_joins`.

  \cgalModels{CorrelationClusteringSolver}
*/
template <class First, class Second>
class Solver_sequence
{
public:
  /// creates the sequence from two solver objects.
  explicit Solver_sequence(First first = First(), Second second = Second())
    : m_first(std::move(first)), m_second(std::move(second))
  {}

  /// returns the first solver.
  First& first() { return m_first; }
  /// returns the first solver.
  const First& first() const { return m_first; }
  /// returns the second solver.
  Second& second() { return m_second; }
  /// returns the second solver.
  const Second& second() const { return m_second; }

  /*!
    computes a clustering of `g`.

    \param g the graph.
    \param labels on entry, passed to `First`; on exit, the labels computed by `Second`.
    \return the number of clusters.
  */
  std::size_t operator()(const Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    m_first(g, labels);
    return m_second(g, labels);
  }

private:
  First m_first;
  Second m_second;
};

/*!
  \ingroup PkgFeatureSegmentationSolvers

  \brief the default solver: `Greedy_additive_edge_contraction` followed by
  `Kernighan_lin_with_joins`, as recommended by Keuper et al.

  It ignores any initial labelling, like its first stage.

  \cgalModels{CorrelationClusteringSolver}
*/
class Default_correlation_clustering_solver
  : public Solver_sequence<Greedy_additive_edge_contraction, Kernighan_lin_with_joins>
{
public:
  /// creates the solver; the parameters are those of `Kernighan_lin_with_joins`.
  explicit Default_correlation_clustering_solver(std::size_t number_of_iterations = 100,
                                                 double epsilon = 1e-9,
                                                 std::size_t moves_without_improvement = 100)
    : Solver_sequence<Greedy_additive_edge_contraction, Kernighan_lin_with_joins>(
        Greedy_additive_edge_contraction(),
        Kernighan_lin_with_joins(number_of_iterations, epsilon, moves_without_improvement))
  {}

  /*!
    computes a clustering of `g` into `labels` and returns the number of clusters, as the
    `CorrelationClusteringSolver` concept asks: the result of the sequence of the two
    solvers, which here share one adjacency.
  */
  std::size_t operator()(const Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    // Same as Solver_sequence::operator(), but both stages share one adjacency.
    internal::Simple_adjacency adj;
    internal::greedy_additive_edge_contraction(g, adj, labels);
    internal::Kernighan_lin_with_joins_impl klj(second().number_of_iterations(),
                                                second().epsilon(),
                                                second().moves_without_improvement(),
                                                second().parallel());
    klj.run(adj, labels);
    return normalize_labels(labels);
  }
};

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_SOLVER_SEQUENCE_H
