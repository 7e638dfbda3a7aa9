// SPDX-License-Identifier: GPL-3.0-or-later
// Per-face patches from (smoothed) patch boundaries, two ways: on the input mesh, every
// face takes the patch covering most of its area; or a refined copy of the mesh in which
// the boundaries are chains of edges and every face lies in exactly one patch, ready for
// CGAL's per-patch tools (connected components, remeshing with constraints, ...).

#ifndef CGAL_FEATURE_SEGMENTATION_FACE_PATCHES_H
#define CGAL_FEATURE_SEGMENTATION_FACE_PATCHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/internal/boundary_refinement_impl.h>
#include <CGAL/Feature_segmentation/internal/reserve_mesh.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationBoundaries
/// Gives every face of the mesh the patch that covers most of its area, the areas being
/// cut by the boundaries as they are in `boundaries` (typically after
/// `smooth_patch_boundaries()`).
///
/// A face whose three vertices lie in one patch gets that patch. In a face the boundary
/// passes through, the lone vertex's patch owns the quadrilateral between the vertex,
/// the boundary's points on its two edges and the face's point; the other patch owns
/// the rest. At a junction, each vertex's patch owns its quadrilateral. Ties go to the
/// smallest patch id. This is the package's one face rule: `segment_along_features()`
/// and `Feature_aligned_segmentation::patch(face_descriptor)` apply it to the unsmoothed
/// boundaries; after `smooth_patch_boundaries()` it follows the smoothed ones, to within
/// half a triangle.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FacePatchMap a `WritablePropertyMap` from `face_descriptor` to an integer type
/// \param boundaries the boundaries
/// \param face_patch_map the output
/// \return the number of faces the boundaries cross (faces with two patches or more)
template <typename TriangleMesh, typename FacePatchMap>
std::size_t majority_face_patches(const Patch_boundaries<TriangleMesh>& boundaries, FacePatchMap face_patch_map)
{
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;
  const auto& s = boundaries.state();
  std::size_t crossed = 0;
  for(std::size_t f = 0; f < s.number_of_faces(); ++f)
  {
    if(s.has_cut_edges(f)) ++crossed;
    put(face_patch_map, s.face_list[f], static_cast<Id>(internal::majority_patch(s, f)));
  }
  return crossed;
}

