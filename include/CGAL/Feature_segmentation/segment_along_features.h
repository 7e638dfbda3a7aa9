// SPDX-License-Identifier: GPL-3.0-or-later
// The one-shot automatic segmentation (paper, Sections 3.1-3.3): curvature, crest lines,
// edge weights, then correlation clustering of the mesh's vertex graph; the number of
// patches comes out of the solve.

#ifndef CGAL_FEATURE_SEGMENTATION_SEGMENT_ALONG_FEATURES_H
#define CGAL_FEATURE_SEGMENTATION_SEGMENT_ALONG_FEATURES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>

#include <cstddef>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationSegmentation
/// Segments `tm` into patches whose boundaries follow its salient ridges and valleys:
/// correlation clustering of the mesh's vertex graph with the weights of
/// `compute_edge_weights()` (Eq. 1 and 3). Returns the number of patches and writes the
/// patch of every vertex, numbered `0` to `n-1` in the order of the vertices.
///
/// By default the clustering runs on the reduced graph G' of a watershed
/// oversegmentation (paper, Section 3.3): the distance on the dual graph from the
/// triangles that hold a feature edge (BGL's Dijkstra, dual edges of length
/// Similarity(e)) is negated and flooded by the immersion watershed of Vincent and
/// Soille; every vertex takes the majority basin of the basin triangles around it (ties:
/// the smallest basin; a vertex with watershed triangles only: the basin of the nearest
/// labelled vertex); the oversegments are the connected components of same-basin
/// vertices joined by non-feature edges, so that every feature line is a boundary of the
/// oversegmentation. G' has one node per oversegment and one edge per adjacent pair,
/// weighted by the sum of the weights of the mesh edges between them; its clustering is
/// pulled back to the vertices. `use_oversegmentation(false)` clusters the full vertex
/// graph instead.
///
/// The vertex labels are the clustering's output, except on a rough mesh (one that is
/// not a clean tessellation: noisy, or a smooth model) whose creases are looked for
/// (`crease_angle` below 180): there a patch of at most ten vertices (of the mesh cut
/// open along its creases) is noise, and joins the neighbouring patch whose join raises
/// the cut cost least. A patch's boundary is the dual of its cut edges. A face gets the
/// patch that covers most of its area under these boundaries (the rule of
/// `majority_face_patches()` on `compute_patch_boundaries()`; ties to the smallest id): a
/// face whose vertices share a patch gets it.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexPatchMap a `WritablePropertyMap` from `vertex_descriptor` to an integer type
/// \param tm the mesh (checked with `check_input_mesh()`: throws `Invalid_input`)
/// \param vertex_patch_map the output
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{alpha}
///     \cgalParamDescription{the global parameter \f$ \alpha \f$, the \f$ \alpha_e \f$ of the feature edges;
///                           useful range 0.5 to 1.0, larger values give more patches}
///     \cgalParamType{`double`, finite}
///     \cgalParamDefault{`default_alpha` (0.6)}
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
///   \cgalParamNBegin{edge_alpha_map}
///     \cgalParamDescription{the \f$ \alpha_e \f$ of every edge, overriding `alpha`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::edge_descriptor` as key type and `double` (finite)
///                    as value type}
///     \cgalParamDefault{`alpha` on feature edges, 0 elsewhere}
///     \cgalParamExtra{A non-finite value throws `Invalid_input`. A crease takes the value of its edge. On a
///                     tessellation of a CAD part, the edges of detected crest lines get 0.5 less (see
///                     `crest_lines_on_clean_tessellations`).}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_angle}
///     \cgalParamDescription{the edges whose faces bend by at least this angle (in degrees) are creases: the
///                           segmentation runs on the mesh cut open along them; 180 or more: no creases (the
///                           paper's pipeline)}
///     \cgalParamType{`double`, above 0}
///     \cgalParamDefault{`default_crease_angle` (20)}
///     \cgalParamExtra{A value that is not a finite number above 0 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_filter_iterations}
///     \cgalParamDescription{the rounds of bilateral filtering of the face normals before the creases are
///                           found: none on a clean mesh, until the normals are smooth (at most 10 rounds) on
///                           a smooth model, on a noisy one from 5 to all of them as the noise grows; 0: the
///                           raw dihedral angles}
///     \cgalParamType{an integer type, 0 to 1000}
///     \cgalParamDefault{`default_crease_filter_iterations` (40)}
///     \cgalParamExtra{A value outside 0 to 1000 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{tangent_discontinuities}
///     \cgalParamDescription{whether, on a clean tessellation of a CAD part, the curvature discontinuities
///                           (where a fillet meets a plane or a wider curved face without a crease angle)
///                           join the creases, and seam lines (where two curved faces meet and the
///                           smaller principal curvature steps) join the crest lines}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_tangent_discontinuities` (`true`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crest_lines_on_clean_tessellations}
///     \cgalParamDescription{whether the crest lines of a tessellation of a CAD part (a clean one, a noisy
///                           one, or one its creases cut into pieces) get the full \f$ \alpha \f$ (the
///                           paper's features); if not, their \f$ \alpha_e \f$ is \f$ \alpha \f$ minus
///                           0.5, so that the creases and the curvature discontinuities bound the patches}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_crest_lines_on_clean_tessellations` (`false`)}
///     \cgalParamExtra{Without effect when `feature_lines` is given.}
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
///     \cgalParamDescription{a tag indicating whether the curvature fits, the crease detection (the rounds of
///                           the normal filter, the gap test) and the terms of the edge weights run
///                           sequentially or on TBB's threads}
///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
///     \cgalParamDefault{`CGAL::Sequential_tag`}
///     \cgalParamExtra{With `CGAL::Parallel_tag` the program must link TBB (e.g. `CGAL::TBB_support`);
///                     `tbb::global_control` bounds the number of threads. The result is the same at any
///                     thread count.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{solver}
///     \cgalParamDescription{the correlation clustering solver, stored by copy}
///     \cgalParamType{a model of `CorrelationClusteringSolver`}
///     \cgalParamDefault{`Default_correlation_clustering_solver` (GAEC followed by Kernighan-Lin with joins)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{use_oversegmentation}
///     \cgalParamDescription{whether the clustering is solved on the reduced graph G' of the watershed
///                           oversegmentation (`true`) or on the full vertex graph}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{watershed_distance}
///     \cgalParamDescription{the distance whose watershed makes the oversegmentation: anisotropic (dual edges
///                           of length Similarity(e)) or geodesic (of length Award(e))}
///     \cgalParamType{`Watershed_distance`}
///     \cgalParamDefault{`Watershed_distance::ANISOTROPIC`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{face_patch_map}
///     \cgalParamDescription{an optional output: the patch of every face, the patch that covers most of its
///                           area under the boundaries of the vertex patches (the smallest id on a tie)}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::face_descriptor` as key type and an integer type as
///                    value type}
///     \cgalParamDefault{none (no output)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{cut_cost_output}
///     \cgalParamDescription{an optional output: the cut cost (Eq. 1) of the result is written to
///                           `*cut_cost_output` (nothing is written through a null pointer)}
///     \cgalParamType{`double*`}
///     \cgalParamDefault{none (no output)}
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
/// \return the number of patches
template <typename TriangleMesh, typename VertexPatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t segment_along_features(const TriangleMesh& tm, VertexPatchMap vertex_patch_map,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  // one shot of the editing class: same precomputation, same defaults, same solve
  const Feature_aligned_segmentation<TriangleMesh> seg(tm, np);
  seg.vertex_patches(vertex_patch_map);
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::face_patch_t>::value)
    seg.face_patches(get_parameter(np, CGAL::internal_np::face_patch));
  if constexpr(!is_default_parameter<NamedParameters, internal_np::cut_cost_output_t>::value)
  {
    double* out = get_parameter(np, internal_np::cut_cost_output);
    if(out != nullptr) *out = seg.cut_cost();
  }
  const std::size_t n = seg.number_of_patches();
  return n;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_SEGMENT_ALONG_FEATURES_H
