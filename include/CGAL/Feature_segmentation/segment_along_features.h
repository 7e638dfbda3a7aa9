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
/// The vertex labels are the clustering's output; a patch's boundary is the dual of its
/// cut edges. A face gets the patch that covers most of its area under these boundaries
/// (the rule of `majority_face_patches()` on `compute_patch_boundaries()`; ties to the
/// smallest id): a face whose vertices share a patch gets it.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexPatchMap a `WritablePropertyMap` from `vertex_descriptor` to an integer type
/// \param tm the mesh (checked with `check_input_mesh()`: throws `Invalid_input`)
/// \param vertex_patch_map the output
/// \param np optional named parameters:
///   - `alpha` (double): the global parameter, `alpha_e` on feature edges; default 0.6;
///     useful range 0.5 to 1.0, larger gives more patches
///   - `gamma` (double >= 0): anisotropy of the metric, default 0.05
///   - `edge_alpha_map`: `alpha_e` for every edge (overrides `alpha`)
///   - `principal_curvature_map`: the vertex curvatures (else estimated with
///     `neighborhood_rings` and `neighborhood_radius`, as by `estimate_principal_curvatures()`)
///   - `feature_lines` (`Feature_lines<TriangleMesh>`) and/or `edge_is_feature_map`: the
///     features (else crest lines are detected with `strength_threshold`,
///     `umbilic_ratio`, `detect_ridges`, `detect_valleys`)
///   - `solver`: a model of `CorrelationClusteringSolver`, default
///     `Default_correlation_clustering_solver` (GAEC followed by Kernighan-Lin with joins)
///   - `use_oversegmentation` (bool): solve on the watershed graph G' (default `true`) or
///     on the full vertex graph
///   - `watershed_distance` (`Watershed_distance`): default `Watershed_distance::ANISOTROPIC`
///   - `face_patch_map`: an optional output, a `WritablePropertyMap` from
///     `face_descriptor` to an integer type
///   - `cut_cost_output` (`double*`): an optional output, the cut cost of the result (Eq. 1)
///   - `vertex_point_map`, `geom_traits`
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
