// The seams of noisy surfaces of revolution (revolution_seams.h): the axis fit is exact
// on exact normals of a tilted torus and cylinder and refuses a plane; the pieces of a profile are the
// brute-force optimum; the fits of a profile's pieces touch where they are tangent; on a
// noisy cylinder running tangentially into a sphere the seam is the circle of edges where
// they meet and parts the two; a noisy cylinder alone, a noisy elliptic cylinder (no
// surface of revolution) and a noisy plane get none; a bent pipe, exact and noisy, is cut
// at its two tangent joints into its straight pieces and arc, on the same edges; a
// weak crease inside a noisy cylinder is unmarked, a strong one that bounds a region or
// one on an elliptic cylinder stays; a strong crease that bounds nothing and the border
// of an island of faces whose normals follow the cylinder's are unmarked, the borders
// of its flat caps stay; a lightly noisy nail without planes gets the 15-degree seam
// between its shank and its tip.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/crease_detection.h>
#include <CGAL/Feature_segmentation/internal/revolution_seams.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "crease_test_geometry.h"
#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

BOOST_AUTO_TEST_SUITE(revolution_seams)

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
namespace I = FS::internal;

BOOST_AUTO_TEST_CASE(axis_of_a_tilted_torus_and_cylinder_and_none_for_a_plane)
{
  // Points and exact normals of a torus (radii 3 and 1) about the axis through (1, -2, 0.5)
  // along (1, 2, 2) / 3, over a quarter of its parallels and half of its meridians.
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 2).normalized(), origin(1, -2, 0.5);
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  std::vector<Eigen::Vector3d> c, n;
  for(int i = 0; i < 20; ++i)
    for(int j = 0; j < 20; ++j)
    {
      const double theta = 0.5 * M_PI * i / 19, phi = M_PI * j / 19;
      const Eigen::Vector3d radial = std::cos(theta) * e1 + std::sin(theta) * e2;
      const Eigen::Vector3d normal = std::cos(phi) * radial + std::sin(phi) * axis;
      c.push_back(origin + 3. * radial + normal);
      n.push_back(normal);
    }
  const std::vector<double> w(c.size(), 1.);
  Eigen::Vector3d a, p;
  BOOST_TEST(I::fit_revolution_axis(c, n, w, a, p));
  BOOST_TEST(std::abs(a.dot(axis)) == 1., boost::test_tools::tolerance(1e-9));
  BOOST_TEST((p - origin).cross(axis).norm() < 1e-7); // p on the axis

  // a cylinder (radius 2, the same axis and origin) with exact normals: its normal lines
  // also meet helices about the axis, and the axis is the one taken
  std::vector<Eigen::Vector3d> cc, cn;
  for(int i = 0; i < 20; ++i)
    for(int j = 0; j < 10; ++j)
    {
      const double theta = 1.5 * M_PI * i / 19;
      const Eigen::Vector3d radial = std::cos(theta) * e1 + std::sin(theta) * e2;
      cc.push_back(origin + 2. * radial + 0.3 * j * axis);
      cn.push_back(radial);
    }
  BOOST_TEST(I::fit_revolution_axis(cc, cn, std::vector<double>(cc.size(), 1.), a, p));
  BOOST_TEST(std::abs(a.dot(axis)) == 1., boost::test_tools::tolerance(1e-9));
  BOOST_TEST((p - origin).cross(axis).norm() < 1e-6);

  // a plane's normals are one direction: every line along it is an axis
  std::vector<Eigen::Vector3d> pc, pn;
  for(int i = 0; i < 10; ++i)
    for(int j = 0; j < 10; ++j)
    {
      pc.emplace_back(i, j, 0.);
      pn.emplace_back(0., 0., 1.);
    }
  BOOST_TEST(!I::fit_revolution_axis(pc, pn, std::vector<double>(pc.size(), 1.), a, p));
}

