// SPDX-License-Identifier: GPL-3.0-or-later
// The work behind the edge weights (paper, Section 3.2, Eq. 3-6): dual vertices, the
// per-triangle anisotropic tensors and the two lengths of every edge's dual segment,
// Similarity (anisotropic metric) and Award (Euclidean metric). They depend on the mesh,
// the curvatures, the feature points and gamma, never on alpha: an alpha edit only
// recombines them, w(e) = Similarity(e) - alpha_e * Award(e).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_EDGE_WEIGHTS_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_EDGE_WEIGHTS_IMPL_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/compact_index.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The anisotropic metric of one triangle, in an orthonormal basis (u, v) of its plane:
// length^2 of a tangent vector x = (x.e1)^2 + lambda2 (x.e2)^2 (Eq. 4 and 6).
struct Triangle_metric
{
  Eigen::Vector3d u = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero(); // plane basis; zero if degenerate
  Eigen::Vector2d e1 = Eigen::Vector2d(1, 0), e2 = Eigen::Vector2d(0, 1);   // metric eigenvectors
  double lambda2 = 1.;
  double anisotropy = 0.; // s = |k1| - |k2| of the triangle

  bool is_degenerate() const { return u.squaredNorm() == 0; }
  // Euclidean length of the projection of w on the plane
  double euclidean(const Eigen::Vector3d& w) const
  {
    if(is_degenerate()) return w.norm();
    return std::hypot(w.dot(u), w.dot(v));
  }
  double anisotropic(const Eigen::Vector3d& w) const
  {
    if(is_degenerate()) return w.norm();
    const Eigen::Vector2d x(w.dot(u), w.dot(v));
    const double a = x.dot(e1), b = x.dot(e2);
    return std::sqrt(a * a + lambda2 * b * b);
  }
};

// Inputs per vertex: position and curvature tensor pieces (k1, k2, d1, d2).
struct Vertex_tensor_input
{
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  double k1 = 0, k2 = 0;
  Eigen::Vector3d d1 = Eigen::Vector3d::Zero(), d2 = Eigen::Vector3d::Zero();
};

// What the features decide (a sketch changes it; the editing engine shares one between
// its states until a sketch makes a new one): the feature edges and the feature points
// on them, the dual vertices, Similarity and Award.
struct Feature_terms
{
  typedef Eigen::Vector3d Vec3;

  std::vector<char> is_feature_edge;     // per edge (and crease tie)
  // The feature points on the edges, as a sum and a count per edge that has any: a few
  // edges of the mesh, so the sums are kept for those edges only.
  std::vector<Compact_index> point_slot; // per edge: its entry in point_sum, or none
  std::vector<Vec3> point_sum;           // per entry: sum of the edge's feature points
  std::vector<int> point_count;          // per entry: their number
  std::size_t number_of_feature_edges = 0;
  std::vector<Vec3> dual_vertices;       // per face
  std::vector<double> similarity, award; // per edge (and crease tie)

  // w(e) = Similarity(e) - alpha_e Award(e), Eq. 3.
  double weight(std::size_t e, double alpha_e) const { return similarity[e] - alpha_e * award[e]; }

  // No feature point on any of `number_of_edges` edges.
  void clear_points(std::size_t number_of_edges)
  {
    point_slot.assign(number_of_edges, std::size_t(-1));
    point_sum.clear();
    point_count.clear();
  }
  void add_point(std::size_t e, const Vec3& p)
  {
    std::size_t k = point_slot[e];
    if(k == std::size_t(-1))
    {
      k = point_sum.size();
      point_slot[e] = k;
      point_sum.push_back(Vec3::Zero());
      point_count.push_back(0);
    }
    point_sum[k] += p;
    ++point_count[k];
  }
  bool has_points(std::size_t e) const { return e < point_slot.size() && point_slot[e] != std::size_t(-1); }
  // The centroid of the feature points of `e` (which has some).
  Vec3 mean_point(std::size_t e) const
  {
    const std::size_t k = point_slot[e];
    return Vec3(point_sum[k] / point_count[k]);
  }

