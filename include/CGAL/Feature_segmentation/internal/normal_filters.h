// SPDX-License-Identifier: GPL-3.0-or-later
// The filters of the face normals that the crease detection reads on rough meshes
// (crease_detection.h): the bilateral filter (on lightly noisy meshes also with a
// narrower range, crease_narrow_filter.h), and on heavily noisy meshes the filter along
// the normals' gradient (crease_staircase.h says why). All weigh a face's ring with the
// same spatial Gaussian (normal_filter_spatial_weights(), computed once per mesh in a
// Normal_filter_ring) and the same range Gaussian on normal differences
// (Range_gaussian), and each round reads the previous round only: the same result at
// any thread count. Also the dihedral angles of a normal field.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_NORMAL_FILTERS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_NORMAL_FILTERS_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the filter along the gradient, chosen on the 30 development parts
// and the generated ones at 0.1% and 0.3% noise (manual, Creases).
struct Gradient_filter
{
  // The gradient fit's ridge, as a share of the ring's spatial weights (in coordinates
  // of centroid spacings), and the most the gradient turns the normal per spacing.
  static constexpr double ridge = 0.03;
  static constexpr double gradient_cap = 0.3;
};

// The range Gaussian exp(-d2 / (2 sigma_r^2)) of a squared difference d2 of normals,
// read from a table over [0, 4] (the range of unit normals) with linear interpolation,
// relative error below 4e-6 for sigma_r = 0.3 (computing the exponential per pair
// would be most of the filters' time); beyond 4 (the carried normals of the gradient
// filter, which are not unit) computed.
class Range_gaussian
{
public:
  explicit Range_gaussian(double sigma_r)
    : m_inv(1. / (2 * sigma_r * sigma_r)), m_value(table_size + 2)
  {
    for(std::size_t k = 0; k < m_value.size(); ++k) m_value[k] = std::exp(-4. * double(k) / double(table_size) * m_inv);
  }

  double operator()(double d2) const
  {
    if(!(d2 < 4.)) return std::exp(-d2 * m_inv);
    const double x = (std::max)(0., d2) * (double(table_size) / 4.);
    const std::size_t k = static_cast<std::size_t>(x);
    const double t = x - double(k);
    return (1 - t) * m_value[k] + t * m_value[k + 1];
  }

private:
  static constexpr std::size_t table_size = 4096;
  double m_inv;
  std::vector<double> m_value;
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

// The rings of the faces (`begin`, `ring`: CSR, as vertex_adjacent_faces() lists them)
// with the filters' spatial weights (normal_filter_spatial_weights()) and the faces'
// centroids: computed once for every filter that a mesh's normals go through. Holds
// references to `centroid`, `begin` and `ring`, which must outlive it.
struct Normal_filter_ring
{
  Normal_filter_ring(const std::vector<double>& area, const std::vector<Eigen::Vector3d>& centroid,
                     const std::vector<std::uint32_t>& begin, const std::vector<std::uint32_t>& ring)
    : centroid(centroid), begin(begin), ring(ring),
      spatial(normal_filter_spatial_weights(area, centroid, begin, ring, spacing))
  {}

  const std::vector<Eigen::Vector3d>& centroid;
  const std::vector<std::uint32_t>& begin;
  const std::vector<std::uint32_t>& ring;
  double spacing = 0; // declared before `spatial`, whose initializer sets it
  std::vector<double> spatial;
};

// Face normals filtered so that noise fades and creases stay sharp: bilateral normal
// filtering (Zheng, Fu, Au, Tai, IEEE TVCG 2011) over the faces sharing a vertex, with
// a spatial Gaussian of the mean distance between neighbouring centroids and a range
// Gaussian of sigma_r on the difference of normals, at most max_iterations rounds,
// stopping once the roughness (normal_roughness; `initial_roughness` before the first
// round) is at most `stop_roughness`; with stop_roughness 0 every round runs.
inline std::vector<Eigen::Vector3d> filter_face_normals(const std::vector<Eigen::Vector3d>& normal,
                                                        double initial_roughness, const Normal_filter_ring& rings,
                                                        int max_iterations, double sigma_r, double stop_roughness,
                                                        bool parallel = false)
{
  if(max_iterations <= 0 || initial_roughness <= stop_roughness) return normal;
  const std::size_t nf = normal.size();
  const std::vector<std::uint32_t>& begin = rings.begin;
  const std::vector<std::uint32_t>& ring = rings.ring;
  const std::vector<double>& spatial = rings.spatial;
  const Range_gaussian range(sigma_r);
  std::vector<Eigen::Vector3d> n = normal, next(nf);
  // With a stop, every round also measures the roughness of the normals it reads
  // (the smallest difference it meets per face, as normal_roughness does): once that is
  // at most stop_roughness, its output is dropped and its input returned, the result of
  // the same rounds as measuring after each round, without a second pass over the pairs.
  std::vector<double> least(stop_roughness > 0 ? nf : 0);
  // one round on the faces [first, last): each face reads the normals of the previous
  // round only, so the faces of a round may be filtered by several threads
  auto filter_range = [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f)
    {
      double closest = 4.;
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
      {
        const std::size_t g = ring[i];
        if(n[g].squaredNorm() == 0) continue;
        const double d2 = (std::min)(4., (n[f] - n[g]).squaredNorm());
        if(g != f) closest = (std::min)(closest, d2);
        m += spatial[i] * range(d2) * n[g];
      }
      if(!least.empty()) least[f] = closest;
      const double len = m.norm();
      next[f] = n[f].squaredNorm() > 0 && len > 0 && std::isfinite(len) ? Eigen::Vector3d(m / len) : n[f];
    }
  };
  for(int it = 0; it < max_iterations; ++it)
  {
    for_each_range(nf, parallel, 1024, filter_range);
    if(it > 0 && !least.empty())
    {
      // the roughness of n, the output of round it - 1 (round 0 reads the input, whose
      // roughness initial_roughness is above the stop)
      std::nth_element(least.begin(), least.begin() + std::ptrdiff_t(nf / 2), least.end());
      if(std::sqrt(least[nf / 2]) <= stop_roughness) break;
    }
    n.swap(next);
  }
  return n;
}