BOOST_AUTO_TEST_CASE(profile_pieces_are_the_brute_force_optimum)
{
  // 12 bins of 3 points each along a profile that runs straight (z from 0 to 1.2 at r = 1)
  // and then round a circle of radius 0.5, with deterministic offsets of up to 0.02; the
  // pieces of at least 2 bins minimising the fit error over 1e-4 plus 3 per piece, found
  // by the dynamic programme and by trying all 2^11 sets of cuts.
  const std::size_t bins = 12, least = 2;
  const double unit = 1e-4, penalty = 3.;
  std::vector<I::Profile_moments> per_bin(bins);
  unsigned state = 7;
  for(std::size_t b = 0; b < bins; ++b)
    for(int k = 0; k < 3; ++k)
    {
      state = state * 1103515245u + 12345u;
      const double jitter = 0.02 * ((state >> 8) % 1000 / 500. - 1.);
      const double t = 0.2 * (double(b) + k / 3.);
      double z, r;
      if(t <= 1.2) { z = t; r = 1.; }
      else
      {
        const double angle = (t - 1.2) / 0.5;
        z = 1.2 + 0.5 * std::sin(angle);
        r = 0.5 + 0.5 * std::cos(angle);
      }
      per_bin[b].add(1., z, r + jitter);
    }
  std::vector<I::Profile_moments> prefix(bins + 1);
  for(std::size_t b = 0; b < bins; ++b)
    for(int k = 0; k < 10; ++k) prefix[b + 1].s[k] = prefix[b].s[k] + per_bin[b].s[k];
  auto cost = [&](const std::vector<std::size_t>& first) {
    double total = 0.;
    for(std::size_t i = 0; i < first.size(); ++i)
    {
      const std::size_t end = i + 1 < first.size() ? first[i + 1] : bins;
      if(end - first[i] < least) return std::numeric_limits<double>::infinity();
      total += (prefix[end] - prefix[first[i]]).fit_error() / unit + penalty;
    }
    return total;
  };
  double best = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> best_first;
  for(unsigned mask = 0; mask < (1u << (bins - 1)); ++mask)
  {
    std::vector<std::size_t> first{ 0 };
    for(std::size_t b = 1; b < bins; ++b)
      if(mask & (1u << (b - 1))) first.push_back(b);
    const double c = cost(first);
    if(c < best)
    {
      best = c;
      best_first = first;
    }
  }
  const std::vector<std::size_t> first = I::profile_pieces(prefix, least, unit, penalty);
  BOOST_TEST(cost(first) == best, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(first == best_first, boost::test_tools::per_element());
  // more than one piece: the straight part and the arc
  BOOST_TEST(first.size() >= 2u);
  // one straight piece: its fit error is its points' jitter only
  BOOST_TEST((prefix[6] - prefix[0]).fit_error() <= 18 * 0.02 * 0.02);
}

// A surface of revolution about the z axis, `around` facets round, whose vertex rows run
// along the profile point(j) (z, r) for j = 0 .. rows, every vertex moved along the
// profile's normal by add_noise_along() of `amplitude`.
template <typename Profile>
fs_test::Soup noisy_revolution(int around, int rows, Profile point, double amplitude)
{
  fs_test::Soup s = fs_test::parametric_grid(around, rows, true, false, [&](double u, double v) {
    const double a = 2 * M_PI * u;
    const std::array<double, 2> zr = point(v * rows);
    return std::array<double, 3>{ zr[1] * std::cos(a), zr[1] * std::sin(a), zr[0] };
  });
  std::vector<std::array<double, 3> > normal;
  for(int j = 0; j <= rows; ++j)
    for(int i = 0; i < around; ++i)
    {
      const double a = 2 * M_PI * i / around;
      const std::array<double, 2> p = point(j - 0.01), q = point(j + 0.01);
      // the profile's normal: its tangent (dz, dr) turned to point away from the axis
      double nz = -(q[1] - p[1]), nr = q[0] - p[0];
      const double len = std::hypot(nz, nr);
      nz /= len;
      nr /= len;
      normal.push_back({ nr * std::cos(a), nr * std::sin(a), nz });
    }
  fs_test::add_noise_along(s, normal, amplitude);
  return s;
}

// The marks of mark_revolution_seams() on a mesh with no crease.
std::vector<char> revolution_seams_of(const SM& m, const I::Mesh_indexing<SM>& idx, std::size_t& marked)
{
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  std::vector<char> is_crease(idx.number_of_edges(), 0);
  marked = I::mark_revolution_seams(idx, get(CGAL::vertex_point, m), g.normal, g.area, g.centroid, g.begin, g.ring,
                                    is_crease);
  return is_crease;
}

BOOST_AUTO_TEST_CASE(fits_of_pieces_and_where_they_touch)
{
  // exact points on a quarter of the circle of centre (2, 3) and radius 1.5, and on the
  // line r = z / 2 + 1: the fits are the circle and the line
  I::Profile_moments arc, line;
  for(int k = 0; k <= 20; ++k)
  {
    const double a = k * M_PI / 40;
    arc.add(1., 2. + 1.5 * std::cos(a), 3. + 1.5 * std::sin(a));
    line.add(1., 0.3 * k, 0.15 * k + 1.);
  }
  Eigen::Vector2d point = Eigen::Vector2d::Zero(), direction = Eigen::Vector2d::Zero();
  double radius = -1.;
  BOOST_TEST(arc.fit(point, direction, radius));
  BOOST_TEST(std::abs(radius - 1.5) < 1e-9);
  BOOST_TEST((point - Eigen::Vector2d(2., 3.)).norm() < 1e-9);
  BOOST_TEST(line.fit(point, direction, radius));
  BOOST_TEST(radius == 0.);
  BOOST_TEST(std::abs(std::abs(direction.dot(Eigen::Vector2d(2., 1.).normalized())) - 1.) < 1e-12);
  BOOST_TEST(std::abs(point.y() - (point.x() / 2 + 1.)) < 1e-12); // on the line
  BOOST_TEST(!I::Profile_moments().fit(point, direction, radius)); // no points

  // where two fits touch, within 10 degrees of tangency
  const Eigen::Vector2d x(1., 0.), none(0., 0.);
  Eigen::Vector2d at;
  auto touch = [&](const Eigen::Vector2d& p1, const Eigen::Vector2d& d1, double r1, const Eigen::Vector2d& p2,
                   const Eigen::Vector2d& d2, double r2, const Eigen::Vector2d& expected) {
    at = Eigen::Vector2d(-99., -99.);
    const bool found = I::tangent_point(p1, d1, r1, p2, d2, r2, 10., at);
    const bool found_swapped = I::tangent_point(p2, d2, r2, p1, d1, r1, 10., at);
    BOOST_TEST(found);
    BOOST_TEST(found_swapped);
    BOOST_TEST((at - expected).norm() < 1e-12);
  };
  // the line r = 1 and the circle of radius 1 about (5, 2): the foot of the centre, (5, 1)
  touch(Eigen::Vector2d(0., 1.), x, 0., Eigen::Vector2d(5., 2.), none, 1., Eigen::Vector2d(5., 1.));
  // and a circle crossing it at 8.1 degrees (its centre 0.99 from the line): the foot
  touch(Eigen::Vector2d(0., 1.), x, 0., Eigen::Vector2d(5., 1.99), none, 1., Eigen::Vector2d(5., 1.));
  // circles of radii 1 and 2 about (0, 0) and (3, 0) touch from outside at (1, 0)
  touch(Eigen::Vector2d(0., 0.), none, 1., Eigen::Vector2d(3., 0.), none, 2., Eigen::Vector2d(1., 0.));
  // the circle of radius 2 about (1, 0) touches that of radius 3 about (0, 0) inside at (3, 0)
  touch(Eigen::Vector2d(0., 0.), none, 3., Eigen::Vector2d(1., 0.), none, 2., Eigen::Vector2d(3., 0.));
  // a crease: the circle of radius 1 about (5, 1.5) crosses the line at 60 degrees
  BOOST_TEST(!I::tangent_point(Eigen::Vector2d(0., 1.), x, 0., Eigen::Vector2d(5., 1.5), none, 1., 10., at));
  // circles crossing (centres 2 apart, radii 1 and 2: at 76 degrees), apart, or two lines
  BOOST_TEST(!I::tangent_point(Eigen::Vector2d(0., 0.), none, 1., Eigen::Vector2d(2., 0.), none, 2., 10., at));
  BOOST_TEST(!I::tangent_point(Eigen::Vector2d(0., 0.), none, 1., Eigen::Vector2d(5., 0.), none, 2., 10., at));
  BOOST_TEST(!I::tangent_point(Eigen::Vector2d(0., 0.), x, 0., Eigen::Vector2d(0., 1.), x, 0., 10., at));
}

BOOST_AUTO_TEST_CASE(cylinder_into_sphere_under_noise)
{
  // A cylinder of radius 1 from z = 0 to 3 (30 rows of 0.1) running tangentially into the
  // sphere of radius 1 about (0, 0, 3) up to 75 degrees of latitude (13 rows of 0.1007),
  // 64 facets round (0.098); no dihedral angle marks the seam circle z = 3, and the
  // curvature along the profile jumps from 0 to 1 there. Noise uniform in +-0.03 along
  // the normals (a standard deviation of 0.017, 0.36% of the diagonal 4.87).
  const double top = 75. * M_PI / 180.;
  auto profile = [&](double j) {
    if(j <= 30) return std::array<double, 2>{ 0.1 * j, 1. };
    const double theta = (j - 30) / 13. * top;
    return std::array<double, 2>{ 3. + std::sin(theta), std::cos(theta) };
  };
  const SM m = fs_test::to_mesh<SM>(noisy_revolution(64, 43, profile, 0.03));
  const I::Mesh_indexing<SM> idx(m);
  std::size_t marked = 0;
  const std::vector<char> is_crease = revolution_seams_of(m, idx, marked);
  double farthest = 0.;
  std::size_t count = 0;
  for(std::size_t e = 0; e < is_crease.size(); ++e)
    if(is_crease[e])
    {
      BOOST_TEST(is_crease[e] == 2); // a curvature discontinuity
      ++count;
      const auto h = halfedge(idx.edge_at(e), m);
      farthest = (std::max)({ farthest, std::abs(m.point(source(h, m)).z() - 3.), std::abs(m.point(target(h, m)).z() - 3.) });
    }
  BOOST_TEST_MESSAGE("marked " << marked << ", at most " << farthest << " from the seam circle");
  BOOST_TEST(marked == count);
  // a closed circle round the axis takes at least one edge per facet
  BOOST_TEST(marked >= 64u);
  // the ring of vertices at z = 3 itself (the noise moves them along the normals, which
  // are radial there up to 1e-5): the fits of the cylinder and the sphere touch within a
  // third of a row of it, where the faces' centroids are (cut on the half-edge bins of
  // the profile alone, the seam was a row, 0.1, off)
  BOOST_TEST(farthest <= 1e-3);
  // the seam parts the cylinder from the sphere: two regions
  const std::vector<std::size_t> root = I::face_components(idx, [&](std::size_t e) { return !is_crease[e]; });
  const std::set<std::size_t> regions(root.begin(), root.end());
  BOOST_TEST(regions.size() == 2u);

  // and the crease detection at the defaults marks it too
  const fs_test::Detected_creases detected = fs_test::detect_creases_at_defaults(idx);
  BOOST_TEST(!detected.clean);
  std::size_t seams = 0;
  for(std::size_t e = 0; e < detected.is_crease.size(); ++e) seams += detected.is_crease[e] == 2 && is_crease[e];
  BOOST_TEST(seams >= 64u);
}

// An elliptic cylinder (semi-axes 2 and 1, height 6; 64 facets round, 30 rows of 0.2)
// with noise uniform in +-0.05 along its normals: no surface of revolution.
fs_test::Soup noisy_elliptic_cylinder()
{
  fs_test::Soup s = fs_test::parametric_grid(64, 30, true, false, [](double u, double v) {
    const double a = 2 * M_PI * u;
    return std::array<double, 3>{ 2 * std::cos(a), std::sin(a), 6 * v };
  });
  std::vector<std::array<double, 3> > normal;
  for(const auto& p : s.points)
  {
    const double nx = p[0] / 4, ny = p[1], len = std::hypot(nx, ny);
    normal.push_back({ nx / len, ny / len, 0. });
  }
  fs_test::add_noise_along(s, normal, 0.05);
  return s;
}

BOOST_AUTO_TEST_CASE(one_piece_or_no_surface_of_revolution_gets_none)
{
  std::size_t marked = 0;
  // a noisy cylinder of radius 1 and height 6 (32 facets round, 30 rows): one straight piece
  {
    const SM m = fs_test::to_mesh<SM>(fs_test::noisy_cylinder(1., 6., 32, 30, 0.05));
    const I::Mesh_indexing<SM> idx(m);
    revolution_seams_of(m, idx, marked);
    BOOST_TEST(marked == 0u);
  }
  // a noisy elliptic cylinder: its normals meet no line, and about the best one its
  // profile is no thin curve
  {
    const SM m = fs_test::to_mesh<SM>(noisy_elliptic_cylinder());
    const I::Mesh_indexing<SM> idx(m);
    revolution_seams_of(m, idx, marked);
    BOOST_TEST(marked == 0u);
  }
  // a noisy plane: no axis, or about one near its normal a single straight piece
  {
    fs_test::Soup s = fs_test::plane(2., 40);
    fs_test::add_noise_along(s, std::vector<std::array<double, 3> >(s.points.size(), { 0., 0., 1. }), 0.03);
    const SM m = fs_test::to_mesh<SM>(s);
    const I::Mesh_indexing<SM> idx(m);
    revolution_seams_of(m, idx, marked);
    BOOST_TEST(marked == 0u);
  }
}

// A round tube of radius 1.5 bent along a planar spine: 10 straight along z, a quarter
// circle of radius 6 in the xz plane, 12 straight along x (the generated bent pipe's
// outer wall), 32 facets round (0.29) and 105 rows along the spine's length 31.42 (0.30),
// every vertex moved along the tube's normal by add_noise_along() of `amplitude`. Its
// joints (spine lengths 10 and 19.42) are tangent seams: no dihedral angle marks them.
struct Bent_pipe
{
  static constexpr double radius = 1.5, bend = 6., first = 10., last = 12.;
  static double joint(int k) { return k == 0 ? first : first + bend * M_PI / 2; }
  static double length() { return joint(1) + last; }
  // the spine's point and the bend plane's unit normal N (towards the bend's centre on
  // the arc) at spine length t; the binormal is y
  static void frame(double t, Eigen::Vector3d& c, Eigen::Vector3d& n)
  {
    if(t <= first)
    {
      c = Eigen::Vector3d(0, 0, t);
      n = Eigen::Vector3d(1, 0, 0);
    }
    else if(t <= joint(1))
    {
      const double phi = (t - first) / bend;
      c = Eigen::Vector3d(bend - bend * std::cos(phi), 0, first + bend * std::sin(phi));
      n = Eigen::Vector3d(std::cos(phi), 0, -std::sin(phi));
    }
    else
    {
      c = Eigen::Vector3d(bend + t - joint(1), 0, first + bend);
      n = Eigen::Vector3d(0, 0, -1);
    }
  }
  // the spine length of a point within the radius of the spine
  static double spine_length(const Eigen::Vector3d& p)
  {
    const double phi = std::atan2(p.z() - first, bend - p.x());
    if(phi < 0) return p.z();
    if(phi > M_PI / 2) return joint(1) + p.x() - bend;
    return first + bend * phi;
  }
  static fs_test::Soup soup(double amplitude)
  {
    std::vector<std::array<double, 3> > normal;
    fs_test::Soup s = fs_test::parametric_grid(32, 105, true, false, [&](double u, double v) {
      Eigen::Vector3d c, n;
      frame(v * length(), c, n);
      const double a = 2 * M_PI * u;
      const Eigen::Vector3d d = std::cos(a) * n + std::sin(a) * Eigen::Vector3d(0, 1, 0);
      normal.push_back({ d.x(), d.y(), d.z() });
      const Eigen::Vector3d q = c + radius * d;
      return std::array<double, 3>{ q.x(), q.y(), q.z() };
    });
    fs_test::add_noise_along(s, normal, amplitude);
    return s;
  }
};

// The marked edges of a bent pipe: per joint, how many, and how far (along the spine)
// the farthest of their vertices is from it (returned); and the regions they bound.
std::array<double, 2> check_pipe_seams(double amplitude, double tolerance)
{
  const SM m = fs_test::to_mesh<SM>(Bent_pipe::soup(amplitude));
  const I::Mesh_indexing<SM> idx(m);
  std::size_t marked = 0;
  const std::vector<char> is_crease = revolution_seams_of(m, idx, marked);
  std::size_t count[2] = { 0, 0 };
  double farthest[2] = { 0., 0. };
  for(std::size_t e = 0; e < is_crease.size(); ++e)
  {
    if(!is_crease[e]) continue;
    BOOST_TEST(is_crease[e] == 2); // a curvature discontinuity
    const auto h = halfedge(idx.edge_at(e), m);
    double t[2];
    for(int k = 0; k < 2; ++k)
    {
      const auto& q = m.point(k == 0 ? source(h, m) : target(h, m));
      t[k] = Bent_pipe::spine_length(Eigen::Vector3d(q.x(), q.y(), q.z()));
    }
    const double mid = 0.5 * (t[0] + t[1]);
    const int j = std::abs(mid - Bent_pipe::joint(0)) < std::abs(mid - Bent_pipe::joint(1)) ? 0 : 1;
    ++count[j];
    for(double tk : t) farthest[j] = (std::max)(farthest[j], std::abs(tk - Bent_pipe::joint(j)));
  }
  BOOST_TEST_MESSAGE("amplitude " << amplitude << ": " << count[0] << " and " << count[1] << " edges, at most "
                                  << farthest[0] << " and " << farthest[1] << " from the joints");
  BOOST_TEST(marked == count[0] + count[1]);
  for(int j = 0; j < 2; ++j)
  {
    // a closed ring round the tube takes at least one edge per facet
    BOOST_TEST(count[j] >= 32u);
    BOOST_TEST(farthest[j] <= tolerance);
  }
  // the seams part the straight pieces from the arc: three regions
  const std::vector<std::size_t> root = I::face_components(idx, [&](std::size_t e) { return !is_crease[e]; });
  const std::set<std::size_t> regions(root.begin(), root.end());
  BOOST_TEST(regions.size() == 3u);
  return { farthest[0], farthest[1] };
}

BOOST_AUTO_TEST_CASE(bent_pipe_into_straight_pieces_and_arc)
{
  // Exact: the spine of the tube's faces is the spine up to the facets (a face's
  // centroid and normal lie a little inside the tube), so the joints are cut on the rows
  // that hold them (a row is 0.30 long, and a marked edge's far vertex one row off).
  const std::array<double, 2> exact = check_pipe_seams(0., 0.31);
  // Noise uniform in +-0.1 along the normals (a standard deviation of 0.058, 0.2% of
  // the diagonal 27.4, a fifth of an edge): the straight pieces' and the arc's fits, each
  // over thousands of faces, touch within a fraction of a row of the joints, so the
  // seams lie on the rows that hold the joints, as on the exact pipe: no vertex of theirs
  // is farther from a joint than the exact pipe's. (From the fit errors alone a tangent
  // joint is only placed within about sqrt(2 R sigma) of it, R = 6 the bend's radius:
  // 0.83, plus a row; such cuts left vertices 0.33 from the second joint, whose row's
  // far side is 0.03 from it.)
  const std::array<double, 2> noisy = check_pipe_seams(0.1, 0.31);
  for(int j = 0; j < 2; ++j) BOOST_TEST(noisy[j] <= exact[j] + 1e-9);
}

// The creases left after mark_revolution_seams() with crease angles: the ring of edges
// at half height `middle` of a noisy surface 6 high, 30 rows of 0.2, 64 facets round,
// marked as creases of `ring_angle` degrees.
std::size_t creases_left(const SM& m, double middle, double ring_angle)
{
  const I::Mesh_indexing<SM> idx(m);
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  std::vector<char> is_crease(idx.number_of_edges(), 0);
  std::vector<double> angle(idx.number_of_edges(), 0.);
  std::size_t ring = 0;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto h = halfedge(idx.edge_at(e), m);
    if(std::abs(m.point(source(h, m)).z() - middle) < 0.01 && std::abs(m.point(target(h, m)).z() - middle) < 0.01)
    {
      is_crease[e] = 1;
      angle[e] = ring_angle;
      ++ring;
    }
  }
  BOOST_TEST(ring == 64u);
  const std::size_t marked = I::mark_revolution_seams(idx, get(CGAL::vertex_point, m), g.normal, g.area, g.centroid,
                                                      g.begin, g.ring, is_crease, &angle);
  BOOST_TEST(marked == 0u); // one piece above and below the ring: no seam
  return std::size_t(std::count(is_crease.begin(), is_crease.end(), char(1)));
}

