// SPDX-License-Identifier: GPL-3.0-or-later
// Creases of heavily noisy meshes that are steps of a smooth turn. The bilateral filter
// of the face normals (crease_detection.h) gathers the steady turn of a curved face
// whose facets bend by nearly the crease angle (a torus or tube some twenty facets
// round) into flat strips and steps far steeper than the crease angle, which no angle
// test can tell from creases. Two views of the same normals tell them apart:
// - the normals filtered along their gradient (filter_face_normals_along_gradient()):
//   each face carries its neighbours' normals back along the gradient it fits over its
//   ring before averaging them, so a steady turn stays smooth and its steps do not form;
//   but a moderate crease that turns the way its curved side curves (a barrel meeting
//   its end disk) looks like more of the same turn and fades;
// - the steps themselves: a step of a smooth turn has another step nearly parallel to
//   it on both sides within a few edge lengths (staircase_creases()), a crease at most
//   on one side (a rib's or a thin wall's other crease).
// A heavily noisy mesh keeps the creases of the gradient-filtered normals and those of
// the bilateral filter that are not staircase steps (detect_creases()).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_STAIRCASE_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_STAIRCASE_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the gradient filter and the staircase test, chosen on the 30
// development parts and the generated ones at 0.1% and 0.3% noise (manual, Creases).
struct Crease_staircase
{
  // The raw roughness (normal_roughness) from which a noisy mesh gets the rule: heavy
  // noise (0.3% of the diagonal: 0.1 to 0.22); from 0 on, light noise (0.035 to 0.1)
  // loses narrow faces (the knurls of CAD part 30419 at 0.1% noise: F 0.98 -> 0.90).
  static constexpr double roughness = 0.08;
  // The gradient fit's ridge, as a share of the ring's spatial weights (in coordinates
  // of centroid spacings), and the most the gradient turns the normal per spacing.
  static constexpr double ridge = 0.03;
  static constexpr double gradient_cap = 0.3;
  // A step's neighbours: candidates whose direction is within acos(0.85) (32 degrees)
  // of it, at 0.5 to `reach` mean edge lengths across it and within 1.5 along it.
  static constexpr double parallel_cosine = 0.85;
  static constexpr double reach = 4.;
};

// The spatial weights of the normal filters (filter_face_normals(),
// filter_face_normals_along_gradient()), fixed over their rounds: for every pair of a
// face f and a face g of its ring (`begin`, `ring`: CSR), g's area times a Gaussian of
// their centroids' distance whose sigma, `spacing`, is the mean distance between the
// centroids of such pairs (1 without any).
inline std::vector<double> normal_filter_spatial_weights(const std::vector<double>& area,
                                                         const std::vector<Eigen::Vector3d>& centroid,
                                                         const std::vector<std::uint32_t>& begin,
                                                         const std::vector<std::uint32_t>& ring, double& spacing)
{
  const std::size_t nf = area.size();
  double sum = 0;
  std::size_t count = 0;
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
      if(ring[i] != f) { sum += (centroid[f] - centroid[ring[i]]).norm(); ++count; }
  spacing = count > 0 ? sum / double(count) : 1.;
  const double inv_s = spacing > 0 ? 1. / (2 * spacing * spacing) : 0.;
  std::vector<double> spatial(ring.size());
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
      spatial[i] = area[ring[i]] * std::exp(-(centroid[f] - centroid[ring[i]]).squaredNorm() * inv_s);
  return spatial;
}

