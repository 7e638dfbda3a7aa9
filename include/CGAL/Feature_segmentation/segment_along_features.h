// SPDX-License-Identifier: GPL-3.0-or-later
// The one-shot automatic segmentation (paper, Sections 3.1-3.3): curvature, crest lines,
// edge weights, then correlation clustering of the mesh's vertex graph; the number of
// patches comes out of the solve.

#ifndef CGAL_FEATURE_SEGMENTATION_SEGMENT_ALONG_FEATURES_H
#define CGAL_FEATURE_SEGMENTATION_SEGMENT_ALONG_FEATURES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>
#include <CGAL/Feature_segmentation/internal/prepare_segmentation_data.h>
#include <CGAL/Feature_segmentation/internal/oversegmentation_impl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
/// \ingroup PkgFeatureSegmentationSegmentation
/// The distance whose watershed makes the oversegmentation (paper, Section 3.3).
enum class Watershed_distance
{
  ANISOTROPIC, ///< dual edges of length Similarity(e): the paper's choice, the default
  GEODESIC     ///< dual edges of Euclidean length Award(e), as Mitani-Suzuki and Levy et al.
};

namespace internal {

// The patch of a face from its vertices' patches: the majority; when the three differ,
// the smallest id.
inline std::size_t face_patch_from_vertices(std::size_t a, std::size_t b, std::size_t c)
{
  if(a == b || a == c) return a;
  if(b == c) return b;
  return (std::min)(a, (std::min)(b, c));
}

template <typename TriangleMesh, typename FacePatchMap>
void write_face_patches(const Mesh_indexing<TriangleMesh>& idx, const std::vector<std::size_t>& labels,
                        FacePatchMap face_patch)
{
  const TriangleMesh& tm = idx.mesh();
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    auto h = halfedge(idx.face_at(f), tm);
    put(face_patch, idx.face_at(f),
        static_cast<Id>(face_patch_from_vertices(labels[idx.id(source(h, tm))], labels[idx.id(target(h, tm))],
                                                 labels[idx.id(target(next(h, tm), tm))])));
  }
}

} // namespace internal

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
/// cut edges. Faces get the patch of the majority of their three vertices, or the smallest
/// of the three ids when all differ.
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
///     `neighborhood_rings`, default 2)
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
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  const internal::Segmentation_options opt = internal::read_segmentation_options<TriangleMesh>(np);
  internal::Segmentation_data<TriangleMesh> data(tm);
  Feature_lines<TriangleMesh> lines;
  internal::prepare_segmentation_data(tm, np, opt, data, lines);

  const std::vector<double> alpha_e = internal::edge_alphas(data, opt, np);
  const auto solver = choose_parameter(get_parameter(np, internal_np::solver),
                                       Default_correlation_clustering_solver());
  const bool reduced = choose_parameter(get_parameter(np, internal_np::use_oversegmentation), true);
  const Watershed_distance distance = choose_parameter(get_parameter(np, internal_np::watershed_distance),
                                                       Watershed_distance::ANISOTROPIC);
  std::vector<std::size_t> labels;
  if(reduced)
  {
    const internal::Oversegmentation os =
      internal::compute_oversegmentation(data, distance == Watershed_distance::ANISOTROPIC);
    internal::Reduced_graph rg;
    rg.build(os.vertex_segment, os.number_of_segments, data.edge_vertices);
    const Correlation_clustering_graph gr = rg.graph([&](std::size_t e) { return data.weight(e, alpha_e[e]); });
    std::vector<std::size_t> segment_labels;
    solver(gr, segment_labels);
    CGAL_postcondition(segment_labels.size() == gr.number_of_nodes());
    labels.resize(os.vertex_segment.size());
    for(std::size_t v = 0; v < labels.size(); ++v) labels[v] = segment_labels[os.vertex_segment[v]];
  }
  else
  {
    solver(data.graph(alpha_e), labels);
    CGAL_postcondition(labels.size() == data.idx.number_of_vertices());
  }
  const std::size_t n = normalize_labels(labels);

  typedef typename boost::property_traits<VertexPatchMap>::value_type Id;
  for(std::size_t v = 0; v < labels.size(); ++v)
    put(vertex_patch_map, data.idx.vertex_at(v), static_cast<Id>(labels[v]));
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::face_patch_t>::value)
    internal::write_face_patches(data.idx, labels, get_parameter(np, CGAL::internal_np::face_patch));
  if constexpr(!is_default_parameter<NamedParameters, internal_np::cut_cost_output_t>::value)
  {
    double* out = get_parameter(np, internal_np::cut_cost_output);
    if(out != nullptr)
    {
      double cost = 0; // on the mesh's edges (equal to G''s cut cost: inner edges are never cut)
      for(std::size_t e = 0; e < data.edge_vertices.size(); ++e)
        if(labels[data.edge_vertices[e].first] != labels[data.edge_vertices[e].second])
          cost += data.weight(e, alpha_e[e]);
      *out = cost;
    }
  }
  return n;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_SEGMENT_ALONG_FEATURES_H