BOOST_AUTO_TEST_CASE(weak_creases_inside_a_piece_are_cleared)
{
  // A noisy cylinder (radius 1, 64 facets round) is one straight piece of its profile:
  // the ring, a crease of 30 degrees (below Revolution_seams::clear_below_angle), is
  // noise inside it and is unmarked; one of 70 degrees parts it into two regions, which
  // are one straight piece together (join_coaxial_regions()), and is unmarked too.
  const SM cylinder = fs_test::to_mesh<SM>(fs_test::noisy_cylinder(1., 6., 64, 30, 0.05));
  // (z from -3 to 3)
  BOOST_TEST(creases_left(cylinder, 0., 30.) == 0u);
  BOOST_TEST(creases_left(cylinder, 0., 70.) == 0u);
  // on a noisy elliptic cylinder (z from 0 to 6), no surface of revolution, the weak
  // ring stays
  BOOST_TEST(creases_left(fs_test::to_mesh<SM>(noisy_elliptic_cylinder()), 3., 30.) == 64u);
}

// A noisy cylinder (radius 1, z from -3 to 3, 30 rows of 0.2, 64 facets round), closed
// at the bottom by a flat cap of 64 triangles and at the top by one too, or with
// `cone_rings` by a cone of that many rings of triangles (2 per facet, 64 at the apex)
// rising by 20 degrees from the rim, its points moved along z by the noise of the
// cylinder; its first `side_faces` faces are the side's.
SM capped_noisy_cylinder(std::size_t& side_faces, int cone_rings = 0)
{
  fs_test::Soup s = fs_test::noisy_cylinder(1., 6., 64, 30, 0.05);
  side_faces = s.faces.size();
  const std::size_t bottom = s.points.size(), top = bottom + 1;
  const double rise = std::tan(20. * M_PI / 180.);
  s.points.push_back({ 0., 0., -3. });
  s.points.push_back({ 0., 0., cone_rings > 0 ? 3. + rise : 3. });
  // the cone's inner rings (ring 0: the cylinder's top row)
  fs_test::Soup cone;
  for(int j = 1; j < cone_rings; ++j)
    for(std::size_t i = 0; i < 64; ++i)
    {
      const double rho = 1. - double(j) / cone_rings, a = 2 * M_PI * double(i) / 64;
      cone.points.push_back({ rho * std::cos(a), rho * std::sin(a), 3. + (1. - rho) * rise });
    }
  fs_test::add_noise_along(cone, std::vector<std::array<double, 3> >(cone.points.size(), { 0., 0., 1. }), 0.05);
  const std::size_t first_ring = s.points.size();
  s.points.insert(s.points.end(), cone.points.begin(), cone.points.end());
  auto ring = [&](int j, std::size_t i) { return j == 0 ? 30 * 64 + i : first_ring + std::size_t(j - 1) * 64 + i; };
  for(std::size_t i = 0; i < 64; ++i)
  {
    const std::size_t j = (i + 1) % 64;
    s.faces.push_back({ bottom, j, i });
    for(int k = 1; k < cone_rings; ++k)
    {
      s.faces.push_back({ ring(k, i), ring(k - 1, i), ring(k - 1, j) });
      s.faces.push_back({ ring(k, i), ring(k - 1, j), ring(k, j) });
    }
    const int last = (std::max)(cone_rings - 1, 0);
    s.faces.push_back({ top, ring(last, i), ring(last, j) });
  }
  return fs_test::to_mesh<SM>(s);
}