// Face normals filtered as filter_face_normals() does (`rounds` rounds, range parameter
// `sigma_r`, the same spatial Gaussian), but along their gradient: each round, face f
// fits the gradient G of the normals over its ring (n_g - n_f ~ G d_g, d_g the
// centroid offset in f's tangent plane in units of the mean centroid spacing, weighted
// by the bilateral weights, with the ridge Crease_staircase::ridge and the norm of G at
// most Crease_staircase::gradient_cap), then averages the carried normals n_g - G d_g
// with the spatial and range weights, the range Gaussian on n_g - G d_g - n_f. Each face
// reads the previous round only: the same result at any thread count.
inline std::vector<Eigen::Vector3d> filter_face_normals_along_gradient(const std::vector<Eigen::Vector3d>& normal,
                                                                       const std::vector<double>& area,
                                                                       const std::vector<Eigen::Vector3d>& centroid,
                                                                       const std::vector<std::uint32_t>& begin,
                                                                       const std::vector<std::uint32_t>& ring,
                                                                       int rounds, double sigma_r, bool parallel = false)
{
  const std::size_t nf = normal.size();
  const double inv_r = 1. / (2 * sigma_r * sigma_r);
  double spacing = 0;
  const std::vector<double> spatial = normal_filter_spatial_weights(area, centroid, begin, ring, spacing);
  std::vector<Eigen::Vector3d> n = normal, next(nf);
  for(int it = 0; it < rounds; ++it)
  {
    for_each_range(nf, parallel, 1024, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
      {
        if(n[f].squaredNorm() == 0) { next[f] = n[f]; continue; }
        // f's tangent frame
        const Eigen::Vector3d& nf0 = n[f];
        Eigen::Vector3d u = std::abs(nf0.x()) < 0.9 ? Eigen::Vector3d::UnitX().cross(nf0)
                                                     : Eigen::Vector3d::UnitY().cross(nf0);
        u.normalize();
        const Eigen::Vector3d v = nf0.cross(u);
        auto offset = [&](std::size_t g) {
          const Eigen::Vector3d d = centroid[g] - centroid[f];
          return Eigen::Vector2d(d.dot(u) / spacing, d.dot(v) / spacing);
        };
        // the gradient, by weighted least squares with a ridge
        Eigen::Matrix2d dd = Eigen::Matrix2d::Zero();
        Eigen::Matrix<double, 3, 2> nd = Eigen::Matrix<double, 3, 2>::Zero();
        double weights = 0;
        for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
        {
          const std::size_t g = ring[i];
          weights += spatial[i];
          if(g == f || n[g].squaredNorm() == 0) continue;
          const double w = spatial[i] * std::exp(-(n[f] - n[g]).squaredNorm() * inv_r);
          const Eigen::Vector2d d = offset(g);
          dd += w * d * d.transpose();
          nd += w * (n[g] - n[f]) * d.transpose();
        }
        dd += Crease_staircase::ridge * weights * Eigen::Matrix2d::Identity();
        Eigen::Matrix<double, 3, 2> gradient = nd * dd.inverse();
        const double norm = gradient.norm();
        if(norm > Crease_staircase::gradient_cap) gradient *= Crease_staircase::gradient_cap / norm;
        // the carried normals, averaged
        Eigen::Vector3d m = Eigen::Vector3d::Zero();
        for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
        {
          const std::size_t g = ring[i];
          if(n[g].squaredNorm() == 0) continue;
          const Eigen::Vector3d carried = n[g] - gradient * offset(g);
          m += spatial[i] * std::exp(-(carried - n[f]).squaredNorm() * inv_r) * carried;
        }
        const double len = m.norm();
        next[f] = len > 0 && std::isfinite(len) ? Eigen::Vector3d(m / len) : n[f];
      }
    });
    n.swap(next);
  }
  return n;
}

