// SPDX-License-Identifier: GPL-3.0-or-later
// The feature-lines structure shared by every stage: polylines of points that lie on
// mesh edges (an edge and a barycentric position), consecutive points sharing a face,
// as the paper represents Yoshizawa et al.'s crest lines (feature points on edges joined
// by segments inside triangles). The edges holding a feature point are the feature edges.

#ifndef CGAL_FEATURE_SEGMENTATION_FEATURE_LINES_H
#define CGAL_FEATURE_SEGMENTATION_FEATURE_LINES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationFeatureLines
/// The kind of a feature line.
enum class Feature_line_type
{
  RIDGE,  ///< a maximum of `k_max` along its direction, with `k_max > |k_min|`
  VALLEY, ///< a minimum of `k_min` along its direction, with `k_min < -|k_max|`
  USER,   ///< given by the user (a polyline file, a sketch)
  SEAM    ///< where two curved faces of a CAD part meet without a crease: a maximum, along
          ///< the direction of `k2`, of the derivative of `k2` (a cylinder running into a torus)
};

/// \ingroup PkgFeatureSegmentationFeatureLines
/// A point on a mesh edge: `(1 - t) * source(halfedge) + t * target(halfedge)`.
template <typename TriangleMesh>
struct Feature_point
{
  /// the halfedge type of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  halfedge_descriptor halfedge; ///< the edge, as one of its halfedges
  double t = 0.;                ///< barycentric position along `halfedge`, in [0, 1]

  /// The point in space, with `vpm` the vertex point map of the mesh.
  template <typename VertexPointMap>
  typename boost::property_traits<VertexPointMap>::value_type
  point(const TriangleMesh& tm, VertexPointMap vpm) const
  {
    const auto& p = get(vpm, source(halfedge, tm));
    const auto& q = get(vpm, target(halfedge, tm));
    return typename boost::property_traits<VertexPointMap>::value_type(
      (1 - t) * p.x() + t * q.x(), (1 - t) * p.y() + t * q.y(), (1 - t) * p.z() + t * q.z());
  }
};

/// \ingroup PkgFeatureSegmentationFeatureLines
/// One feature line: a polyline of feature points, two consecutive points lying on two
/// edges of a common triangle.
template <typename TriangleMesh>
struct Feature_line
{
  Feature_line_type type = Feature_line_type::RIDGE; ///< ridge, valley or user line
  std::vector<Feature_point<TriangleMesh> > points;  ///< the polyline
  bool is_closed = false;  ///< `true` if the last point joins the first
  double length = 0.;      ///< Euclidean length of the polyline
  double strength = 0.;    ///< integral of |curvature| along the line (dimensionless); 0 for user lines
};

/// \ingroup PkgFeatureSegmentationFeatureLines
/// The feature lines of a mesh.
template <typename TriangleMesh>
struct Feature_lines
{
  std::vector<Feature_line<TriangleMesh> > lines; ///< all lines, strongest first
  /// Number of lines of a type.
  std::size_t number_of_lines(Feature_line_type type) const
  {
    std::size_t n = 0;
    for(const auto& l : lines) n += (l.type == type);
    return n;
  }
};

/// \ingroup PkgFeatureSegmentationFeatureLines
/// Sets `edge_is_feature` to `true` on every edge holding a point of one of `lines`, to
/// `false` on the others, and returns the number of feature edges.
/// \tparam EdgeIsFeatureMap a `ReadWritePropertyMap` from `edge_descriptor` to `bool`
template <typename TriangleMesh, typename EdgeIsFeatureMap>
std::size_t mark_feature_edges(const TriangleMesh& tm, const Feature_lines<TriangleMesh>& lines,
                               EdgeIsFeatureMap edge_is_feature)
{
  for(auto e : edges(tm)) put(edge_is_feature, e, false);
  std::size_t n = 0;
  for(const auto& l : lines.lines)
    for(const auto& p : l.points)
    {
      auto e = edge(p.halfedge, tm);
      if(!get(edge_is_feature, e)) { put(edge_is_feature, e, true); ++n; }
    }
  return n;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_FEATURE_LINES_H