// Per edge of capped_noisy_cylinder(): 1 where a cap meets the side, 2 on the ring at
// z = 0 (only its edges with x > 0 if `half`), 3 between faces of two islands or an
// island and the rest (`island_of`: per face, its island or 0), else 0.
template <typename Island>
std::vector<int> capped_cylinder_edges(const SM& m, const I::Mesh_indexing<SM>& idx, std::size_t side_faces, bool half,
                                       Island island_of)
{
  std::vector<int> kind(idx.number_of_edges(), 0);
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto h = halfedge(idx.edge_at(e), m);
    const std::size_t f = idx.face_id(h), f2 = idx.face_id(opposite(h, m));
    const auto& p = m.point(source(h, m));
    const auto& q = m.point(target(h, m));
    if((f >= side_faces) != (f2 >= side_faces))
      kind[e] = 1;
    else if(std::abs(p.z()) < 0.01 && std::abs(q.z()) < 0.01 && (!half || (p.x() > 0 && q.x() > 0)))
      kind[e] = 2;
    else if(island_of(f) != island_of(f2))
      kind[e] = 3;
  }
  return kind;
}

// Marks the edges of capped_noisy_cylinder() (with `cone_rings`) by hand
// (capped_cylinder_edges(), the ring whole or `half`, `islands` islands of 3 rows by 4
// facets side by side from 0 facets round, between z = `island_z` and `island_z` + 0.6),
// the caps' borders at 90 degrees and the others at 70, and runs mark_revolution_seams()
// on them, with `clusters` or not; `count` receives the edges of each kind, and the edges
// of each kind left marked 1 are returned. None may be marked 2 (the cylinder and the
// cone are one piece each).
std::array<std::size_t, 4> capped_cylinder_creases_left(bool half, int islands, bool clusters,
                                                        std::array<std::size_t, 4>& count, double island_z = 1.,
                                                        int cone_rings = 0)
{
  std::size_t side_faces = 0;
  const SM m = capped_noisy_cylinder(side_faces, cone_rings);
  const I::Mesh_indexing<SM> idx(m);
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  auto island_of = [&](std::size_t f) {
    const auto& c = g.centroid[f];
    const double a = std::atan2(c.y(), c.x()) / (2 * M_PI / 64);
    if(f >= side_faces || c.z() < island_z || c.z() > island_z + 0.6 || a < 0. || a > 4. * islands) return 0;
    return 1 + int(a / 4.);
  };
  std::vector<std::size_t> island_faces(islands + 1, 0);
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f) ++island_faces[island_of(f)];
  for(int k = 1; k <= islands; ++k) BOOST_TEST(island_faces[k] == 24u);
  const std::vector<int> kind = capped_cylinder_edges(m, idx, side_faces, half, island_of);
  count = {};
  for(int k : kind) ++count[k];
  std::vector<char> is_crease(idx.number_of_edges(), 0);
  std::vector<double> angle(idx.number_of_edges(), 0.);
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    is_crease[e] = kind[e] != 0;
    angle[e] = kind[e] == 1 ? 90. : kind[e] != 0 ? 70. : 0.;
  }
  const std::size_t marked = I::mark_revolution_seams(idx, get(CGAL::vertex_point, m), g.normal, g.area, g.centroid,
                                                      g.begin, g.ring, is_crease, &angle, true, clusters);
  BOOST_TEST(marked == 0u); // one piece: no seam
  std::array<std::size_t, 4> left{};
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e) left[kind[e]] += is_crease[e] == 1;
  return left;
}