// Per edge of the mesh of `idx`, whether it is a candidate (nonzero in `candidate`) with
// another candidate nearly parallel to it on both sides (Crease_staircase): the
// candidates met on the faces reached from its two faces across edges, staying within
// `reach` mean edge lengths across it and two along it (a search ends once both sides
// have one); `normal`: unit face normals (the across direction is the edge's direction
// times the sum of its faces' normals), `centroid`: the faces'; the candidates by TBB's
// threads if `parallel`.
template <typename TriangleMesh, typename VPM>
std::vector<char> staircase_creases(const Mesh_indexing<TriangleMesh>& idx, VPM vpm, const std::vector<char>& candidate,
                                    const std::vector<Eigen::Vector3d>& normal,
                                    const std::vector<Eigen::Vector3d>& centroid, bool parallel = false)
{
  typedef Crease_staircase Limits;
  typedef std::uint32_t Id; // detect_creases() has checked that 3 ids per face fit
  const TriangleMesh& tm = idx.mesh();
  const std::size_t ne = idx.number_of_edges(), nf = idx.number_of_faces();
  const Id none = Id(-1);
  // every edge's midpoint and unit direction, every face's edges and the faces across them
  std::vector<Eigen::Vector3d> middle(ne), direction(ne);
  double sum = 0;
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    const auto& p = get(vpm, source(h, tm));
    const auto& q = get(vpm, target(h, tm));
    const Eigen::Vector3d a(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    const Eigen::Vector3d b(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
    middle[e] = 0.5 * (a + b);
    direction[e] = b - a;
    const double len = direction[e].norm();
    sum += len;
    if(len > 0) direction[e] /= len;
  }
  std::vector<Id> face_edge(3 * nf, none), across(3 * nf, none);
  for(std::size_t f = 0; f < nf; ++f)
  {
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
    {
      if(k == 3) break;
      const std::size_t g = idx.face_id(opposite(h, tm));
      face_edge[3 * f + k] = Id(idx.edge_id(h));
      across[3 * f + k] = g == idx.npos ? none : Id(g);
      ++k;
    }
  }
  const double w = ne > 0 ? sum / double(ne) : 0.;
  std::vector<std::size_t> candidates;
  for(std::size_t e = 0; e < ne; ++e)
    if(candidate[e]) candidates.push_back(e);
  std::vector<char> out(ne, 0);
  // each candidate on its own (its search reads `candidate` only): the same at any
  // thread count
  for_each_range(candidates.size(), parallel, 64, [&](std::size_t first, std::size_t last) {
    std::vector<char> mark(nf, 0);
    std::vector<Id> stack, seen;
    for(std::size_t c = first; c < last; ++c)
    {
      const std::size_t e = candidates[c];
      const auto h = halfedge(idx.edge_at(e), tm);
      const std::size_t f = idx.face_id(h), g = idx.face_id(opposite(h, tm));
      if(f == idx.npos || g == idx.npos) continue;
      const Eigen::Vector3d& m = middle[e];
      const Eigen::Vector3d& t = direction[e];
      const Eigen::Vector3d up = normal[f] + normal[g];
      if(!(t.squaredNorm() > 0) || !(up.norm() > 0)) continue;
      Eigen::Vector3d side_direction = t.cross(up);
      if(!(side_direction.norm() > 0)) continue;
      side_direction.normalize();
      bool side[2] = { false, false };
      stack.assign({ Id(f), Id(g) });
      seen = stack;
      mark[f] = mark[g] = 1;
      while(!stack.empty() && !(side[0] && side[1]))
      {
        const Id x = stack.back();
        stack.pop_back();
        for(int k = 0; k < 3; ++k)
        {
          const Id e2 = face_edge[3 * x + k];
          if(e2 != e && candidate[e2])
          {
            const Eigen::Vector3d d = middle[e2] - m;
            const double s = d.dot(side_direction);
            if(std::abs(direction[e2].dot(t)) >= Limits::parallel_cosine && std::abs(s) >= 0.5 * w &&
               std::abs(d.dot(t)) <= 1.5 * w)
              side[s > 0 ? 0 : 1] = true;
          }
          const Id y = across[3 * x + k];
          if(y == none || mark[y]) continue;
          const Eigen::Vector3d d = centroid[y] - m;
          if(std::abs(d.dot(side_direction)) > Limits::reach * w || std::abs(d.dot(t)) > 2 * w) continue;
          mark[y] = 1;
          seen.push_back(y);
          stack.push_back(y);
        }
      }
      for(Id x : seen) mark[x] = 0;
      out[e] = side[0] && side[1];
    }
  });
  return out;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_STAIRCASE_H
