// SPDX-License-Identifier: GPL-3.0-or-later
// The corners of a rolling-ball blend: where the fillets of a fillet-rounded box or
// housing meet, a ball of the fillets' radius R rolling along the edges of the inner
// box leaves a sphere at each of its corners, tangent to the cylinders. Creases and
// plane borders bound the whole fillet network as one region (manual, Creases), and
// the seams between its cylinders and spheres carry no crease. What tells them apart is
// the smaller principal curvature: 0 on a cylinder, 1/R on a sphere, while the larger is
// 1/R on both. Per face, the shape operator is fitted by least squares to the changes
// of the raw face normals over the faces of its region within half the blend's radius
// (the differences of normals against those of the centroids, in the face's tangent
// plane), so the support scales with the blend and not with the tessellation or the
// diagonal: a coarse tessellation takes about one ring, a fine one more, which averages
// a noisy mesh's normals. A region is a blend when the larger curvature is about
// constant over it (the ratio of its quartiles) and most of it is cylinder-like, as a
// sample of its faces says (one of them sphere-like); then all its faces are fitted,
// those whose smaller curvature reaches half the larger (same sign) form candidate
// corners, and a candidate is a corner when it is a piece of one sphere: its faces'
// centres of curvature (centroid minus normal times R, averaged over each face's
// support) gather round one point, where a strip of a cylinder or a torus
// spreads them along its axis or spine as far as its centroids. Noise leaves the
// corner's rim out of it or takes rows of the cylinders in, so its border then moves to
// where the sphere meets the cylinders: the planes through the sphere's centre (fitted
// to the corner's centroids) normal to the axes of the cylinders next to it, found from
// the directions of their faces' centres of curvature and their raw normals; noise
// along the normals hardly moves a centroid along an axis, so a face is the corner's
// when its centroid lies on the centre's side of every plane and near the sphere. The
// edges between a corner and the rest of its region are marked as curvature
// discontinuities.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_BLEND_CORNERS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_BLEND_CORNERS_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/crease_staircase.h>
#include <CGAL/Feature_segmentation/internal/union_find.h>

#include <Eigen/Dense>

#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the blend corners, chosen on the development and generated parts,
// clean and at 0.1% and 0.3% noise (evaluate_quality; manual, Creases).
struct Blend_corners
{
  // The least number of faces of a region that is looked at.
  static constexpr std::size_t least_faces = 100;
  // The most faces of a region whose curvatures decide whether it is a blend with a
  // corner (evenly spread over it; a corner among them); a blend's faces are all fitted
  // then.
  static constexpr std::size_t sample = 512;
  // The faces whose normals a face's curvature is fitted to: those of its region within
  // this fraction of the blend's radius (the inverse of the median larger curvature).
  static constexpr double support = 0.5;
  // ... and within this many times the median distance between adjacent centroids of
  // the region (a blend tessellated finely has its curvature in a few rings, and the
  // cost stays linear).
  static constexpr double most_spacings = 3.;
  // The largest ratio of the upper to the lower quartile of the larger curvature's
  // magnitude in a blend: 1.03 to 1.3 on the generated rounded boxes clean and at 0.3%
  // noise, about 3 on a noisy plane.
  static constexpr double quartile_ratio = 1.6;
  // A face of a candidate corner: its smaller curvature at least this fraction of the
  // larger (0 on a cylinder, 1 on a sphere).
  static constexpr double umbilic = 0.5;
  // A blend's cylinders: most of its faces have a smaller curvature at most this
  // fraction of the larger (a sphere bounded by creases has a few such faces where its
  // fits are one-sided, at its rim).
  static constexpr double cylinder = 0.25;
  // The least number of faces of a corner.
  static constexpr std::size_t least_corner_faces = 6;
  // The least area of a corner, times the blend's curvature squared: a spherical
  // triangle's area over R^2 is its angle excess, pi/2 (1.57) at a box's corner (1.37 to
  // 1.8 measured on the generated boxes clean and noisy), pi/3 where a wedge of 60
  // degrees meets a face; sphere-like pieces of tori measure about 0.5.
  static constexpr double least_corner_area = 0.75;
  // A corner's centres of curvature spread (root mean square distance to their mean)
  // at most this fraction of its centroids' spread.
  static constexpr double collapse = 0.3;
  // A corner's border then moves to the planes through its sphere's centre normal to the
  // axes of the cylinders next to it (refine_corner in mark_blend_corners()): the faces
  // within `reach` radii of the centre whose centres of curvature lie `least_axis_distance`
  // to `reach` radii from it are the cylinders' (grouped by direction within
  // `cylinder_angle` degrees); an axis is normal to its faces' raw normals, fitted again
  // over those within `off_axis_angle` degrees of normal to it, and is kept if it goes
  // within `axis_angle` degrees of the way of the centres; a face is the corner's only
  // within a band about the sphere fitted to the corner's centroids (3 times their root
  // mean square distance from it, at least `least_band` radii), which bounds the corner
  // where no cylinder's plane does (a sphere into a torus). Over three noise realisations
  // the generated rounded boxes at 0.1% noise go from 0.89 and 0.99 (coarse and fine) to
  // 0.93 and 1.00, the fine one at 0.3% from 0.88 to 0.92, clean the coarse box and the
  // coarse turned part from 0.98 and 0.99 to 1.00, CAD part 30274 clean from 0.982 to
  // 0.979 (0.971 without the band: its small spheres meet one cylinder each), and no
  // other part changes. Without the band, with the axes along the mean directions of the
  // centres (which tilt by up to 8 degrees on the short fillets of the fine box), the
  // fine box at 0.1% falls to 0.97; with the centres of curvature as the sphere's centre
  // (noise moves them outwards), the coarse box at 0.1% reaches 0.90 and the fine one at
  // 0.3% 0.91.
  static constexpr double reach = 2.;
  static constexpr double least_axis_distance = 0.5;
  static constexpr double cylinder_angle = 30.;
  static constexpr double off_axis_angle = 15.;
  static constexpr double axis_angle = 20.;
  static constexpr double least_band = 0.05;
};

