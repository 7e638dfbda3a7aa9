// SPDX-License-Identifier: GPL-3.0-or-later
// The repairs and checks that turn a file's polygon soup into a mesh, in time linear in
// the soup: points at the same position merged, duplicate faces removed, each edge's
// faces found through a vertex-to-corner table (no map, no sort of the edges), every edge
// checked for more than two faces and for two faces folded onto each other, and each
// vertex checked for a single fan. A soup that passes (the usual case) is built into the
// mesh directly, halfedge by halfedge; one that needs reorienting or has pinched
// vertices is left to CGAL's `orient_polygon_soup` by the caller.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_SOUP_TOPOLOGY_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_SOUP_TOPOLOGY_H

#include "mesh_soup.h"

#include <CGAL/Feature_segmentation/internal/faces_from_corners.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace fs_app {
namespace internal {

constexpr std::uint32_t no_corner = std::uint32_t(-1);

/// For each vertex, the corners (positions in `soup.indices`) at it, in face order.
struct Vertex_corners
{
  std::vector<std::uint32_t> begin;   // size: number of points + 1
  std::vector<std::uint32_t> corners;
  std::vector<std::uint32_t> face_of; // face of each corner

  Vertex_corners(const Mesh_soup& soup, std::size_t n)
  {
    begin.assign(n + 1, 0);
    for(std::uint32_t v : soup.indices)
      ++begin[v + 1];
    for(std::size_t i = 0; i < n; ++i)
      begin[i + 1] += begin[i];
    corners.resize(soup.indices.size());
    face_of.resize(soup.indices.size());
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
      for(std::uint32_t c = soup.begin[f]; c < soup.begin[f + 1]; ++c)
      {
        corners[fill[soup.indices[c]]++] = c;
        face_of[c] = static_cast<std::uint32_t>(f);
      }
  }
};

/// The corner after `c` in its face.
inline std::uint32_t next_corner(const Mesh_soup& soup, const Vertex_corners& vc, std::uint32_t c)
{
  const std::uint32_t f = vc.face_of[c];
  return c + 1 == soup.begin[f + 1] ? soup.begin[f] : c + 1;
}

/// The corner before `c` in its face.
inline std::uint32_t previous_corner(const Mesh_soup& soup, const Vertex_corners& vc, std::uint32_t c)
{
  const std::uint32_t f = vc.face_of[c];
  return c == soup.begin[f] ? soup.begin[f + 1] - 1 : c - 1;
}

/// Merges points at the same position into the first of them: `first_at_position[i]` is
/// the first point with the coordinates of point `i`. Coordinates are finite.
inline std::vector<std::uint32_t> first_at_position(const Mesh_soup& soup)
{
  Position_table table(soup.points, soup.points.size());
  std::vector<std::uint32_t> result(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    result[i] = table.first(static_cast<std::uint32_t>(i));
  return result;
}

/// A face as a key that is the same for every starting vertex and both orientations.
inline std::vector<std::uint32_t> canonical_face(const std::uint32_t* face, std::size_t n)
{
  const std::size_t first = static_cast<std::size_t>(std::min_element(face, face + n) - face);
  std::vector<std::uint32_t> forward(n), backward(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    forward[k] = face[(first + k) % n];
    backward[k] = face[(first + n - k) % n];
  }
  return (std::min)(forward, backward);
}

/// `true` if faces `f` and `g` of `soup` are the same face (up to start and orientation).
inline bool same_face(const Mesh_soup& soup, std::size_t f, std::size_t g)
{
  const std::size_t n = soup.face_size(f);
  if(soup.face_size(g) != n)
    return false;
  if(n == 3)
  {
    std::uint32_t a[3], b[3];
    std::copy(soup.face(f), soup.face(f) + 3, a);
    std::copy(soup.face(g), soup.face(g) + 3, b);
    std::sort(a, a + 3);
    std::sort(b, b + 3);
    return std::equal(a, a + 3, b);
  }
  return canonical_face(soup.face(f), n) == canonical_face(soup.face(g), n);
}

/// For each face, the first face equal to it (itself if it is the first); the faces are
/// looked at by TBB's threads (the same result at any count).
inline std::vector<std::uint32_t> first_equal_face(const Mesh_soup& soup, const Vertex_corners& vc)
{
  std::vector<std::uint32_t> result(soup.number_of_faces());
  CGAL::Feature_segmentation::internal::for_each_range(soup.number_of_faces(), true, 16384,
                                                       [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f)
    {
      result[f] = static_cast<std::uint32_t>(f);
      const std::uint32_t v = *std::min_element(soup.face(f), soup.face(f) + soup.face_size(f));
      for(std::uint32_t k = vc.begin[v]; k < vc.begin[v + 1]; ++k)
      {
        const std::uint32_t g = vc.face_of[vc.corners[k]];
        if(g >= f)
          break; // corners are in face order
        if(same_face(soup, f, g))
        {
          result[f] = g; // the first face equal to f: no earlier one is equal to g either
          break;
        }
      }
    }
  });
  return result;
}

// `true` unless the normals of two faces (of their first three points) make an angle
// clearly below 180 degrees.
template <typename Point>
bool nearly_opposite_normals(const std::vector<Point>& points, const std::uint32_t* f, const std::uint32_t* g)
{
  const auto normal = [&points](const std::uint32_t* face) {
    const Point& a = points[face[0]];
    const Point& b = points[face[1]];
    const Point& c = points[face[2]];
    const double u[3] = {CGAL::to_double(b.x() - a.x()), CGAL::to_double(b.y() - a.y()), CGAL::to_double(b.z() - a.z())};
    const double v[3] = {CGAL::to_double(c.x() - a.x()), CGAL::to_double(c.y() - a.y()), CGAL::to_double(c.z() - a.z())};
    return std::array<double, 3>{{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  };
  const std::array<double, 3> m = normal(f), n = normal(g);
  const double dot = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
  const double mm = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  // Polygons may be non-planar and their first three points collinear: test them exactly.
  return !(dot > -0.5 * std::sqrt(mm * nn)) || mm == 0 || nn == 0;
}

/// What `analyse_edges` found out about a soup without duplicates.
struct Soup_topology
{
  /// For each corner c (the edge from its vertex to the next corner's), the corner of
  /// the face on the other side of that edge, which runs the other way; `no_corner` on
  /// the border.
  std::vector<std::uint32_t> twin;
  bool is_consistently_oriented = true; ///< no edge is run the same way by two faces
  bool has_manifold_vertices = true;    ///< every vertex has one fan of faces
  /// Edges shared by more than two faces (each counted once). The soup is then left to
  /// CGAL's `orient_polygon_soup`, which treats such an edge as a border of each of its
  /// faces and duplicates its vertices, so that the faces come apart along it.
  std::size_t number_of_non_manifold_edges = 0;
};

/// Finds each edge's faces and counts the edges with more than two faces (a repair: see
/// `Soup_topology`). Throws `Input_error` for two faces folded onto each other (coplanar,
/// on the same side of their edge).
template <typename Point>
Soup_topology analyse_edges(const std::string& path, const Mesh_soup& soup,
                            const std::vector<Point>& points, const Vertex_corners& vc)
{
  Soup_topology topology;
  topology.twin.assign(soup.indices.size(), no_corner);
  // The vertex opposite the edge from corner c: for a triangle, its third vertex; for a
  // polygon, the one after the edge, as in the fan that triangulates it.
  // A point of the face of corner c off the line of its edge, searched from the corner
  // after the edge on, as in the fan that triangulates the face (for a triangle, its
  // third point); null if the whole face is on that line, which check_faces excludes.
  const auto apex = [&](std::uint32_t c, const Point& p, const Point& q) -> const Point* {
    const std::uint32_t start = next_corner(soup, vc, c);
    for(std::uint32_t k = next_corner(soup, vc, start); k != start; k = next_corner(soup, vc, k))
      if(!CGAL::collinear(p, q, points[soup.indices[k]]))
        return &points[soup.indices[k]];
    return nullptr;
  };
  // Each corner on its own, by TBB's threads; what they find is gathered in corner
  // order, so that the counts and the first fold (the error) are those of one pass.
  const std::uint32_t none = no_corner;
  struct Found
  {
    std::size_t non_manifold_edges = 0;
    bool inconsistent = false;
    std::uint32_t first_fold = no_corner, fold_other = no_corner;
  };
  const std::size_t corner_count = soup.indices.size();
  const std::size_t chunk = 16384, chunks = (corner_count + chunk - 1) / chunk;
  std::vector<Found> found(chunks);
  CGAL::Feature_segmentation::internal::for_each_range(chunks, true, 1, [&](std::size_t first_chunk, std::size_t last_chunk) {
   for(std::size_t ch = first_chunk; ch < last_chunk; ++ch)
   {
    Found& out = found[ch];
    const std::uint32_t chunk_end = std::uint32_t((std::min)(corner_count, (ch + 1) * chunk));
    for(std::uint32_t c = std::uint32_t(ch * chunk); c < chunk_end && out.first_fold == none; ++c)
    {
      const std::uint32_t a = soup.indices[c];
      const std::uint32_t b = soup.indices[next_corner(soup, vc, c)];
      std::uint32_t faces = 1, other = no_corner;
      bool same_direction = false;
      for(std::uint32_t k = vc.begin[b]; k < vc.begin[b + 1]; ++k) // b -> a elsewhere
      {
        const std::uint32_t d = vc.corners[k];
        if(vc.face_of[d] != vc.face_of[c] && soup.indices[next_corner(soup, vc, d)] == a)
        {
          ++faces;
          other = d;
        }
      }
      for(std::uint32_t k = vc.begin[a]; k < vc.begin[a + 1]; ++k) // a -> b elsewhere
      {
        const std::uint32_t d = vc.corners[k];
        if(d != c && soup.indices[next_corner(soup, vc, d)] == b)
        {
          ++faces;
          other = d;
          same_direction = true;
        }
      }
      if(faces > 2)
      {
        // counted at the corner of its smallest face, so once per edge
        bool first = true;
        for(std::uint32_t k = vc.begin[a]; first && k < vc.begin[a + 1]; ++k)
        {
          const std::uint32_t d = vc.corners[k], n = soup.indices[next_corner(soup, vc, d)];
          first = !(n == b && vc.face_of[d] < vc.face_of[c]);
        }
        for(std::uint32_t k = vc.begin[b]; first && k < vc.begin[b + 1]; ++k)
        {
          const std::uint32_t d = vc.corners[k], n = soup.indices[next_corner(soup, vc, d)];
          first = !(n == a && vc.face_of[d] < vc.face_of[c]);
        }
        if(first) ++out.non_manifold_edges;
        out.inconsistent = true; // no twins: CGAL's orientation builds the mesh
        continue;
      }
      if(faces < 2)
        continue;
      if(same_direction)
        out.inconsistent = true;
      else
        topology.twin[c] = other;
      // Two faces folded onto each other have opposite normals; only a pair whose double
      // normals are close to opposite needs the exact test.
      if(c < other && nearly_opposite_normals(points, soup.face(vc.face_of[c]), soup.face(vc.face_of[other])))
      {
        const Point& p = points[a];
        const Point& q = points[b];
        const Point* r = apex(c, p, q);
        const Point* s = apex(other, p, q);
        if(r != nullptr && s != nullptr && CGAL::coplanar(p, q, *r, *s) &&
           CGAL::coplanar_orientation(p, q, *r, *s) == CGAL::POSITIVE)
        {
          out.first_fold = c;
          out.fold_other = other;
        }
      }
    }
   }
  });
  for(const Found& out : found)
  {
    if(out.first_fold != none)
      throw Input_error(path + ": " + face_name(soup, vc.face_of[out.first_fold]) + " and " +
                        face_name(soup, vc.face_of[out.fold_other]) +
                        " overlap (folded onto each other across an edge)");
    topology.number_of_non_manifold_edges += out.non_manifold_edges;
    if(out.inconsistent) topology.is_consistently_oriented = false;
  }
  if(!topology.is_consistently_oriented)
    return topology;

  // one fan per vertex (the corners at each vertex: vc)
  topology.has_manifold_vertices = CGAL::Feature_segmentation::internal::every_vertex_has_one_fan(
    vc.begin.size() - 1, [&](std::size_t v) { return vc.begin[v]; }, [&](std::size_t k) { return vc.corners[k]; },
    [&](std::size_t c) { return next_corner(soup, vc, std::uint32_t(c)); },
    [&](std::size_t c) { return previous_corner(soup, vc, std::uint32_t(c)); },
    [&](std::size_t c) { return std::size_t(topology.twin[c]); }, std::size_t(no_corner), true);
  return topology;
}

/// Builds `mesh` from a soup that `analyse_edges` found consistently oriented with
/// manifold vertices: point i becomes the i-th vertex, face f the f-th face.
template <typename Mesh, typename Point>
void build_mesh(const Mesh_soup& soup, const std::vector<Point>& points,
                const Soup_topology& topology, Mesh& mesh,
                std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& vertex_of_point,
                std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& face_of_polygon)
{
  mesh.clear();
  std::size_t number_of_edges = 0;
  for(std::uint32_t t : topology.twin)
    number_of_edges += (t == no_corner) ? 2 : 1; // a twin pair is counted twice
  reserve(mesh, points.size(), number_of_edges / 2, soup.number_of_faces());

  auto vpm = get(CGAL::vertex_point, mesh);
  vertex_of_point.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    vertex_of_point[i] = add_vertex(mesh);
    put(vpm, vertex_of_point[i], points[i]);
  }

  // the faces (and their halfedges and edges), then the border, as Euler::add_face
  CGAL::Feature_segmentation::internal::add_faces_from_corners(
    mesh, vertex_of_point, soup.number_of_faces(), [&](std::size_t f) { return soup.begin[f]; },
    [&](std::size_t c) { return soup.indices[c]; }, [&](std::size_t c) { return std::size_t(topology.twin[c]); },
    std::size_t(no_corner), face_of_polygon);
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_SOUP_TOPOLOGY_H
