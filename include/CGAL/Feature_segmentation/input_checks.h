// SPDX-License-Identifier: GPL-3.0-or-later
// Validation of an input triangle mesh. Every entry point of the package calls
// `check_input_mesh()` first, so input a user can get wrong (an empty mesh, a face that
// is not a triangle, a NaN or infinite coordinate, a pinched vertex) is reported by one
// exception with a clear message instead of undefined behaviour further down.

#ifndef CGAL_FEATURE_SEGMENTATION_INPUT_CHECKS_H
#define CGAL_FEATURE_SEGMENTATION_INPUT_CHECKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/internal/mesh_pass_counts.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationRef
/// Thrown by the package's functions when the input mesh or an option value cannot be
/// processed; `what()` says which and why in one line.
class Invalid_input : public std::invalid_argument
{
public:
  /// An exception with the one-line message `what`.
  explicit Invalid_input(const std::string& what) : std::invalid_argument(what) {}
};

/// \ingroup PkgFeatureSegmentationRef
/// What `check_input_mesh()` found, for callers that want counts rather than an
/// exception for the conditions the package can live with.
struct Mesh_check_report
{
  std::size_t number_of_degenerate_faces = 0; ///< faces whose three points are collinear
  std::size_t number_of_border_edges = 0;     ///< edges with a face on one side only
};

/// \ingroup PkgFeatureSegmentationRef
/// Checks that `tm` is a non-empty, pure triangle mesh with finite coordinates and no
/// non-manifold vertex, and throws `Invalid_input` otherwise. Degenerate faces and
/// border edges are allowed by the package (each stage documents its treatment); they
/// are counted in the returned report, and `Invalid_input` is thrown for degenerate faces
/// only when `allow_degenerate_faces` is `false`.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \param tm the mesh
/// \param allow_degenerate_faces whether zero-area faces are accepted
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t` must
///                     be available in `TriangleMesh`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_check_report check_input_mesh(const TriangleMesh& tm,
                                   bool allow_degenerate_faces = true,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  CGAL_FEATURE_SEGMENTATION_COUNT_PASS(checks);
  VPM vpm = internal::vertex_point_map(tm, np);

  Mesh_check_report report;
  if(faces(tm).empty())
    throw Invalid_input("the mesh has no faces");

  for(auto v : vertices(tm))
  {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      throw Invalid_input("the mesh has a vertex with a NaN or infinite coordinate");
  }
  for(auto f : faces(tm))
  {
    if(!CGAL::is_triangle(halfedge(f, tm), tm))
      throw Invalid_input("the mesh has a face that is not a triangle "
                          "(triangulate it first, e.g. with Polygon_mesh_processing::triangulate_faces)");
  }
  // A vertex is pinched (non-manifold) when the halfedges pointing to it do not all lie
  // in the one fan around it. Linear time: CGAL 5.5's is_non_manifold_vertex() scans
  // all halfedges for each vertex, quadratic on a whole mesh.
  {
    auto vdeg = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    for(auto v : vertices(tm)) put(vdeg, v, 0);
    for(auto h : halfedges(tm)) put(vdeg, target(h, tm), get(vdeg, target(h, tm)) + 1);
    for(auto v : vertices(tm))
    {
      if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        continue; // an isolated vertex has no fan (the segmentation makes it a patch of its own)
      std::size_t fan = 0;
      for(auto h : CGAL::halfedges_around_target(v, tm)) { (void)h; ++fan; }
      if(fan != get(vdeg, v))
        throw Invalid_input("the mesh has a non-manifold vertex (two or more fans of faces "
                            "meet at one vertex; split it first, e.g. with "
                            "Polygon_mesh_processing::duplicate_non_manifold_vertices)");
    }
  }
  for(auto f : faces(tm))
    if(CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(
         f, tm, CGAL::parameters::vertex_point_map(vpm)))
      ++report.number_of_degenerate_faces;
  if(!allow_degenerate_faces && report.number_of_degenerate_faces > 0)
    throw Invalid_input("the mesh has " + std::to_string(report.number_of_degenerate_faces) +
                        " degenerate (zero-area) triangle(s)");
  for(auto e : edges(tm))
    if(CGAL::is_border(e, tm))
      ++report.number_of_border_edges;
  return report;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_INPUT_CHECKS_H
