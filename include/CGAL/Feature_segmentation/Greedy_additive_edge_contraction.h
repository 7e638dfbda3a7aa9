// SPDX-License-Identifier: GPL-3.0-or-later
//
// Greedy additive edge contraction (GAEC), a fast model of CorrelationClusteringSolver
// that builds a clustering bottom-up from singletons. It is the usual initialisation of
// Kernighan_lin_with_joins (see Default_correlation_clustering_solver); the contraction
// machinery lives in internal/correlation_clustering/.

#ifndef CGAL_FEATURE_SEGMENTATION_GREEDY_ADDITIVE_EDGE_CONTRACTION_H
#define CGAL_FEATURE_SEGMENTATION_GREEDY_ADDITIVE_EDGE_CONTRACTION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Simple_adjacency.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/greedy_additive_edge_contraction_impl.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/*!
  \ingroup PkgFeatureSegmentationSolvers

  \brief Greedy additive edge contraction, after Keuper et al., "Efficient decomposition
  of image and mesh graphs by lifted multicuts", ICCV 2015.

  Starting from singleton clusters, the solver repeatedly contracts the edge of largest
  positive weight, that is, merges the two clusters that most want to be together. When
  two clusters are merged, the edges they had to a common neighbour become one edge whose
  weight is the sum of theirs. The solver stops when no edge of positive weight is left:
  every further merge would increase the cut cost. Ties between equal weights are broken
  by edge index, so the result is deterministic.

  GAEC ignores any initial labelling passed to it; use `Kernighan_lin_with_joins` to
  improve a given partition.

  Complexity: \f$ O(m \log m) \f$ heap operations for a graph with \f$ m \f$ edges, plus
  the merging of neighbourhoods, which costs the size of the smaller one per contraction.

  \cgalModels{CorrelationClusteringSolver}
*/
class Greedy_additive_edge_contraction
{
public:
  /*!
    computes a clustering of `g`.

    \param g the graph.
    \param labels ignored on entry; on exit, the cluster of every node, normalised as by
           `normalize_labels()`.
    \return the number of clusters.
  */
  std::size_t operator()(const Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    internal::Simple_adjacency adj;
    return internal::greedy_additive_edge_contraction(g, adj, labels);
  }
};

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_GREEDY_ADDITIVE_EDGE_CONTRACTION_H