  std::size_t memory() const
  {
    return is_feature_edge.capacity() + point_slot.capacity() * sizeof(Compact_index) +
           point_sum.capacity() * sizeof(Vec3) + point_count.capacity() * sizeof(int) +
           dual_vertices.capacity() * sizeof(Vec3) + (similarity.capacity() + award.capacity()) * sizeof(double);
  }
};

// The computations of the terms, on the per-face metrics and the features' points.
template <typename TriangleMesh>
struct Edge_weight_terms
{
  typedef Mesh_indexing<TriangleMesh> Indexing;
  typedef Eigen::Vector3d Vec3;

  // The metrics of every face, then the dual vertices and terms of `f` (whose feature
  // edges and points are set). `curvature_scale`: the length by which curvatures are
  // multiplied before gamma applies.
  static void compute(const Indexing& idx, const std::vector<Vertex_tensor_input>& vin,
                      const std::vector<Vec3>& points, double gamma,
                      double curvature_scale, std::vector<Triangle_metric>& metrics, Feature_terms& f,
                      bool parallel = false)
  {
    const TriangleMesh& tm = idx.mesh();
    const std::size_t nf = idx.number_of_faces(), ne = idx.number_of_edges();
    metrics.assign(nf, Triangle_metric());
    f.dual_vertices.assign(nf, Vec3::Zero());
    for_each_range(nf, parallel, 4096, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
      {
        auto h = halfedge(idx.face_at(i), tm);
        metrics[i] = triangle_metric(vin[idx.id(source(h, tm))], vin[idx.id(target(h, tm))],
                                     vin[idx.id(target(next(h, tm), tm))], gamma, curvature_scale);
        f.dual_vertices[i] = dual_vertex(idx, points, f, i);
      }
    });
    f.similarity.assign(ne, 0.);
    f.award.assign(ne, 0.);
    for_each_range(ne, parallel, 4096, [&](std::size_t first, std::size_t last) {
      for(std::size_t e = first; e < last; ++e) edge_terms(idx, points, metrics, f, e);
    });
  }

  // After the features of some edges changed (a sketch): the dual vertices of `faces`
  // and the terms of their edges.
  static void update_faces(const Indexing& idx, const std::vector<Vec3>& points,
                           const std::vector<Triangle_metric>& metrics, Feature_terms& f,
                           const std::vector<std::size_t>& faces)
  {
    const TriangleMesh& tm = idx.mesh();
    for(std::size_t i : faces)
      f.dual_vertices[i] = dual_vertex(idx, points, f, i);
    for(std::size_t i : faces)
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(i), tm), tm))
        edge_terms(idx, points, metrics, f, idx.edge_id(h));
  }

  // Dual vertex: centroid of the feature points on the face's feature edges, if any (a
  // feature edge without located points contributes its midpoint), else the centroid.
  static Vec3 dual_vertex(const Indexing& idx, const std::vector<Vec3>& points,
                          const Feature_terms& ft, std::size_t f)
  {
    const TriangleMesh& tm = idx.mesh();
    Vec3 sum = Vec3::Zero(), centroid = Vec3::Zero();
    int count = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
    {
      centroid += points[idx.id(target(h, tm))] / 3.;
      const std::size_t e = idx.edge_id(h);
      if(!ft.is_feature_edge[e]) continue;
      sum += ft.has_points(e) ? ft.mean_point(e)
                                   : Vec3(0.5 * (points[idx.id(source(h, tm))] + points[idx.id(target(h, tm))]));
      ++count;
    }
    return count > 0 ? Vec3(sum / count) : centroid;
  }

  static void edge_terms(const Indexing& idx, const std::vector<Vec3>& points,
                         const std::vector<Triangle_metric>& metrics, Feature_terms& ft, std::size_t e)
  {
    const TriangleMesh& tm = idx.mesh();
    auto h = halfedge(idx.edge_at(e), tm);
    const std::size_t f1 = idx.face_id(h), f2 = idx.face_id(opposite(h, tm));
    ft.similarity[e] = ft.award[e] = 0.;
    if(f1 != Indexing::npos && f2 != Indexing::npos)
    {
      const Vec3 w = ft.dual_vertices[f2] - ft.dual_vertices[f1];
      ft.similarity[e] = 0.5 * (metrics[f1].anisotropic(w) + metrics[f2].anisotropic(w));
      ft.award[e] = 0.5 * (metrics[f1].euclidean(w) + metrics[f2].euclidean(w));
      return;
    }
    // Border edge: a boundary cutting it runs from the dual vertex of its one face to the
    // edge; the half segment from the dual vertex to the edge's feature point (or
    // midpoint) takes the place of the dual segment.
    const std::size_t f = (f1 != Indexing::npos) ? f1 : f2;
    if(f == Indexing::npos) return; // an isolated edge: no face, weight 0
    const Vec3 end = ft.has_points(e)
                       ? ft.mean_point(e)
                       : Vec3(0.5 * (points[idx.id(source(h, tm))] + points[idx.id(target(h, tm))]));
    const Vec3 w = end - ft.dual_vertices[f];
    ft.similarity[e] = metrics[f].anisotropic(w);
    ft.award[e] = metrics[f].euclidean(w);
  }

  // Per-triangle tensor: the vertices' curvature tensors k1 d1 d1^T + k2 d2 d2^T are
  // averaged (tensors, unlike directions, have no sign ambiguity), restricted to the
  // triangle's plane and diagonalised there.
  static Triangle_metric triangle_metric(const Vertex_tensor_input& a, const Vertex_tensor_input& b,
                                         const Vertex_tensor_input& c, double gamma, double scale)
  {
    Triangle_metric m;
    const Vec3 n = (b.p - a.p).cross(c.p - a.p);
    const double len = n.norm();
    if(!(len > 0) || !std::isfinite(len))
      return m; // degenerate: Euclidean (documented), so Similarity = Award
    const Vec3 nn = n / len;
    m.u = (b.p - a.p).normalized();
    m.v = nn.cross(m.u);
    Eigen::Matrix3d T = Eigen::Matrix3d::Zero();
    for(const Vertex_tensor_input* x : {&a, &b, &c})
      T += x->k1 * x->d1 * x->d1.transpose() + x->k2 * x->d2 * x->d2.transpose();
    T /= 3.;
    Eigen::Matrix<double, 3, 2> B;
    B.col(0) = m.u; B.col(1) = m.v;
    const Eigen::Matrix2d S = B.transpose() * T * B;
    const double mean = 0.5 * (S(0, 0) + S(1, 1));
    const double radius = std::sqrt(0.25 * (S(0, 0) - S(1, 1)) * (S(0, 0) - S(1, 1)) + S(0, 1) * S(0, 1));
    const double lp = mean + radius, lm = mean - radius;
    const double theta = 0.5 * std::atan2(2. * S(0, 1), S(0, 0) - S(1, 1));
    Eigen::Vector2d dp(std::cos(theta), std::sin(theta)), dm(-std::sin(theta), std::cos(theta));
    const bool plus_first = std::abs(lp) >= std::abs(lm);
    const double k1 = plus_first ? lp : lm, k2 = plus_first ? lm : lp;
    m.e1 = plus_first ? dp : dm;
    m.e2 = plus_first ? dm : dp;
    m.anisotropy = (std::abs(k1) - std::abs(k2)) * scale;
    const double q = 1. + gamma * m.anisotropy;
    m.lambda2 = 1. / (q * q);
    return m;
  }

};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_EDGE_WEIGHTS_IMPL_H