BOOST_AUTO_TEST_CASE(strong_creases_and_islands_inside_a_piece_are_cleared)
{
  // The capped noisy cylinder, marked by hand: the caps' borders (90 degrees), half a
  // ring at z = 0 (70 degrees, the edges with x > 0) and the border of an island of 24
  // faces (70 degrees: 3 rows by 4 facets). The cylinder is one straight piece of its
  // profile: the half ring bounds nothing and is noise inside it; the island's normals
  // follow the cylinder's, so its border is noise too; the caps (small regions inside
  // the piece too) are normal to the cylinder and stay.
  std::array<std::size_t, 4> count{};
  const std::array<std::size_t, 4> left = capped_cylinder_creases_left(true, 1, false, count);
  BOOST_TEST(count[1] == 128u);
  BOOST_TEST(count[2] >= 28u);
  BOOST_TEST(count[3] == 14u); // 4 facets above and below, 3 rows at either end
  BOOST_TEST(left[1] == 128u);
  BOOST_TEST(left[2] == 0u);
  BOOST_TEST(left[3] == 0u);
}

BOOST_AUTO_TEST_CASE(regions_of_one_surface_and_clusters_of_islands_are_joined)
{
  // The capped noisy cylinder, marked by hand: the caps' borders (90 degrees), a whole
  // ring at z = 0 (70 degrees), which parts the cylinder into two regions of 1920
  // faces, and the borders of two islands of 24 faces side by side (70 degrees; 3 rows
  // by 4 facets each, one from 0 to 4 facets round, the other from 4 to 8, their common
  // border marked too). The two regions are one surface: the ring goes with or without
  // clusters. The islands touch each other, so each alone is no island; as one cluster
  // (a heavily noisy mesh) they are, and their borders go. The caps (64 faces each,
  // normal to the cylinder) stay in both runs.
  for(bool clusters : { false, true })
  {
    BOOST_TEST_CONTEXT("clusters " << clusters)
    {
      std::array<std::size_t, 4> count{};
      const std::array<std::size_t, 4> left = capped_cylinder_creases_left(false, 2, clusters, count);
      BOOST_TEST(count[1] == 128u);
      BOOST_TEST(count[2] == 64u);
      BOOST_TEST(count[3] == 25u); // 8 facets above and below, 3 rows at the ends and between
      BOOST_TEST(left[1] == 128u);
      BOOST_TEST(left[2] == 0u);
      BOOST_TEST(left[3] == (clusters ? 0u : count[3]));
    }
  }
}

