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
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{gamma}
///     \cgalParamDescription{the anisotropy \f$ \gamma \f$ of the curvature metric (Eq. 6), whose eigenvalues
///                           are 1 and \f$ 1/(1 + \gamma s)^2 \f$ with \f$ s = \vert k_1 \vert - \vert k_2
///                           \vert \f$, the curvatures being those of the mesh scaled to a largest
///                           bounding-box side of 1}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_gamma` (0.05)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{principal_curvature_map}
///     \cgalParamDescription{the principal curvatures of the vertices, used instead of estimating them}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and
///                    `Principal_curvatures<GeomTraits>` as value type}
///     \cgalParamDefault{estimated as by `estimate_principal_curvatures()`, with `neighborhood_rings`,
///                       `neighborhood_radius` and `concurrency_tag`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{feature_lines}
///     \cgalParamDescription{the feature lines to follow (e.g. the user's), whose points place the dual
///                           vertices}
///     \cgalParamType{`Feature_lines<TriangleMesh>`}
///     \cgalParamDefault{the detected crest lines (with `strength_threshold`, `umbilic_ratio`,
///                       `detect_ridges` and `detect_valleys`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{edge_is_feature_map}
///     \cgalParamDescription{the feature edges: with `feature_lines`, the features are the union of these
///                           edges and the edges the lines cross; alone, no crest lines are detected and a
///                           feature edge contributes its midpoint}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::edge_descriptor` as key type and `bool` as value
///                    type}
///     \cgalParamDefault{the edges of the lines (those that `feature_lines`, or else the detected crest
///                       lines, cross)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{strength_threshold}
///     \cgalParamDescription{the crest lines whose strength (the integral of \f$ \vert k \vert \f$ along the
///                           line) is below it are dropped}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_strength_threshold` (1.0)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`. Used only when neither
///                     `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{umbilic_ratio}
///     \cgalParamDescription{the zero crossings near umbilics, where \f$ \vert k \vert - \vert k_{other}
///                           \vert \leq \f$ `umbilic_ratio` \f$ \cdot \vert k \vert \f$, are dropped: there
///                           the principal directions are noise}
///     \cgalParamType{`double` in [0, 1)}
///     \cgalParamDefault{`0.1`}
///     \cgalParamExtra{A value outside [0, 1) throws `Invalid_input`. Used only when neither `feature_lines`
///                     nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_ridges}
///     \cgalParamDescription{whether ridges (maxima of `k_max` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{Used only when neither `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_valleys}
///     \cgalParamDescription{whether valleys (minima of `k_min` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{Used only when neither `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{the number of rings of neighbours of a vertex that the curvature fit takes: the
///                           scale of the features on coarse meshes}
///     \cgalParamType{an integer type, at least 1}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{A value below 1 throws `Invalid_input`. Used only when `principal_curvature_map` is
///                     not given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{neighborhood_radius}
///     \cgalParamDescription{beyond the rings, the curvature fit also takes the vertices within this fraction
///                           of the bounding-box diagonal whose normals are within 30 degrees of the vertex
///                           normal: the scale of the features on fine meshes; 0: rings only}
///     \cgalParamType{`double` in [0, 1]}
///     \cgalParamDefault{`default_neighborhood_radius` (0.01)}
///     \cgalParamExtra{A value outside [0, 1] throws `Invalid_input`. Used only when
///                     `principal_curvature_map` is not given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{concurrency_tag}
///     \cgalParamDescription{a tag indicating whether the curvature fits and the terms of the faces and edges
///                           (their metrics, Similarity and Award) run sequentially or on TBB's threads}
///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
///     \cgalParamDefault{`CGAL::Sequential_tag`}
///     \cgalParamExtra{With `CGAL::Parallel_tag` the program must link TBB (e.g. `CGAL::TBB_support`);
///                     `tbb::global_control` bounds the number of threads. The result is the same at any
///                     thread count.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{alpha}
///     \cgalParamDescription{the global parameter \f$ \alpha \f$ of the segmentation: only checked here, the
///                           result does not depend on it}
///     \cgalParamType{`double`, finite}
///     \cgalParamDefault{`default_alpha` (0.6)}
///     \cgalParamExtra{A non-finite value throws `Invalid_input`. `edge_alpha_map` is not read.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_angle}
///     \cgalParamDescription{the crease angle of the segmentation (in degrees): only checked here; this
///                           function works on `tm` as it is, not cut open along its creases}
///     \cgalParamType{`double`, above 0}
///     \cgalParamDefault{`default_crease_angle` (20)}
///     \cgalParamExtra{A value that is not a finite number above 0 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_filter_iterations}
///     \cgalParamDescription{the rounds of the segmentation's normal filter before its creases are found:
///                           only checked here; this function works on `tm` as it is, not cut open along its
///                           creases}
///     \cgalParamType{an integer type, 0 to 1000}
///     \cgalParamDefault{`default_crease_filter_iterations` (40)}
///     \cgalParamExtra{A value outside 0 to 1000 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{tangent_discontinuities}
///     \cgalParamDescription{the segmentation's option that makes the curvature discontinuities of CAD
///                           tessellations creases: read, but without effect here; this function works on
///                           `tm` as it is, not cut open along its creases}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_tangent_discontinuities` (`true`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crest_lines_on_clean_tessellations}
///     \cgalParamDescription{the segmentation's option that gives the crest lines of CAD tessellations the
///                           full \f$ \alpha \f$: read, but without effect here; this function works on `tm`
///                           as it is, not cut open along its creases}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_crest_lines_on_clean_tessellations` (`false`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t` must
///                     be available in `TriangleMesh`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type, deduced with `CGAL::Kernel_traits`}
///     \cgalParamExtra{The geometric traits class must be compatible with the vertex point type. Only its
///                     types are used (`FT`, `Point_3`, `Vector_3`: the value type of the curvature map is
///                     `Principal_curvatures<GeomTraits>`); the computations are done in `double`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
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
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{alpha}
///     \cgalParamDescription{the global parameter \f$ \alpha \f$, the \f$ \alpha_e \f$ of the feature edges}
///     \cgalParamType{`double`, finite}
///     \cgalParamDefault{`default_alpha` (0.6)}
///     \cgalParamExtra{A non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{edge_alpha_map}
///     \cgalParamDescription{the \f$ \alpha_e \f$ of every edge, overriding `alpha`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::edge_descriptor` as key type and `double` (finite)
///                    as value type}
///     \cgalParamDefault{`alpha` on feature edges, 0 elsewhere}
///     \cgalParamExtra{A non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{gamma}
///     \cgalParamDescription{the anisotropy \f$ \gamma \f$ of the curvature metric (Eq. 6), whose eigenvalues
///                           are 1 and \f$ 1/(1 + \gamma s)^2 \f$ with \f$ s = \vert k_1 \vert - \vert k_2
///                           \vert \f$, the curvatures being those of the mesh scaled to a largest
///                           bounding-box side of 1}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_gamma` (0.05)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{principal_curvature_map}
///     \cgalParamDescription{the principal curvatures of the vertices, used instead of estimating them}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and
///                    `Principal_curvatures<GeomTraits>` as value type}
///     \cgalParamDefault{estimated as by `estimate_principal_curvatures()`, with `neighborhood_rings`,
///                       `neighborhood_radius` and `concurrency_tag`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{feature_lines}
///     \cgalParamDescription{the feature lines to follow (e.g. the user's), whose points place the dual
///                           vertices}
///     \cgalParamType{`Feature_lines<TriangleMesh>`}
///     \cgalParamDefault{the detected crest lines (with `strength_threshold`, `umbilic_ratio`,
///                       `detect_ridges` and `detect_valleys`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{edge_is_feature_map}
///     \cgalParamDescription{the feature edges: with `feature_lines`, the features are the union of these
///                           edges and the edges the lines cross; alone, no crest lines are detected and a
///                           feature edge contributes its midpoint}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::edge_descriptor` as key type and `bool` as value
///                    type}
///     \cgalParamDefault{the edges of the lines (those that `feature_lines`, or else the detected crest
///                       lines, cross)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{strength_threshold}
///     \cgalParamDescription{the crest lines whose strength (the integral of \f$ \vert k \vert \f$ along the
///                           line) is below it are dropped}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_strength_threshold` (1.0)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`. Used only when neither
///                     `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{umbilic_ratio}
///     \cgalParamDescription{the zero crossings near umbilics, where \f$ \vert k \vert - \vert k_{other}
///                           \vert \leq \f$ `umbilic_ratio` \f$ \cdot \vert k \vert \f$, are dropped: there
///                           the principal directions are noise}
///     \cgalParamType{`double` in [0, 1)}
///     \cgalParamDefault{`0.1`}
///     \cgalParamExtra{A value outside [0, 1) throws `Invalid_input`. Used only when neither `feature_lines`
///                     nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_ridges}
///     \cgalParamDescription{whether ridges (maxima of `k_max` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{Used only when neither `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_valleys}
///     \cgalParamDescription{whether valleys (minima of `k_min` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{Used only when neither `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{the number of rings of neighbours of a vertex that the curvature fit takes: the
///                           scale of the features on coarse meshes}
///     \cgalParamType{an integer type, at least 1}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{A value below 1 throws `Invalid_input`. Used only when `principal_curvature_map` is
///                     not given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{neighborhood_radius}
///     \cgalParamDescription{beyond the rings, the curvature fit also takes the vertices within this fraction
///                           of the bounding-box diagonal whose normals are within 30 degrees of the vertex
///                           normal: the scale of the features on fine meshes; 0: rings only}
///     \cgalParamType{`double` in [0, 1]}
///     \cgalParamDefault{`default_neighborhood_radius` (0.01)}
///     \cgalParamExtra{A value outside [0, 1] throws `Invalid_input`. Used only when
///                     `principal_curvature_map` is not given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{concurrency_tag}
///     \cgalParamDescription{a tag indicating whether the curvature fits and the terms of the faces and edges
///                           (their metrics, Similarity and Award) run sequentially or on TBB's threads}
///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
///     \cgalParamDefault{`CGAL::Sequential_tag`}
///     \cgalParamExtra{With `CGAL::Parallel_tag` the program must link TBB (e.g. `CGAL::TBB_support`);
///                     `tbb::global_control` bounds the number of threads. The result is the same at any
///                     thread count.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_angle}
///     \cgalParamDescription{the crease angle of the segmentation (in degrees): only checked here; this
///                           function works on `tm` as it is, not cut open along its creases}
///     \cgalParamType{`double`, above 0}
///     \cgalParamDefault{`default_crease_angle` (20)}
///     \cgalParamExtra{A value that is not a finite number above 0 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_filter_iterations}
///     \cgalParamDescription{the rounds of the segmentation's normal filter before its creases are found:
///                           only checked here; this function works on `tm` as it is, not cut open along its
///                           creases}
///     \cgalParamType{an integer type, 0 to 1000}
///     \cgalParamDefault{`default_crease_filter_iterations` (40)}
///     \cgalParamExtra{A value outside 0 to 1000 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{tangent_discontinuities}
///     \cgalParamDescription{the segmentation's option that makes the curvature discontinuities of CAD
///                           tessellations creases: read, but without effect here; this function works on
///                           `tm` as it is, not cut open along its creases}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_tangent_discontinuities` (`true`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crest_lines_on_clean_tessellations}
///     \cgalParamDescription{the segmentation's option that gives the crest lines of CAD tessellations the
///                           full \f$ \alpha \f$: read, but without effect here; this function works on `tm`
///                           as it is, not cut open along its creases}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_crest_lines_on_clean_tessellations` (`false`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t` must
///                     be available in `TriangleMesh`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type, deduced with `CGAL::Kernel_traits`}
///     \cgalParamExtra{The geometric traits class must be compatible with the vertex point type. Only its
///                     types are used (`FT`, `Point_3`, `Vector_3`: the value type of the curvature map is
///                     `Principal_curvatures<GeomTraits>`); the computations are done in `double`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
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
