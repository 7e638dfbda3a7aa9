// SPDX-License-Identifier: GPL-3.0-or-later
// Per-face patches from the boundary state: the area of every patch inside a triangle
// (for the majority rule), and the triangles of a refinement of the mesh in which the
// boundaries are chains of edges (cut edges split at their points or snapped to an end,
// triangles split along the boundary inside them).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_REFINEMENT_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_REFINEMENT_IMPL_H

#include <CGAL/Feature_segmentation/internal/boundary_state.h>
#include <CGAL/Feature_segmentation/internal/face_patch_rule.h>

#include <CGAL/assertions.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The patch covering most of face f's area under the boundaries of `s` (the one rule,
// face_patch_rule.h).
template <typename TriangleMesh>
std::size_t majority_patch(const Boundary_state<TriangleMesh>& s, std::size_t f)
{
  const auto& v = s.face_vertices[f];
  if(!s.has_cut_edges(f)) return s.labels[v[0]];
  std::array<Eigen::Vector3d, 3> edge_point;
  for(int k = 0; k < 3; ++k)
    if(s.is_cut(s.face_edges[f][k])) edge_point[k] = s.edge_point(s.face_edges[f][k]);
  return area_majority_patch({ s.labels[v[0]], s.labels[v[1]], s.labels[v[2]] },
                             { s.points[v[0]], s.points[v[1]], s.points[v[2]] }, edge_point, s.face_x[f]);
}

// The refinement as a list of points and patch-labelled triangles (indices into the
// points; the input's vertices first, in vertex id order).
struct Refinement
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<Compact_index, 3> > triangles;
  std::vector<std::size_t> patches; // the user's patch ids: any std::size_t
  std::size_t split_faces = 0;
};