BOOST_AUTO_TEST_CASE(small_region_at_an_end_grows_into_its_piece)
{
  // The noisy cylinder capped at the top by a cone of 4 rings (448 faces, one piece of
  // its own profile, its profile normal 70 degrees from the cylinder's), marked by hand:
  // the caps' borders (90 degrees) and the border of a region of 24 faces (70 degrees: 3
  // rows by 4 facets) in the cylinder's top rows, which touches the cone. Its neighbours
  // lie in two pieces, so it is no island; on a heavily noisy mesh (clusters) it grows
  // into the cylinder's piece, whose profile normal agrees with its own, where the
  // cone's does not: its border with the cylinder goes and the one with the cone stays.
  for(bool clusters : { false, true })
  {
    BOOST_TEST_CONTEXT("clusters " << clusters)
    {
      std::array<std::size_t, 4> count{};
      const std::array<std::size_t, 4> left = capped_cylinder_creases_left(false, 1, clusters, count, 2.4, 4);
      BOOST_TEST(count[1] == 128u);
      BOOST_TEST(count[2] == 64u); // the ring at z = 0, marked too: one surface, it goes
      BOOST_TEST(count[3] == 10u); // 4 facets below, 3 rows at either end
      BOOST_TEST(left[1] == 128u);
      BOOST_TEST(left[2] == 0u);
      BOOST_TEST(left[3] == (clusters ? 0u : count[3]));
    }
  }
}

