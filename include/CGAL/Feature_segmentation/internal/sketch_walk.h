// SPDX-License-Identifier: GPL-3.0-or-later
// From a sketch (a polyline of points in known faces) to the mesh edges it crosses, for
// feature sketching (paper, Section 4.3): the polyline is followed face to face, each
// step moving to the face nearest to the next sample point among the faces around the
// current one; every edge passed through is crossed.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_SKETCH_WALK_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_SKETCH_WALK_H

#include <CGAL/Feature_segmentation/internal/Segmentation_data.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Sketch_input
{
  std::size_t face;
  Eigen::Vector3d point;
};

struct Sketch_crossing
{
  std::size_t edge;
  Eigen::Vector3d point; // where the sketch crosses the edge (nearest point of the edge)
};

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
inline Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if(d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if(d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if(d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = va + vb + vc;
  if(!(denom > 0)) return a; // degenerate triangle
  return a + (vb / denom) * ab + (vc / denom) * ac;
}

template <typename TriangleMesh>
double mean_edge_length(const Segmentation_data<TriangleMesh>& data)
{
  double sum = 0;
  for(const auto& ev : data.edge_vertices) sum += (data.points[ev.first] - data.points[ev.second]).norm();
  return data.edge_vertices.empty() ? 0. : sum / double(data.edge_vertices.size());
}

// Distance from a sketch point to the face it claims to lie in.
template <typename TriangleMesh>
double distance_to_face(const Segmentation_data<TriangleMesh>& data, const Sketch_input& s)
{
  const auto& idx = data.idx;
  const TriangleMesh& tm = idx.mesh();
  auto h = halfedge(idx.face_at(s.face), tm);
  const Eigen::Vector3d& a = data.points[idx.id(source(h, tm))];
  const Eigen::Vector3d& b = data.points[idx.id(target(h, tm))];
  const Eigen::Vector3d& c = data.points[idx.id(target(next(h, tm), tm))];
  return (closest_point_on_triangle(s.point, a, b, c) - s.point).norm();
}

template <typename TriangleMesh>
std::vector<Sketch_crossing> walk_sketch(const Segmentation_data<TriangleMesh>& data,
                                         const std::vector<Sketch_input>& sketch)
{
  typedef Eigen::Vector3d Vec3;
  const auto& idx = data.idx;
  const TriangleMesh& tm = idx.mesh();
  auto corner = [&](std::size_t f, int i) {
    auto h = halfedge(idx.face_at(f), tm);
    for(int k = 0; k < i; ++k) h = next(h, tm);
    return data.points[idx.id(target(h, tm))];
  };
  auto distance = [&](std::size_t f, const Vec3& p) {
    return (closest_point_on_triangle(p, corner(f, 0), corner(f, 1), corner(f, 2)) - p).squaredNorm();
  };
  auto edge_point = [&](std::size_t e, const Vec3& p) {
    const Vec3& a = data.points[data.edge_vertices[e].first];
    const Vec3& b = data.points[data.edge_vertices[e].second];
    const double l2 = (b - a).squaredNorm();
    const double t = l2 > 0 ? std::max(0., std::min(1., (p - a).dot(b - a) / l2)) : 0.;
    return Vec3(a + t * (b - a));
  };
  std::vector<Sketch_crossing> out;
  std::vector<char> seen(idx.number_of_edges(), 0);
  auto cross = [&](std::size_t e, const Vec3& p) {
    if(seen[e]) return;
    seen[e] = 1;
    out.push_back({e, edge_point(e, p)});
  };
  // Faces reachable from `from` to `to` by a shortest dual path: each edge on it is crossed.
  std::vector<std::size_t> parent_edge(idx.number_of_faces()), visited_stamp(idx.number_of_faces(), 0);
  std::size_t stamp = 0;
  auto connect = [&](std::size_t from, std::size_t to, const Vec3& p) {
    if(from == to) return;
    ++stamp;
    std::deque<std::size_t> q{from};
    visited_stamp[from] = stamp;
    while(!q.empty() && visited_stamp[to] != stamp)
    {
      const std::size_t f = q.front();
      q.pop_front();
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
      {
        const std::size_t g = idx.face_id(opposite(h, tm));
        if(g == Mesh_indexing<TriangleMesh>::npos || visited_stamp[g] == stamp) continue;
        visited_stamp[g] = stamp;
        parent_edge[g] = idx.edge_id(h);
        q.push_back(g);
      }
    }
    if(visited_stamp[to] != stamp) return; // another connected component: nothing crossed
    std::vector<std::size_t> path;
    for(std::size_t f = to; f != from;)
    {
      const std::size_t e = parent_edge[f];
      path.push_back(e);
      auto h = halfedge(idx.edge_at(e), tm);
      const std::size_t f1 = idx.face_id(h), f2 = idx.face_id(opposite(h, tm));
      f = (f1 == f) ? f2 : f1;
    }
    for(auto it = path.rbegin(); it != path.rend(); ++it) cross(*it, p);
  };
  const double step = 0.25 * std::max(1e-300, mean_edge_length(data));
  for(std::size_t i = 0; i + 1 < sketch.size(); ++i)
  {
    const Vec3& pa = sketch[i].point;
    const Vec3& pb = sketch[i + 1].point;
    std::size_t current = sketch[i].face;
    const std::size_t n = std::max<std::size_t>(1, std::size_t(std::ceil((pb - pa).norm() / step)));
    for(std::size_t k = 1; k <= n; ++k)
    {
      const Vec3 s = pa + (pb - pa) * (double(k) / double(n));
      // candidates: the faces sharing a vertex with the current one
      std::size_t best = current;
      double best_d = distance(current, s);
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(current), tm), tm))
        for(auto g : CGAL::faces_around_target(h, tm))
        {
          if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
          const std::size_t gi = idx.id(g);
          const double d = distance(gi, s);
          // on a tie the walk stays where it is (a sample on a vertex is at distance 0 of
          // every face around it) or, between others, takes the smallest id
          if(d < best_d || (d == best_d && best != current && gi < best)) { best = gi; best_d = d; }
        }
      connect(current, best, s);
      current = best;
    }
    connect(current, sketch[i + 1].face, pb);
  }
  return out;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_SKETCH_WALK_H