template <typename TriangleMesh>
Refinement refine_along_boundaries(const Boundary_state<TriangleMesh>& s, double delta)
{
  typedef Eigen::Vector3d Vec3;
  const std::size_t npos = std::size_t(-1);
  Refinement r;
  // points: at most a new one per edge and per face
  check_compact_index_range(s.number_of_vertices() + s.number_of_edges() + s.number_of_faces());
  // The arrays are sized once (a face with cut edges gives at most one point and six
  // triangles): a growing array would be copied into fresh memory several times.
  std::size_t cut_edges = 0, cut_faces = 0;
  for(std::size_t e = 0; e < s.number_of_edges(); ++e) cut_edges += s.is_cut(e) ? 1 : 0;
  for(std::size_t f = 0; f < s.number_of_faces(); ++f) cut_faces += s.has_cut_edges(f) ? 1 : 0;
  r.points.reserve(s.number_of_vertices() + cut_edges + cut_faces);
  r.points.assign(s.points.begin(), s.points.end());
  r.triangles.reserve(s.number_of_faces() + 5 * cut_faces);
  r.patches.reserve(s.number_of_faces() + 5 * cut_faces);
  // Every cut edge: a new vertex at its point, or the end it snaps to.
  std::vector<std::size_t> edge_node(s.number_of_edges(), npos);
  for(std::size_t e = 0; e < s.number_of_edges(); ++e)
  {
    if(!s.is_cut(e)) continue;
    const double t = s.edge_t[e];
    if(t < delta) edge_node[e] = s.edge_vertices[e][0];
    else if(t > 1 - delta) edge_node[e] = s.edge_vertices[e][1];
    else { edge_node[e] = r.points.size(); r.points.push_back(s.edge_point(e)); }
  }
  const std::size_t nv = s.number_of_vertices();
  auto position = [&](std::size_t i) -> const Vec3& { return r.points[i]; };
  auto twice_area = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (position(b) - position(a)).cross(position(c) - position(a)).norm();
  };
  // smallest angle of a triangle (its sine, up to the triangle's scale: 2 area / (longest side)^2)
  auto quality = [&](std::size_t a, std::size_t b, std::size_t c) {
    const double l = (std::max)({ (position(b) - position(a)).squaredNorm(), (position(c) - position(b)).squaredNorm(),
                                  (position(a) - position(c)).squaredNorm() });
    return l > 0 ? twice_area(a, b, c) / l : 0.;
  };
  // Triangulates a convex polygon whose vertices lie on the sides of a triangle and on
  // one chord: the fan, among those from each vertex, whose worst triangle is best (a
  // fan from a vertex collinear with one of the polygon's edges has a flat triangle).
  auto triangulate = [&](const std::vector<std::size_t>& poly, std::size_t patch) {
    const std::size_t n = poly.size();
    std::size_t best_apex = 0;
    double best = -1;
    for(std::size_t a = 0; a < n; ++a)
    {
      double worst = 1e300;
      for(std::size_t i = 1; i + 1 < n; ++i)
        worst = (std::min)(worst, quality(poly[a], poly[(a + i) % n], poly[(a + i + 1) % n]));
      if(worst > best) { best = worst; best_apex = a; }
    }
    for(std::size_t i = 1; i + 1 < n; ++i)
    {
      r.triangles.push_back({ poly[best_apex], poly[(best_apex + i) % n], poly[(best_apex + i + 1) % n] });
      r.patches.push_back(patch);
    }
  };

  for(std::size_t f = 0; f < s.number_of_faces(); ++f)
  {
    const auto& v = s.face_vertices[f];
    std::array<std::size_t, 3> cut;
    const int n = s.cut_edges(f, cut);
    if(n == 0)
    {
      r.triangles.push_back(v);
      r.patches.push_back(s.labels[v[0]]);
      continue;
    }
    // The boundary polygon of the face: corners and split points, with the patch of
    // every polygon edge (the side of the boundary it lies on).
    std::vector<std::size_t> poly, edge_patch;
    std::array<std::size_t, 3> end_of_edge; // per side k: the boundary's end on it
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t e = s.face_edges[f][k], a = v[k], b = v[(k + 1) % 3];
      poly.push_back(a);
      end_of_edge[k] = npos;
      if(!s.is_cut(e)) { edge_patch.push_back(s.labels[a]); continue; }
      const std::size_t node = edge_node[e];
      end_of_edge[k] = node;
      if(node == a) edge_patch.push_back(s.labels[b]);
      else if(node == b) edge_patch.push_back(s.labels[a]);
      else
      {
        edge_patch.push_back(s.labels[a]);
        poly.push_back(node);
        edge_patch.push_back(s.labels[b]);
      }
    }
    const std::size_t first_triangle = r.triangles.size();
    // The face's point: kept at a junction (moved inside so that its barycentric
    // coordinates are >= delta); kept in a through triangle where the boundary bends
    // there by more than delta of the chord's length and it lies delta inside.
    bool keep_x = (n == 3);
    Vec3 x = s.face_x[f];
    if(n == 3) x = s.keep_inside(f, x, (std::min)(delta, 0.3));
    else
    {
      std::array<std::size_t, 2> ends;
      int found = 0;
      for(int k = 0; k < 3; ++k) if(end_of_edge[k] != npos) ends[found++] = end_of_edge[k];
      const Vec3 p = position(ends[0]), q = position(ends[1]);
      const double chord = (q - p).norm();
      const std::array<double, 3> w = s.barycentric(f, x);
      const double inside = (std::min)(w[0], (std::min)(w[1], w[2]));
      const double bend = chord > 0 ? (x - p).cross(q - p).norm() / chord : 0.;
      keep_x = chord > 0 && inside >= delta && inside > 0 && bend >= delta * chord && bend > 0;
    }
    if(keep_x)
    {
      const std::size_t xi = r.points.size();
      r.points.push_back(x);
      const std::size_t m = poly.size();
      for(std::size_t i = 0; i < m; ++i)
      {
        r.triangles.push_back({ xi, poly[i], poly[(i + 1) % m] });
        r.patches.push_back(edge_patch[i]);
      }
      ++r.split_faces;
      continue;
    }
    // A through triangle cut straight by the chord between its two boundary ends.
    std::size_t ea = npos, eb = npos;
    for(int k = 0; k < 3; ++k)
      if(end_of_edge[k] != npos) { if(ea == npos) ea = end_of_edge[k]; else eb = end_of_edge[k]; }
    const std::size_t ia = std::size_t(std::find(poly.begin(), poly.end(), ea) - poly.begin());
    const std::size_t ib = std::size_t(std::find(poly.begin(), poly.end(), eb) - poly.begin());
    const std::size_t m = poly.size();
    std::vector<std::size_t> sides[2];
    std::size_t side_patch[2] = { edge_patch[ia], edge_patch[ib] };
    if(ea != eb)
    {
      for(std::size_t i = ia;; i = (i + 1) % m) { sides[0].push_back(poly[i]); if(i == ib) break; }
      for(std::size_t i = ib;; i = (i + 1) % m) { sides[1].push_back(poly[i]); if(i == ia) break; }
    }
    int kept = 0;
    for(int k = 0; k < 2; ++k)
    {
      if(sides[k].size() < 3) continue;
      double a = 0;
      for(std::size_t i = 1; i + 1 < sides[k].size(); ++i) a += twice_area(sides[k][0], sides[k][i], sides[k][i + 1]);
      if(!(a > 0)) continue; // the chord runs along a side of the triangle
      triangulate(sides[k], side_patch[k]);
      ++kept;
    }
    if(kept == 0)
    {
      // the boundary only touches the triangle at a vertex: all of it on one side
      std::size_t patch = edge_patch[0];
      for(std::size_t i = 0; i < m; ++i)
        if(poly[i] < nv && end_of_edge[0] != poly[i] && end_of_edge[1] != poly[i] && end_of_edge[2] != poly[i])
          patch = s.labels[poly[i]];
      triangulate(poly, patch);
    }
    if(r.triangles.size() - first_triangle > 1) ++r.split_faces;
  }
  return r;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_REFINEMENT_IMPL_H