// Requires the mesh of `idx` to be rough but not noisy, as a smooth model is.
void require_rough_but_not_noisy(const I::Mesh_indexing<SM>& idx)
{
  const double roughness = fs_test::face_geometry_of(idx).roughness;
  BOOST_TEST_MESSAGE("roughness " << roughness);
  BOOST_REQUIRE(roughness > I::crease_filter_roughness);
  BOOST_REQUIRE(roughness <= I::Crease_gap::raw_roughness);
}

BOOST_AUTO_TEST_CASE(lightly_noisy_hopper_gets_its_seams)
{
  // A hopper round the z axis, 64 facets round: a disk at z = 9 (radii 0.5 to 5, 9
  // rows), a bin wall of radius 5 down to z = 6 (6 rows), a cone down to radius 1 at
  // z = 0 (14 rows) and a spout of radius 1 down to z = -3 (6 rows); the cone bends from
  // the wall and the spout by 33.7 degrees. Noise uniform in +-0.02 along the normals
  // (0.1% of the diagonal 16.6) makes it rough but not noisy, as a smooth model: its
  // filter blurs those bends. Its disk holds a fifth of its area or more, so it gets the
  // plane borders as a noisy mesh does, and the revolution seams as every rough mesh.
  const std::array<std::array<double, 2>, 5> corner{ { { 9., 0.5 }, { 9., 5. }, { 6., 5. }, { 0., 1. }, { -3., 1. } } };
  const std::array<int, 4> segment_rows{ 9, 6, 14, 6 };
  auto profile = [&](double j) {
    j = (std::max)(0., (std::min)(35., j));
    for(int k = 0; k < 4; ++k)
    {
      if(j <= segment_rows[k] || k == 3)
      {
        const double t = (std::min)(1., j / segment_rows[k]);
        return std::array<double, 2>{ corner[k][0] + t * (corner[k + 1][0] - corner[k][0]),
                                      corner[k][1] + t * (corner[k + 1][1] - corner[k][1]) };
      }
      j -= segment_rows[k];
    }
    return corner[4];
  };
  const SM m = fs_test::to_mesh<SM>(noisy_revolution(64, 35, profile, 0.02));
  const I::Mesh_indexing<SM> idx(m);
  require_rough_but_not_noisy(idx);

  const fs_test::Detected_creases detected = fs_test::detect_creases_at_defaults(idx);
  // both circles of the cone, z = 6 and z = 0, marked round the axis (an edge per facet
  // or more) within a row (0.5) of the circle
  std::array<std::size_t, 2> on_circle{ 0, 0 };
  std::size_t seams = 0;
  for(std::size_t e = 0; e < detected.is_crease.size(); ++e)
  {
    if(!detected.is_crease[e]) continue;
    seams += detected.is_crease[e] == 2;
    const auto h = halfedge(idx.edge_at(e), m);
    const double z0 = m.point(source(h, m)).z(), z1 = m.point(target(h, m)).z();
    for(int c = 0; c < 2; ++c)
    {
      const double at = c == 0 ? 6. : 0.;
      if(std::abs(z0 - at) <= 0.55 && std::abs(z1 - at) <= 0.55) ++on_circle[c];
    }
  }
  BOOST_TEST_MESSAGE("marked on the circles: " << on_circle[0] << ", " << on_circle[1] << "; seams " << seams);
  BOOST_TEST(on_circle[0] >= 64u);
  BOOST_TEST(on_circle[1] >= 64u);
  BOOST_TEST(seams > 0u);
  // the disk, the wall, the cone and the spout: four regions of a row or more
  const std::vector<std::size_t> root = I::face_components(idx, [&](std::size_t e) { return !detected.is_crease[e]; });
  std::map<std::size_t, std::size_t> size;
  for(std::size_t r : root) ++size[r];
  std::size_t regions = 0;
  for(const auto& r : size) regions += r.second >= 64u;
  BOOST_TEST(regions == 4u);
}