// The principal curvatures (k1 of the larger magnitude) of the shape operator fitted to
// the normals `n` at points `c` of faces `js` around face f; false with fewer than
// three neighbours or a singular fit.
inline bool fitted_curvatures(std::size_t f, const std::vector<std::size_t>& js, const std::vector<Eigen::Vector3d>& c,
                              const std::vector<Eigen::Vector3d>& n, double& k1, double& k2)
{
  if(js.size() < 3) return false;
  const Eigen::Vector3d& nf = n[f];
  Eigen::Vector3d u = nf.cross(Eigen::Vector3d::UnitX());
  if(u.norm() < 0.1) u = nf.cross(Eigen::Vector3d::UnitY());
  u.normalize();
  const Eigen::Vector3d w = nf.cross(u);
  // dn = S dp with S = [[a, b], [b, d]] in the basis (u, w): two equations per neighbour
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for(std::size_t j : js)
  {
    const Eigen::Vector3d dp = c[j] - c[f], dn = n[j] - n[f];
    const double x = dp.dot(u), y = dp.dot(w);
    const Eigen::Vector3d r1(x, y, 0.), r2(0., x, y);
    ata += r1 * r1.transpose() + r2 * r2.transpose();
    atb += r1 * dn.dot(u) + r2 * dn.dot(w);
  }
  Eigen::LDLT<Eigen::Matrix3d> ldlt(ata);
  if(ldlt.info() != Eigen::Success || !(std::abs(ldlt.vectorD().minCoeff()) > 1e-12 * ata.trace())) return false;
  const Eigen::Vector3d s = ldlt.solve(atb);
  const double mean = 0.5 * (s[0] + s[2]), dev = std::sqrt(0.25 * (s[0] - s[2]) * (s[0] - s[2]) + s[1] * s[1]);
  const double a = mean + dev, b = mean - dev;
  k1 = std::abs(a) >= std::abs(b) ? a : b;
  k2 = std::abs(a) >= std::abs(b) ? b : a;
  return std::isfinite(k1) && std::isfinite(k2);
}

