// SPDX-License-Identifier: GPL-3.0-or-later
// Triangulation of the quads and polygons of an input mesh, one face at a time. Quads
// follow CGAL's rule (PMP::triangulate_face: the diagonal whose two triangles have the
// larger dot product of their normals). Larger polygons are cut by ear clipping in the
// plane that drops the largest coordinate of their normal, with exact predicates, instead
// of CGAL 5.5's constrained Delaunay triangulation: fuzzing found that on a non-planar
// or self-intersecting polygon the latter reads uninitialised memory and can leave the
// mesh broken while reporting success. Here such a polygon is refused.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_TRIANGULATE_POLYGON_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_TRIANGULATE_POLYGON_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fs_app {
namespace internal {

/// Polygons with more vertices are not triangulated (ear clipping is quadratic).
constexpr std::size_t max_polygon_size = 10000;

/// Splits the face `f` of `mesh` into triangles, appending them to `subfaces` (the first
/// one first). Returns `false`, leaving the face whole, if the face is not a simple
/// polygon in its plane or has more than `max_polygon_size` vertices.
template <typename Mesh>
bool triangulate_polygon(typename boost::graph_traits<Mesh>::face_descriptor f, Mesh& mesh,
                         std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& subfaces)
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;
  const auto vpm = get(CGAL::vertex_point, mesh);

  // The face's halfedges, each standing for its target vertex, from the halfedge into
  // the polygon's first vertex.
  std::vector<halfedge_descriptor> ring;
  for(const halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
  {
    ring.push_back(h);
    if(ring.size() > max_polygon_size)
      return false;
  }
  const std::size_t n = ring.size();
  if(n == 3)
  {
    subfaces.push_back(f);
    return true;
  }

  std::vector<double> x(n), y(n), z(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const auto& p = get(vpm, target(ring[i], mesh));
    x[i] = CGAL::to_double(p.x());
    y[i] = CGAL::to_double(p.y());
    z[i] = CGAL::to_double(p.z());
  }

  if(n == 4)
  {
    // CGAL's choice of diagonal, so that quad meshes triangulate as they always did.
    const auto cross = [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
      // (P_b - P_a) x (P_d - P_c)
      const double u[3] = {x[b] - x[a], y[b] - y[a], z[b] - z[a]};
      const double v[3] = {x[d] - x[c], y[d] - y[c], z[d] - z[c]};
      return std::array<double, 3>{{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
    };
    const auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    // ring[i] runs into vertex i; as in CGAL: p0..p3 = targets of ring[0..3].
    const double p1p3 = dot(cross(1, 2, 2, 3), cross(3, 0, 0, 1));
    const double p0p2 = dot(cross(0, 1, 2, 1), cross(2, 3, 0, 3));
    const halfedge_descriptor h = (p0p2 > p1p3) ? CGAL::Euler::split_face(ring[0], ring[2], mesh)
                                                : CGAL::Euler::split_face(ring[1], ring[3], mesh);
    subfaces.push_back(face(h, mesh));
    subfaces.push_back(face(opposite(h, mesh), mesh));
    return true;
  }

  // The plane that drops the largest coordinate of the (Newell) normal; in it the
  // points are exact copies of two input coordinates, so the predicates below are exact.
  double normal[3] = {0, 0, 0};
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    normal[0] += (y[i] - y[j]) * (z[i] + z[j]);
    normal[1] += (z[i] - z[j]) * (x[i] + x[j]);
    normal[2] += (x[i] - x[j]) * (y[i] + y[j]);
  }
  int drop = 0;
  for(int d = 1; d < 3; ++d)
    if(std::fabs(normal[d]) > std::fabs(normal[drop]))
      drop = d;
  if(!(std::fabs(normal[drop]) > 0))
    return false;
  std::vector<Point_2> q(n);
  for(std::size_t i = 0; i < n; ++i)
    q[i] = drop == 0 ? Point_2(y[i], z[i]) : drop == 1 ? Point_2(z[i], x[i]) : Point_2(x[i], y[i]);
  // Counterclockwise in that plane means the normal's sign along the dropped axis.
  const CGAL::Orientation turn = normal[drop] > 0 ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;

  // Only a simple polygon is triangulated: no two edges meet except consecutive ones at
  // their common vertex, and those do not fold back onto each other. (Ear clipping alone
  // would cut some self-intersecting polygons into overlapping triangles.)
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Segment_2 Segment_2;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Point_2& a = q[i];
    const Point_2& b = q[(i + 1) % n];
    const Point_2& c = q[(i + 2) % n];
    if(CGAL::collinear(a, b, c) && CGAL::angle(a, b, c) != CGAL::OBTUSE)
      return false;
    const Segment_2 edge(a, b);
    for(std::size_t j = i + 2; j < n; ++j)
    {
      if(i == 0 && j == n - 1)
        continue; // the last edge meets the first at vertex 0
      if(CGAL::do_intersect(edge, Segment_2(q[j], q[(j + 1) % n])))
        return false;
    }
  }

  // Ear clipping: a vertex whose corner turns the polygon's way and whose triangle holds
  // no other remaining vertex (not even on its sides) is cut off. A simple polygon always
  // has such an ear; when none is found the polygon is not simple.
  std::vector<std::size_t> left(n);
  for(std::size_t i = 0; i < n; ++i)
    left[i] = i;
  std::vector<std::size_t> ears; // in cutting order: vertex i of each ear
  while(left.size() > 3)
  {
    bool cut = false;
    for(std::size_t k = 0; k < left.size() && !cut; ++k)
    {
      const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k],
                        c = left[(k + 1) % left.size()];
      if(CGAL::orientation(q[a], q[b], q[c]) != turn)
        continue;
      bool empty = true;
      for(const std::size_t m : left)
      {
        if(m == a || m == b || m == c)
          continue;
        const CGAL::Orientation o1 = CGAL::orientation(q[a], q[b], q[m]);
        const CGAL::Orientation o2 = CGAL::orientation(q[b], q[c], q[m]);
        const CGAL::Orientation o3 = CGAL::orientation(q[c], q[a], q[m]);
        if(o1 != -turn && o2 != -turn && o3 != -turn) // inside or on the triangle
        {
          empty = false;
          break;
        }
      }
      if(!empty)
        continue;
      ears.push_back(k);
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      cut = true;
    }
    if(!cut)
      return false;
  }

  // Replays the cuts on the mesh: the ear at position k of the remaining ring is cut off
  // by a new edge between the vertices before and after it.
  for(const std::size_t k : ears)
  {
    const std::size_t m = ring.size();
    const halfedge_descriptor before = ring[(k + m - 1) % m]; // runs into the vertex before
    const halfedge_descriptor after = ring[(k + 1) % m];      // runs into the vertex after
    const halfedge_descriptor h = CGAL::Euler::split_face(before, after, mesh);
    // h runs from the vertex before to the vertex after, on the side of the ear.
    const halfedge_descriptor ear_side = (next(h, mesh) == ring[k]) ? h : opposite(h, mesh);
    subfaces.push_back(face(ear_side, mesh));
    ring[(k + 1) % m] = opposite(ear_side, mesh);
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
  }
  subfaces.push_back(face(ring[0], mesh));
  return true;
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_TRIANGULATE_POLYGON_H