namespace internal {

// The named parameter `snapping_ratio` of the refinement, checked.
template <typename NamedParameters>
double snapping_ratio(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double delta = choose_parameter(get_parameter(np, internal_np::snapping_ratio), 0.1);
  if(!(delta >= 0 && delta < 0.5))
    throw Invalid_input("snapping_ratio must be in [0, 0.5) (got " + std::to_string(delta) + ")");
  return delta;
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationBoundaries
/// Writes into `out` a refined copy of the mesh in which the boundaries are chains of
/// edges, with the exact patch of every face.
///
/// Every cut edge is split at the boundary's point on it, unless that point is closer
/// than `snapping_ratio` times the edge's length to one of the edge's ends: then the
/// boundary is snapped to that vertex (it passes through it). Every face the boundary
/// crosses is split along it: a junction gets a new vertex at the junction point (moved
/// inside the face until its barycentric coordinates are at least `snapping_ratio`, 0.3
/// at most); a face the boundary passes through is cut along the straight chord between
/// the boundary's two ends on its sides, or, where the boundary bends inside the face
/// by more than `snapping_ratio` times the chord and the bend point has barycentric
/// coordinates of at least `snapping_ratio`, through that point. So no new vertex lies
/// closer to an edge's end than `snapping_ratio` times that edge, nor closer to a side of
/// its face than `snapping_ratio` in barycentric coordinates. A smoothed boundary is
/// straight inside every face it passes through, so only junctions add inner vertices.
///
/// Faces of the refined mesh lie in exactly one patch each; the boundary edges (edges
/// between two faces of different patches) form the curves, snapped as described. The
/// output's vertices are the input's (in the order of `vertices(tm)`) followed by the new
/// ones; coordinates are computed in double precision. The patch ids are the vertex
/// patch ids of `boundaries`.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam OutputMesh a model of `MutableFaceGraph` with an internal vertex point map
/// \tparam FacePatchMap a `ReadWritePropertyMap` from the output's `face_descriptor` to an
///         integer type
/// \param boundaries the boundaries
/// \param out the output mesh, to which the refined mesh is added (normally empty:
///        property maps of `out` stay valid, which clearing it would not guarantee)
/// \param face_patch_map the patch of every face of `out`
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{snapping_ratio}
///     \cgalParamDescription{a boundary point closer than this fraction of its edge's length to one of the
///                           edge's ends is snapped to that vertex; a new vertex inside a face has
///                           barycentric coordinates of at least this value}
///     \cgalParamType{`double` in [0, 0.5)}
///     \cgalParamDefault{`0.1`}
///     \cgalParamExtra{A value outside [0, 0.5) throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{an optional output: `true` exactly on the boundary edges of the refined mesh
///                           (the edges between faces of two different patches), `false` on its other edges}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<OutputMesh>::edge_descriptor` as key type and `bool` as value
///                    type}
///     \cgalParamDefault{none (no output)}
///     \cgalParamExtra{Every edge of `out` is written, also those `out` had before.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return the number of faces of the input that were split
///
/// \throws Invalid_input if `snapping_ratio` is outside [0, 0.5)
template <typename TriangleMesh, typename OutputMesh, typename FacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t refine_mesh_along_boundaries(const Patch_boundaries<TriangleMesh>& boundaries, OutputMesh& out,
                                         FacePatchMap face_patch_map,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef boost::graph_traits<OutputMesh> GTo;
  typedef typename boost::property_map<OutputMesh, CGAL::vertex_point_t>::type Out_vpm;
  typedef typename boost::property_traits<Out_vpm>::value_type Out_point;
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;

  const internal::Refinement r = internal::refine_along_boundaries(boundaries.state(), internal::snapping_ratio(np));

  {
    // room for what is added (no doubling of the mesh's arrays): E = (3F + B) / 2, and a
    // border edge of the input is split at most once
    std::size_t border = 0;
    const auto& s = boundaries.state();
    for(const auto& ef : s.edge_faces) if(ef[0] == s.npos || ef[1] == s.npos) ++border;
    internal::reserve_mesh(out, num_vertices(out) + r.points.size(),
                           num_edges(out) + (3 * r.triangles.size() + 2 * border) / 2 + 1,
                           num_faces(out) + r.triangles.size());
  }
  Out_vpm vpm = get(CGAL::vertex_point, out);
  std::vector<typename GTo::vertex_descriptor> vs;
  vs.reserve(r.points.size());
  for(const auto& p : r.points)
  {
    const typename GTo::vertex_descriptor v = add_vertex(out);
    put(vpm, v, Out_point(p.x(), p.y(), p.z()));
    vs.push_back(v);
  }
  for(std::size_t i = 0; i < r.triangles.size(); ++i)
  {
    const auto& t = r.triangles[i];
    const std::array<typename GTo::vertex_descriptor, 3> tri = { vs[t[0]], vs[t[1]], vs[t[2]] };
    const typename GTo::face_descriptor f = CGAL::Euler::add_face(tri, out);
    CGAL_assertion(f != GTo::null_face());
    if(f != GTo::null_face()) put(face_patch_map, f, static_cast<Id>(r.patches[i]));
  }
  // isolated vertices of the input stay isolated; vertices added for nothing cannot occur
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
  {
    auto constrained = get_parameter(np, CGAL::internal_np::edge_is_constrained);
    for(auto e : edges(out)) // an `out` that was not empty has its other edges set too
    {
      const auto h = halfedge(e, out);
      const auto f0 = face(h, out), f1 = face(opposite(h, out), out);
      put(constrained, e, f0 != GTo::null_face() && f1 != GTo::null_face() &&
                            get(face_patch_map, f0) != get(face_patch_map, f1));
    }
  }
  return r.split_faces;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_FACE_PATCHES_H
