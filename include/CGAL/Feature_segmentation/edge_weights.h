// SPDX-License-Identifier: GPL-3.0-or-later
// The edge weights of the correlation clustering (paper, Section 3.2, Eq. 3-6):
// w(e) = Similarity(e) - alpha_e * Award(e), where Similarity and Award are the lengths of
// the edge's dual segment in an anisotropic curvature metric and in the Euclidean metric.

#ifndef CGAL_FEATURE_SEGMENTATION_EDGE_WEIGHTS_H
#define CGAL_FEATURE_SEGMENTATION_EDGE_WEIGHTS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/internal/prepare_segmentation_data.h>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationWeights
/// Computes, for every edge, the two terms of its weight.
///
/// Dual structure: every triangle has a dual vertex at its centroid, or, if one of its
/// edges is a feature edge, at the centroid of the feature points on its feature edges
/// (a feature edge given by an edge map without feature lines contributes its midpoint).
/// The dual segment of an interior edge joins the dual vertices of its two triangles.
/// Each triangle carries an anisotropic metric whose eigenvectors follow the principal
/// directions of the triangle (the vertices' curvature tensors averaged and restricted to
/// its plane), with eigenvalues 1 along the direction of `k1` and `1/(1 + gamma s)^2`
/// along that of `k2`, `s = |k1| - |k2|` (Eq. 6). `Similarity(e)` is the length of the
/// dual segment projected on each triangle's plane, in that triangle's metric, averaged
/// over the two triangles; `Award(e)` the same in the Euclidean metric.
///
/// Units: `gamma` multiplies a curvature, so curvatures are measured on the mesh scaled
/// so that the largest side of its bounding box is 1 (as in the authors' tool); the
/// weights scale with the mesh, the segmentation does not depend on its units.
///
/// Special cases: a border edge has a single triangle; its dual segment is replaced by the
/// half segment from that triangle's dual vertex to the edge's feature point, or to its
/// midpoint. A degenerate (zero-area) triangle has no plane; its metric is the Euclidean
/// one, without projection, so it contributes equally to Similarity and Award.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam SimilarityMap, AwardMap `WritablePropertyMap`s from `edge_descriptor` to a
///         floating-point type
/// \param tm the mesh (checked with `check_input_mesh()`)
/// \param similarity the output `Similarity(e)`
/// \param award the output `Award(e)`
/// \param np optional named parameters: `vertex_point_map`, `geom_traits`, `gamma`
///   (default 0.05), `principal_curvature_map` (else estimated with
///   `neighborhood_rings` and `neighborhood_radius`), `feature_lines` (a `Feature_lines<TriangleMesh>`) and/or
///   `edge_is_feature_map` (else crest lines are detected with the options of
///   `detect_crest_lines()`), `concurrency_tag` (`CGAL::Parallel_tag`: the curvature
///   fits and the terms of the faces and edges on TBB's threads, the same values)
template <typename TriangleMesh, typename SimilarityMap, typename AwardMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void compute_similarity_and_award(const TriangleMesh& tm, SimilarityMap similarity, AwardMap award,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Segmentation_options opt = internal::read_segmentation_options<TriangleMesh>(np);
  internal::Segmentation_data<TriangleMesh> data(tm);
  Feature_lines<TriangleMesh> lines;
  internal::prepare_segmentation_data(tm, np, opt, data, lines);
  for(std::size_t e = 0; e < data.idx.number_of_edges(); ++e)
  {
    put(similarity, data.idx.edge_at(e), data.features.similarity[e]);
    put(award, data.idx.edge_at(e), data.features.award[e]);
  }
}

/// \ingroup PkgFeatureSegmentationWeights
/// Computes the weight `w(e) = Similarity(e) - alpha_e Award(e)` of every edge (Eq. 3),
/// with `alpha_e` read from `edge_alpha_map` if given, else `alpha` on feature edges and
/// 0 on the others. Negative weights ask for a cut.
///
/// \param tm the mesh
/// \param weight the output, a `WritablePropertyMap` from `edge_descriptor` to a
///        floating-point type
/// \param np the named parameters of `compute_similarity_and_award()`, and `alpha`
///        (default 0.6) or `edge_alpha_map` (a `ReadablePropertyMap` from
///        `edge_descriptor` to `double`)
/// \return the number of feature edges
template <typename TriangleMesh, typename WeightMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t compute_edge_weights(const TriangleMesh& tm, WeightMap weight,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Segmentation_options opt = internal::read_segmentation_options<TriangleMesh>(np);
  internal::Segmentation_data<TriangleMesh> data(tm);
  Feature_lines<TriangleMesh> lines;
  internal::prepare_segmentation_data(tm, np, opt, data, lines);
  const std::vector<double> alpha_e = internal::edge_alphas(data, opt, np);
  for(std::size_t e = 0; e < data.idx.number_of_edges(); ++e)
    put(weight, data.idx.edge_at(e), data.weight(e, alpha_e[e]));
  return data.features.number_of_feature_edges;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_EDGE_WEIGHTS_H