// Marks 2 in `is_crease` the edges that are no crease and part a corner of a rolling-ball
// blend (file comment) from the rest of its region, the regions being those that the
// marked edges of `is_crease` bound. `normal`, `area`, `centroid`: the faces' raw unit
// normals, areas and centroids; `begin`, `ring`: the faces sharing a vertex with each
// face (vertex_adjacent_faces). Returns the number of edges marked.
template <typename TriangleMesh>
std::size_t mark_blend_corners(const Mesh_indexing<TriangleMesh>& idx, const std::vector<Eigen::Vector3d>& normal,
                               const std::vector<double>& area, const std::vector<Eigen::Vector3d>& centroid,
                               const std::vector<std::uint32_t>& begin, const std::vector<std::uint32_t>& ring,
                               std::vector<char>& is_crease)
{
  typedef Blend_corners Limits;
  const std::size_t nf = idx.number_of_faces();
  if(nf == 0) return 0;
  // the faces across each face's edges, the regions that the marked edges bound (by
  // their smallest face), and their faces
  const std::uint32_t none = std::uint32_t(-1);
  std::vector<std::uint32_t> face_edge, across;
  face_edges_and_neighbours(idx, none, face_edge, across);
  Smallest_root_union_find sets(nf);
  for(std::size_t k = 0; k < across.size(); ++k)
    if(across[k] != none && !is_crease[face_edge[k]]) sets.unite(k / 3, across[k]);
  const std::vector<std::size_t> root = sets.roots();
  std::vector<std::size_t> first_member(nf + 1, 0), member(nf);
  for(std::size_t f = 0; f < nf; ++f) ++first_member[root[f] + 1];
  for(std::size_t f = 0; f < nf; ++f) first_member[f + 1] += first_member[f];
  {
    std::vector<std::size_t> fill(first_member.begin(), first_member.end() - 1);
    for(std::size_t f = 0; f < nf; ++f) member[fill[root[f]]++] = f;
  }

  std::vector<double> k1(nf, 0.), k2(nf, 0.);
  std::vector<char> fitted(nf, 0);
  // per face, the mean centroid and normal over its support: their centre of curvature
  // averages the noise of the normals out, and stays on a sphere's centre or a
  // cylinder's axis
  std::vector<Eigen::Vector3d> mean_point(nf), mean_normal(nf);
  std::vector<std::size_t> stamp(nf, std::size_t(-1)), ball, front, following;
  // the faces of f's region within `radius` of its centroid, reached across edges
  auto gather = [&](std::size_t f, double radius) {
    ball.clear();
    front.assign(1, f);
    stamp[f] = f;
    const double r2 = radius * radius;
    while(!front.empty())
    {
      following.clear();
      for(std::size_t g : front)
        for(std::size_t k = 3 * g; k < 3 * g + 3; ++k)
        {
          const std::size_t j = across[k];
          if(j == none || stamp[j] == f || root[j] != root[f]) continue;
          stamp[j] = f;
          if((centroid[j] - centroid[f]).squaredNorm() > r2) continue;
          ball.push_back(j);
          following.push_back(j);
        }
      front.swap(following);
    }
  };

  // per face, 0 or 1 + the number of its corner; per face of the region at hand, 1 for
  // a candidate, 2 once in a component
  std::vector<std::size_t> corner(nf, 0), component;
  std::size_t corners = 0;
  std::vector<char> state(nf, 0);
  // the component of f across the non-crease edges, over the faces that `joins`; `beside`
  // sees each face across a non-crease edge that it does not join
  auto grow = [&](std::size_t f, auto&& joins, auto&& beside) {
    component.assign(1, f);
    state[f] = 2;
    for(std::size_t i = 0; i < component.size(); ++i)
      for(std::size_t k = 3 * component[i]; k < 3 * component[i] + 3; ++k)
      {
        const std::size_t g = across[k];
        if(g == none || is_crease[face_edge[k]] || state[g] == 2) continue;
        if(joins(g))
        {
          state[g] = 2;
          component.push_back(g);
        }
        else
          beside(g);
      }
  };
  // the fit of face f over the faces of its region within `radius`, with its support's
  // mean centroid and normal
  auto fit = [&](std::size_t f, double radius) {
    gather(f, radius);
    fitted[f] = fitted_curvatures(f, ball, centroid, normal, k1[f], k2[f]) ? 1 : 0;
    mean_point[f] = centroid[f];
    mean_normal[f] = normal[f];
    for(std::size_t j : ball)
    {
      mean_point[f] += centroid[j];
      mean_normal[f] += normal[j];
    }
    mean_point[f] /= double(ball.size() + 1);
    mean_normal[f] /= double(ball.size() + 1);
  };
  std::vector<double> magnitude, spacing;
  std::vector<std::size_t> sample;
  // per corner, its sphere: the centre, the radius and the band about it that holds the
  // corner's centroids
  struct Sphere
  {
    Eigen::Vector3d centre;
    double radius, band;
  };
  std::vector<Sphere> sphere_of;
  // the cylinders next to a corner: the sum of the directions from the corner's centre to
  // their faces' centres of curvature, their faces, the second moments of their raw normals
  struct Cylinder
  {
    Eigen::Vector3d direction;
    std::size_t faces;
    Eigen::Matrix3d moments;
  };
  std::vector<Cylinder> cylinders;
  std::vector<std::pair<std::size_t, std::size_t> > cylinder_faces; // (cylinder, face)
  std::vector<std::size_t> nearby;
  std::vector<char> inside;
  const double to_radians = 3.14159265358979323846 / 180.;
  // Moves the border of corner `id` (its sphere `sphere`) among the faces `faces` of its
  // blend of radius `radius` to the planes where the sphere meets the cylinders (file
  // comment); `centre_at`: a face's centre of curvature.
  auto refine_corner = [&](const auto& faces, std::size_t id, const Sphere& sphere, double radius,
                           auto&& centre_at) {
    const Eigen::Vector3d& c = sphere.centre;
    cylinders.clear();
    cylinder_faces.clear();
    nearby.clear();
    const double cos_cluster = std::cos(Limits::cylinder_angle * to_radians);
    for(std::size_t g : faces)
    {
      if((corner[g] != 0 && corner[g] != id) || (centroid[g] - c).norm() > Limits::reach * radius) continue;
      nearby.push_back(g);
      if(corner[g] == id) continue;
      const Eigen::Vector3d v = centre_at(g) - c;
      const double length = v.norm();
      if(length < Limits::least_axis_distance * radius || length > Limits::reach * radius) continue;
      const Eigen::Vector3d d = v / length, n = normal[g];
      std::size_t k = 0;
      while(k < cylinders.size() && cylinders[k].direction.normalized().dot(d) < cos_cluster) ++k;
      if(k == cylinders.size()) cylinders.push_back(Cylinder{ Eigen::Vector3d::Zero(), 0, Eigen::Matrix3d::Zero() });
      cylinders[k].direction += d;
      ++cylinders[k].faces;
      cylinders[k].moments += area[g] * n * n.transpose();
      cylinder_faces.emplace_back(k, g);
    }
    // each axis: the direction most nearly normal to the raw normals of the cylinder's
    // faces, again over those within Limits::off_axis_angle of normal to it (the faces at
    // the rim of the corner, which its noisy fits left out of it, bend towards the axis)
    const double sin_off = std::sin(Limits::off_axis_angle * to_radians);
    std::vector<Eigen::Vector3d> axis(cylinders.size());
    auto fit_axes = [&]() {
      for(std::size_t k = 0; k < cylinders.size(); ++k)
      {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cylinders[k].moments);
        axis[k] = es.eigenvectors().col(0);
        if(axis[k].dot(cylinders[k].direction) < 0) axis[k] = -axis[k];
      }
    };
    fit_axes();
    for(int pass = 0; pass < 2; ++pass)
    {
      for(Cylinder& cylinder : cylinders) cylinder.moments.setZero();
      for(const auto& [k, g] : cylinder_faces)
        if(std::abs(normal[g].dot(axis[k])) <= sin_off)
          cylinders[k].moments += area[g] * normal[g] * normal[g].transpose();
      fit_axes();
    }
    // the planes: of the cylinders of enough faces whose axis goes the way of their
    // centres of curvature (a cluster of stray centres is no cylinder) and away from the
    // corner (its faces lie on c's side of every plane)
    Eigen::Vector3d middle = Eigen::Vector3d::Zero();
    std::size_t before = 0;
    for(std::size_t g : nearby)
      if(corner[g] == id)
      {
        middle += centroid[g] - c;
        ++before;
      }
    const double cos_axis = std::cos(Limits::axis_angle * to_radians);
    std::vector<Eigen::Vector3d> planes;
    for(std::size_t k = 0; k < cylinders.size(); ++k)
      if(cylinders[k].faces >= Limits::least_corner_faces &&
         axis[k].dot(cylinders[k].direction.normalized()) >= cos_axis && axis[k].dot(middle) < 0.)
        planes.push_back(axis[k]);
    if(planes.empty()) return;
    inside.assign(nearby.size(), 1);
    std::size_t after = 0;
    for(std::size_t i = 0; i < nearby.size(); ++i)
    {
      for(const Eigen::Vector3d& a : planes) inside[i] = inside[i] && (centroid[nearby[i]] - c).dot(a) <= 0.;
      inside[i] = inside[i] && std::abs((centroid[nearby[i]] - c).norm() - sphere.radius) <= sphere.band;
      after += inside[i];
    }
    // (a corner that the planes would halve keeps its faces)
    if(2 * after < before) return;
    for(std::size_t i = 0; i < nearby.size(); ++i) corner[nearby[i]] = inside[i] ? id : 0;
  };
  for(std::size_t r = 0; r < nf; ++r)
  {
    if(root[r] != r || first_member[r + 1] - first_member[r] < Limits::least_faces) continue;
    const auto faces = boost::make_iterator_range(member.cbegin() + std::ptrdiff_t(first_member[r]),
                                                  member.cbegin() + std::ptrdiff_t(first_member[r + 1]));
    // the tests read a sample of the region's faces, evenly spread over their order
    sample.clear();
    const std::size_t size = first_member[r + 1] - first_member[r];
    const std::size_t stride = (size + Limits::sample - 1) / Limits::sample;
    for(std::size_t i = 0; i < size; i += stride) sample.push_back(member[first_member[r] + i]);
    // the median distance between adjacent centroids, and a first median curvature from
    // the faces sharing a vertex with each face
    spacing.clear();
    magnitude.clear();
    for(std::size_t f : sample)
    {
      ball.clear();
      for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
        if(ring[i] != f && root[ring[i]] == r)
        {
          ball.push_back(ring[i]);
          spacing.push_back((centroid[ring[i]] - centroid[f]).norm());
        }
      double a, b;
      if(fitted_curvatures(f, ball, centroid, normal, a, b)) magnitude.push_back(std::abs(a));
    }
    if(2 * magnitude.size() < sample.size() || spacing.empty()) continue;
    const double first = median_length(magnitude), step = median_length(spacing);
    if(!(first > 0) || !(step > 0)) continue;
    const double radius = (std::min)(Limits::support / first, Limits::most_spacings * step);
    // the curvatures over the support, on the sample
    magnitude.clear();
    std::size_t cylindrical = 0, spherical = 0;
    for(std::size_t f : sample)
    {
      fit(f, radius);
      if(!fitted[f]) continue;
      magnitude.push_back(std::abs(k1[f]));
      if(std::abs(k2[f]) <= Limits::cylinder * std::abs(k1[f])) ++cylindrical;
      if(k1[f] * k2[f] > 0 && std::abs(k2[f]) >= Limits::umbilic * std::abs(k1[f])) ++spherical;
    }
    if(2 * magnitude.size() < sample.size() || spherical == 0) continue;
    std::sort(magnitude.begin(), magnitude.end());
    const double lower = magnitude[magnitude.size() / 4], upper = magnitude[(3 * magnitude.size()) / 4];
    const double blend = magnitude[magnitude.size() / 2];
    // a face's centre of curvature: its support's mean centroid moved along the mean
    // normal by the blend's radius
    auto centre = [&](std::size_t g) -> Eigen::Vector3d {
      return mean_point[g] - mean_normal[g] * ((k1[g] > 0 ? 1. : -1.) / blend);
    };
    if(!(lower > 0) || upper > Limits::quartile_ratio * lower) continue;
    // a blend is mostly cylinders: most of its faces have a small k2
    if(2 * cylindrical < magnitude.size()) continue;
    const std::size_t first_corner = corners;
    // a blend: the curvatures of all its faces
    for(std::size_t f : faces) fit(f, radius);
    // the candidate corners: the components of the faces of sphere-like curvature
    for(std::size_t f : faces)
      state[f] = fitted[f] && k1[f] * k2[f] > 0 && std::abs(k2[f]) >= Limits::umbilic * std::abs(k1[f]) ? 1 : 0;
    const double least_area = Limits::least_corner_area / (blend * blend);
    for(std::size_t f : faces)
    {
      if(state[f] != 1) continue;
      grow(f, [&](std::size_t g) { return state[g] == 1; }, [](std::size_t) {});
      double extent = 0.;
      for(std::size_t g : component) extent += area[g];
      if(component.size() < Limits::least_corner_faces || extent < least_area) continue;
      // a piece of one sphere: its centres of curvature gather round one point
      Eigen::Vector3d mc = Eigen::Vector3d::Zero(), mp = Eigen::Vector3d::Zero();
      for(std::size_t g : component)
      {
        mc += centre(g);
        mp += centroid[g];
      }
      mc /= double(component.size());
      mp /= double(component.size());
      double sc = 0., sp = 0.;
      for(std::size_t g : component)
      {
        sc += (centre(g) - mc).squaredNorm();
        sp += (centroid[g] - mp).squaredNorm();
      }
      if(sc > Limits::collapse * Limits::collapse * sp) continue;
      ++corners;
      for(std::size_t g : component) corner[g] = corners;
      // the centre of the sphere through the corner's centroids (least squares on the
      // centroids q relative to their mean: |q|^2 = 2 q.c + k), which does not depend on
      // the blend's curvature as the centres of curvature do (noise raises the
      // curvature, and the centres move outwards)
      Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
      Eigen::Vector4d atb = Eigen::Vector4d::Zero();
      for(std::size_t g : component)
      {
        const Eigen::Vector3d q = centroid[g] - mp;
        const Eigen::Vector4d row(2. * q(0), 2. * q(1), 2. * q(2), 1.);
        ata += area[g] * row * row.transpose();
        atb += area[g] * row * q.squaredNorm();
      }
      const Eigen::Vector4d sphere = ata.ldlt().solve(atb);
      const Eigen::Vector3d fitted_centre = mp + Eigen::Vector3d(sphere(0), sphere(1), sphere(2));
      const double fitted_radius = std::sqrt((std::max)(0., sphere(3) + sphere.head<3>().squaredNorm()));
      // the sphere's radius and the band about it that holds the corner's centroids (3
      // times their root mean square distance from the sphere, at least
      // Limits::least_band radii)
      double rho = 1. / blend, band = Limits::least_band / blend;
      if(sphere.allFinite() && (fitted_centre - mc).norm() < 0.5 / blend && fitted_radius > 0.)
      {
        mc = fitted_centre;
        rho = fitted_radius;
        double residual = 0., weight = 0.;
        for(std::size_t g : component)
        {
          const double off = (centroid[g] - mc).norm() - rho;
          residual += area[g] * off * off;
          weight += area[g];
        }
        band = (std::max)(3. * std::sqrt(residual / weight), Limits::least_band * rho);
      }
      sphere_of.push_back(Sphere{ mc, rho, band });
    }
    // the corners' borders at the planes where their spheres meet the cylinders
    for(std::size_t c = first_corner; c < corners; ++c)
      refine_corner(faces, c + 1, sphere_of[c], 1. / blend, centre);
    // the pieces of the rest smaller than a corner that touch one corner alone (holes
    // that noise makes in a corner, slivers along its rim) join it
    for(std::size_t f : faces) state[f] = 0;
    std::vector<std::size_t> touching;
    for(std::size_t f : faces)
    {
      if(corner[f] != 0 || state[f] != 0) continue;
      touching.clear();
      grow(f, [&](std::size_t g) { return corner[g] == 0; }, [&](std::size_t g) { touching.push_back(corner[g]); });
      std::sort(touching.begin(), touching.end());
      if(touching.empty() || touching.front() != touching.back()) continue;
      double extent = 0.;
      for(std::size_t g : component) extent += area[g];
      if(extent < least_area)
        for(std::size_t g : component) corner[g] = touching.front();
    }
  }
  if(corners == 0) return 0;
  std::size_t marked = 0;
  for(std::size_t k = 0; k < across.size(); ++k)
  {
    const std::size_t f = k / 3, g = across[k];
    // (the two faces of a non-crease edge are in one region)
    if(g == none || g < f || is_crease[face_edge[k]] || corner[f] == corner[g]) continue;
    is_crease[face_edge[k]] = 2;
    ++marked;
  }
  return marked;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_BLEND_CORNERS_H