BOOST_AUTO_TEST_CASE(lightly_noisy_nail_without_planes_gets_its_tip_seam)
{
  // A nail's shank and tip round the z axis, 64 facets round: a cylinder of radius 1
  // from z = 0 to 8 (32 rows of 0.25) and a cone bending from it by 15 degrees, below the
  // crease angle (20), down to radius 0.3 at z = 8 + 0.7 / tan(15 degrees) = 10.61 (10
  // rows). Noise uniform in +-0.01 along the normals (0.09% of the diagonal 11.2) makes
  // it rough but not noisy, as a smooth model, and it has no plane: the circle z = 8 is
  // a seam round the axis (an edge per facet or more, within a row of it), nothing else
  // is marked, and the shank and the tip are the two regions.
  const double run = 0.7 / std::tan(15. * M_PI / 180.);
  auto profile = [&](double j) {
    if(j <= 32) return std::array<double, 2>{ 0.25 * j, 1. };
    const double t = (std::min)(1., (j - 32) / 10.);
    return std::array<double, 2>{ 8. + run * t, 1. - 0.7 * t };
  };
  const SM m = fs_test::to_mesh<SM>(noisy_revolution(64, 42, profile, 0.01));
  const I::Mesh_indexing<SM> idx(m);
  require_rough_but_not_noisy(idx);
  const fs_test::Detected_creases detected = fs_test::detect_creases_at_defaults(idx);
  std::size_t on_circle = 0, elsewhere = 0;
  for(std::size_t e = 0; e < detected.is_crease.size(); ++e)
  {
    if(!detected.is_crease[e]) continue;
    const auto h = halfedge(idx.edge_at(e), m);
    const double z0 = m.point(source(h, m)).z(), z1 = m.point(target(h, m)).z();
    if(std::abs(z0 - 8.) <= 0.3 && std::abs(z1 - 8.) <= 0.3) ++on_circle;
    else ++elsewhere;
  }
  BOOST_TEST_MESSAGE("marked on the circle " << on_circle << ", elsewhere " << elsewhere);
  BOOST_TEST(on_circle >= 64u);
  BOOST_TEST(elsewhere == 0u);
  const std::vector<std::size_t> root = I::face_components(idx, [&](std::size_t e) { return !detected.is_crease[e]; });
  std::map<std::size_t, std::size_t> size;
  for(std::size_t r : root) ++size[r];
  BOOST_TEST(size.size() == 2u);
}

BOOST_AUTO_TEST_SUITE_END()
