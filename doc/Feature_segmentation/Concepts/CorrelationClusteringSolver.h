// SPDX-License-Identifier: GPL-3.0-or-later

/*!
\ingroup PkgFeatureSegmentationConcepts
\cgalConcept

A solver of the correlation clustering problem (Eq. 1 of the paper): given a weighted
undirected graph, find a partition of its nodes that minimises the sum of the weights of
the edges whose endpoints are in different clusters (the cut cost, see `cut_cost()`).
A positive weight asks for its endpoints to be in the same cluster, a negative weight for
them to be separated; the number of clusters is not given but follows from the weights.

The segmentation builds a `CGAL::Feature_segmentation::Correlation_clustering_graph` (on
the vertices of the mesh, or on the oversegments of the reduced graph G') and hands it to
a model of this concept, given by the named parameter `solver` of
`CGAL::Feature_segmentation::segment_along_features()` and of
`CGAL::Feature_segmentation::Feature_aligned_segmentation`. The object is copied once and
the copy is called many times, e.g.\ after every edit of a weight parameter, and only on
the part of the graph that an edit touches, so the operator is `const` and a model keeps
no state from one call to the next.
Since the problem is NP-hard, models are heuristics: they differ in speed and in how
close they come to the optimum, not in what they return.

Requirements on every model:
- The cut cost of the returned partition is computed with every parallel edge counted,
  which amounts to treating parallel edges as one edge with the sum of their weights.
- The returned labels are normalised as by `normalize_labels()`: labels `0, ..., k-1` in
  order of first appearance, so that equal partitions give equal label vectors.
- The result is deterministic: the same graph and the same initial labels give the same
  labels on every run and platform (no dependence on hash iteration order, no unseeded
  randomness).

Nothing else is required: the package's test `test_solver_concept.cpp` runs an archetype, a
class with exactly the copy constructor and the operator below, through
`CGAL::Feature_segmentation::segment_along_features()`. The example
`custom_solver_example.cpp` (\ref fs_example_custom_solver) plugs in a user-written model.

\cgalHasModelsBegin
\cgalHasModels{`CGAL::Feature_segmentation::Greedy_additive_edge_contraction`}
\cgalHasModels{`CGAL::Feature_segmentation::Kernighan_lin_with_joins`}
\cgalHasModels{`CGAL::Feature_segmentation::Solver_sequence`}
\cgalHasModels{`CGAL::Feature_segmentation::Default_correlation_clustering_solver` (the default)}
\cgalHasModelsEnd

\sa `CGAL::Feature_segmentation::Correlation_clustering_graph`, `CGAL::Feature_segmentation::cut_cost()`
\sa \ref fs_api_solver in the user manual
*/
class CorrelationClusteringSolver
{
public:
  /// \name Creation
  /// @{

  /*!
    Copy constructor; the segmentation stores the solver it is given by value.
  */
  CorrelationClusteringSolver(const CorrelationClusteringSolver&);

  /// @}

  /// \name Operations
  /// @{

  /*!
    computes a partition of the nodes of `g`.

    \param g the graph.
    \param labels on entry, either empty, meaning that there is no initial partition (a
           solver that needs one starts from singletons), or of size
           `g.number_of_nodes()`, holding an initial partition with arbitrary label
           values, which a solver may improve
           (`CGAL::Feature_segmentation::Kernighan_lin_with_joins` does, and never returns
           a worse one) or ignore
           (`CGAL::Feature_segmentation::Greedy_additive_edge_contraction` does, as
           documented). On exit, `labels.size() == g.number_of_nodes()` and `labels[i]`
           is the cluster of node `i`, normalised to `0, ..., k-1` in order of first
           appearance.
    \return `k`, the number of clusters.

    \pre `labels.empty() || labels.size() == g.number_of_nodes()`
  */
  std::size_t operator()(const CGAL::Feature_segmentation::Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const;

  /// @}
};