// The same on the rings of `begin` and `ring` with the spatial weights of `area` and
// `centroid`, computed for this call.
inline std::vector<Eigen::Vector3d> filter_face_normals(const std::vector<Eigen::Vector3d>& normal,
                                                        double initial_roughness,
                                                        const std::vector<double>& area,
                                                        const std::vector<Eigen::Vector3d>& centroid,
                                                        const std::vector<std::uint32_t>& begin,
                                                        const std::vector<std::uint32_t>& ring,
                                                        int max_iterations, double sigma_r, double stop_roughness,
                                                        bool parallel = false)
{
  if(max_iterations <= 0 || initial_roughness <= stop_roughness) return normal;
  return filter_face_normals(normal, initial_roughness, Normal_filter_ring(area, centroid, begin, ring),
                             max_iterations, sigma_r, stop_roughness, parallel);
}

// Face normals filtered as filter_face_normals() does (`rounds` rounds, range parameter
// `sigma_r`, the same spatial Gaussian), but along their gradient: each round, face f
// fits the gradient G of the normals over its ring (n_g - n_f ~ G d_g, d_g the
// centroid offset in f's tangent plane in units of the mean centroid spacing, weighted
// by the bilateral weights, with the ridge Gradient_filter::ridge and the norm of G at
// most Gradient_filter::gradient_cap), then averages the carried normals n_g - G d_g
// with the spatial and range weights, the range Gaussian on n_g - G d_g - n_f. Each face
// reads the previous round only: the same result at any thread count.
inline std::vector<Eigen::Vector3d> filter_face_normals_along_gradient(const std::vector<Eigen::Vector3d>& normal,
                                                                       const Normal_filter_ring& rings, int rounds,
                                                                       double sigma_r, bool parallel = false)
{
  const std::size_t nf = normal.size();
  const Range_gaussian range(sigma_r);
  const std::vector<Eigen::Vector3d>& centroid = rings.centroid;
  const std::vector<std::uint32_t>& begin = rings.begin;
  const std::vector<std::uint32_t>& ring = rings.ring;
  const std::vector<double>& spatial = rings.spatial;
  const double spacing = rings.spacing;
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
          const double w = spatial[i] * range((n[f] - n[g]).squaredNorm());
          const Eigen::Vector2d d = offset(g);
          dd += w * d * d.transpose();
          nd += w * (n[g] - n[f]) * d.transpose();
        }
        dd += Gradient_filter::ridge * weights * Eigen::Matrix2d::Identity();
        Eigen::Matrix<double, 3, 2> gradient = nd * dd.inverse();
        const double norm = gradient.norm();
        if(norm > Gradient_filter::gradient_cap) gradient *= Gradient_filter::gradient_cap / norm;
        // the carried normals, averaged
        Eigen::Vector3d m = Eigen::Vector3d::Zero();
        for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
        {
          const std::size_t g = ring[i];
          if(n[g].squaredNorm() == 0) continue;
          const Eigen::Vector3d carried = n[g] - gradient * offset(g);
          m += spatial[i] * range((carried - n[f]).squaredNorm()) * carried;
        }
        const double len = m.norm();
        next[f] = len > 0 && std::isfinite(len) ? Eigen::Vector3d(m / len) : n[f];
      }
    });
    n.swap(next);
  }
  return n;
}

// The same on the rings of `begin` and `ring` with the spatial weights of `area` and
// `centroid`, computed for this call.
inline std::vector<Eigen::Vector3d> filter_face_normals_along_gradient(const std::vector<Eigen::Vector3d>& normal,
                                                                       const std::vector<double>& area,
                                                                       const std::vector<Eigen::Vector3d>& centroid,
                                                                       const std::vector<std::uint32_t>& begin,
                                                                       const std::vector<std::uint32_t>& ring,
                                                                       int rounds, double sigma_r, bool parallel = false)
{
  return filter_face_normals_along_gradient(normal, Normal_filter_ring(area, centroid, begin, ring), rounds, sigma_r,
                                            parallel);
}

// The angle between the normals of the two faces of every edge, in degrees (0 for a
// border edge or next to a degenerate face); by TBB's threads if `parallel`.
template <typename TriangleMesh>
std::vector<double> dihedral_angles(const Mesh_indexing<TriangleMesh>& idx, const std::vector<Eigen::Vector3d>& normal,
                                    bool parallel = false)
{
  const TriangleMesh& tm = idx.mesh();
  std::vector<double> angle(idx.number_of_edges(), 0.);
  for_each_range(angle.size(), parallel, 8192, [&](std::size_t first, std::size_t last) {
    for(std::size_t e = first; e < last; ++e)
    {
      const auto h = halfedge(idx.edge_at(e), tm);
      const std::size_t f = idx.face_id(h), g = idx.face_id(opposite(h, tm));
      if(f == idx.npos || g == idx.npos) continue;
      if(normal[f].squaredNorm() == 0 || normal[g].squaredNorm() == 0) continue;
      const double c = (std::max)(-1., (std::min)(1., normal[f].dot(normal[g])));
      angle[e] = std::acos(c) * 180. / 3.14159265358979323846;
    }
  });
  return angle;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_NORMAL_FILTERS_H
