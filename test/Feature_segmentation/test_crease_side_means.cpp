// The side-mean creases of heavily noisy meshes (crease_side_means.h): on a noisy turned
// surface the cone's crease of 26.6 degrees, which the bilateral filter wipes out, is
// found along its circle, with detours of a few rows; on a noisy thin cylinder, whose
// curvature alone bends the two sides' mean normals by 29 degrees, nothing is added; on
// a roof the ridge is found, and once it is a crease it bounds the sides; a fillet's
// middle line is no crease at the lightly noisy meshes' ratio over half the radius, a
// ridge of the same angle is; the same creases at any thread count.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/crease_detection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include "crease_test_geometry.h"
#include "test_meshes.h"

#include <array>
#include <functional>
#include <tuple>
#include <cmath>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

BOOST_AUTO_TEST_SUITE(crease_side_means)

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
namespace I = FS::internal;

struct Geometry : fs_test::Face_geometry
{
  std::vector<Eigen::Vector3d> filtered;
};

// The raw normals and those of the bilateral filter as detect_creases() runs it on a
// heavily noisy mesh.
Geometry geometry_of(const I::Mesh_indexing<SM>& idx)
{
  Geometry g;
  static_cast<fs_test::Face_geometry&>(g) = fs_test::face_geometry_of(idx);
  g.filtered = I::filter_face_normals(g.normal, g.roughness, I::Normal_filter_ring(g.area, g.centroid, g.begin, g.ring),
                                      I::noisy_filter_rounds(g.roughness, 40), I::crease_filter_sigma_r, 0.);
  return g;
}

std::size_t count(const std::vector<char>& marks)
{
  std::size_t n = 0;
  for(char c : marks) n += c != 0;
  return n;
}

// The side-mean creases of the mesh at the crease angle of 20 degrees: the marks of
// `is_crease` (none if empty) with the edges added, their bends, and how many were added.
// `across`: the normals that give the plane across the surface.
struct Side_means
{
  std::vector<char> is_crease;
  std::vector<double> angle;
  std::size_t added = 0;
};

Side_means side_means(const SM& m, const I::Mesh_indexing<SM>& idx, const fs_test::Face_geometry& g,
                      const std::vector<Eigen::Vector3d>& across, std::vector<char> is_crease = {},
                      bool parallel = false, double narrower = I::Side_mean_creases::narrower)
{
  Side_means r;
  r.is_crease = is_crease.empty() ? std::vector<char>(idx.number_of_edges(), 0) : std::move(is_crease);
  r.angle.assign(idx.number_of_edges(), 0.);
  r.added = I::add_side_mean_creases(idx, get(CGAL::vertex_point, m), g.normal, g.area, g.centroid, across, 20.,
                                     r.is_crease, r.angle, parallel, narrower);
  return r;
}

// A grid of 40 x 40 cells of 0.05 over [-1, 1]^2 (one diagonal per cell) lifted to
// z = profile(x).
fs_test::Soup profile_grid(const std::function<double(double)>& profile)
{
  return fs_test::parametric_grid(40, 40, false, false, [&](double u, double v) {
    const double x = 2 * u - 1, y = 2 * v - 1;
    return std::array<double, 3>{ x, y, profile(x) };
  });
}

BOOST_AUTO_TEST_CASE(cone_crease_under_heavy_noise)
{
  // The cylinder and cone of fs_test::cylinder_and_cone(), whose crease of 26.6 degrees
  // runs along the circle z = 6 (48 edges). Radial noise uniform in +-0.1 (a standard
  // deviation of 0.058, 0.6% of the diagonal 9.8; 0.4 of the rows' height of 0.25).
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_cylinder_and_cone(0.1));
  const I::Mesh_indexing<SM> idx(m);
  const Geometry g = geometry_of(idx);
  BOOST_TEST_MESSAGE("raw roughness " << g.roughness);
  BOOST_TEST(g.roughness >= I::Crease_staircase::roughness); // heavily noisy
  auto within = [&](std::size_t e, double dz) {
    const auto h = halfedge(idx.edge_at(e), m);
    return std::abs(m.point(source(h, m)).z() - 6.) < dz && std::abs(m.point(target(h, m)).z() - 6.) < dz;
  };
  // the bilateral filter wipes the crease out: no edge of the circle bends by 20 degrees
  const std::vector<double> filtered_angle = I::dihedral_angles(idx, g.filtered);
  std::size_t filtered_on = 0;
  for(std::size_t e = 0; e < filtered_angle.size(); ++e)
    if(filtered_angle[e] >= 20. && within(e, 0.05)) ++filtered_on;
  BOOST_TEST(filtered_on == 0u);

  const auto [is_crease, angle, added] = side_means(m, idx, g, g.filtered);
  std::size_t on = 0, one_row = 0, two_rows = 0, far = 0;
  double least_on = 180., farthest = 0.;
  for(std::size_t e = 0; e < is_crease.size(); ++e)
    if(is_crease[e])
    {
      const auto h = halfedge(idx.edge_at(e), m);
      farthest = (std::max)({ farthest, std::abs(m.point(source(h, m)).z() - 6.), std::abs(m.point(target(h, m)).z() - 6.) });
      if(within(e, 0.05)) { ++on; least_on = (std::min)(least_on, angle[e]); }
      else if(within(e, 0.3)) ++one_row;
      else if(within(e, 0.55)) ++two_rows;
      else ++far;
    }
  BOOST_TEST_MESSAGE("added " << added << ": on the circle " << on << ", within one row " << one_row
                     << ", within two " << two_rows << ", farther " << far << " (at most " << farthest
                     << " from it); least bend on the circle "
                     << least_on);
  BOOST_TEST(added == count(is_crease));
  // At least seven eighths of the circle, each bending by the crease angle or more. The
  // noise moves the peak of the bend across the line by a row or more here and there:
  // the line takes diagonals and rows beside the circle there (fewer edges than the
  // circle's, mostly within two rows), none farther than four rows (1.0).
  BOOST_TEST(on >= 42u);
  BOOST_TEST(least_on >= 20.);
  BOOST_TEST(one_row + two_rows + far <= 48u);
  BOOST_TEST(far <= one_row + two_rows);
  BOOST_TEST(farthest <= 1.05);

  // and so do the creases of the whole detection
  const fs_test::Detected_creases detected = fs_test::detect_creases_at_defaults(idx);
  std::size_t detected_on = 0;
  for(std::size_t e = 0; e < detected.is_crease.size(); ++e)
    if(detected.is_crease[e] && within(e, 0.05)) ++detected_on;
  BOOST_TEST(!detected.clean);
  BOOST_TEST(detected_on >= 42u);
}

BOOST_AUTO_TEST_CASE(thin_cylinder_under_heavy_noise_gets_none)
{
  // A cylinder of radius 1 and height 6, 32 facets round (0.196 wide) and 30 rows (0.2
  // high): median edge length 0.2, so the disks have radius 0.6. A half disk's mean
  // normal turns by 4R / (3 pi r) from the edge's, the two sides' by 8R / (3 pi r) =
  // 0.51 rad = 29 degrees, well above the crease angle on every edge along the axis;
  // radial noise uniform in +-0.05 (0.25 of the rows' height). Over twice the radius the
  // bend doubles, over half of it it halves: no crease.
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_cylinder(1., 6., 32, 30, 0.05));
  const I::Mesh_indexing<SM> idx(m);
  const Geometry g = geometry_of(idx);
  BOOST_TEST_MESSAGE("raw roughness " << g.roughness);
  BOOST_TEST(g.roughness >= I::Crease_staircase::roughness);
  const Side_means r = side_means(m, idx, g, g.filtered);
  BOOST_TEST(r.added == 0u);
  BOOST_TEST(count(r.is_crease) == 0u);
}

BOOST_AUTO_TEST_CASE(a_crease_found_bounds_the_sides)
{
  // A noiseless roof: two planes meeting along the line x = 0 of a grid (z = |x| / 2
  // over [-1, 1]^2, 40 x 40 cells of 0.05, one diagonal per cell), whose normals are 2
  // atan(1/2) = 53.13 degrees apart. Without creases, the ridge's 40 edges bend by
  // exactly that much (their disks split at the ridge; those of the ends are cut by the
  // border on both sides alike) and are added; the edges parallel to it one column away
  // are not (the disk moved onto the ridge bends more), and of the rest only a few
  // diagonals of the ridge's faces are (their split is oblique), all within one column
  // of it. With the ridge marked a crease, the sides stop at it: no edge is added.
  const SM m = fs_test::to_mesh<SM>(profile_grid([](double x) { return 0.5 * std::abs(x); }));
  const I::Mesh_indexing<SM> idx(m);
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  auto within = [&](std::size_t e, double dx) {
    const auto h = halfedge(idx.edge_at(e), m);
    return std::abs(m.point(source(h, m)).x()) < dx && std::abs(m.point(target(h, m)).x()) < dx;
  };
  auto parallel_to_ridge = [&](std::size_t e) {
    const auto h = halfedge(idx.edge_at(e), m);
    return std::abs(m.point(source(h, m)).x() - m.point(target(h, m)).x()) < 1e-9;
  };
  const auto [is_crease, angle, added] = side_means(m, idx, g, g.normal);
  std::size_t ridge = 0, ridge_added = 0, beside = 0;
  for(std::size_t e = 0; e < is_crease.size(); ++e)
  {
    const bool on_ridge = within(e, 1e-9);
    ridge += on_ridge;
    if(!is_crease[e]) continue;
    if(on_ridge)
    {
      ++ridge_added;
      BOOST_TEST(angle[e] == 2 * std::atan(0.5) * 180. / M_PI, boost::test_tools::tolerance(1e-9));
    }
    else
    {
      ++beside;
      BOOST_TEST(within(e, 0.05 + 1e-9));
      BOOST_TEST(!parallel_to_ridge(e));
    }
  }
  BOOST_TEST_MESSAGE("added " << added << ": the ridge's " << ridge_added << " of " << ridge << ", " << beside
                     << " diagonals beside it");
  BOOST_TEST(ridge == 40u);
  BOOST_TEST(ridge_added == 40u);
  BOOST_TEST(added == ridge_added + beside);

  std::vector<char> marked(idx.number_of_edges(), 0);
  for(std::size_t e = 0; e < marked.size(); ++e) marked[e] = within(e, 1e-9) ? 1 : 0;
  const Side_means with = side_means(m, idx, g, g.normal, marked);
  BOOST_TEST(with.added == 0u);
  BOOST_TEST(count(with.is_crease) == 40u);
}

BOOST_AUTO_TEST_CASE(a_fillet_is_no_crease_on_a_lightly_noisy_mesh)
{
  // Two planes 60 degrees apart (slopes -+tan 30 degrees) joined by a noiseless fillet
  // whose normal turns evenly with x over |x| <= a, on the grid of the roof above (40 x 40
  // cells of 0.05 over [-1, 1]^2). Its median edge length is that of the edges along x on
  // the slopes, 0.05 / cos 30, so the disk's radius is R = 0.173; the fillet is 2a = 1.4 R
  // wide. Across its middle line x = 0 the sides' mean normals bend by about 34
  // degrees, the disks moved to either side less, the disk of twice the radius 1.36 times
  // as much (a wider bend than the 1.5 of a face of even curvature), and the disk of half
  // the radius 0.53 times as much (a crease between flat sides: all of it). The heavy-noise
  // ratio 0.4 takes the middle line for a crease (and edges of its faces beside it); the
  // light-noise ratio 0.65 adds nothing, and it still finds a ridge of the same 60 degrees
  // (z = |x| tan 30): its 40 edges, and beside them only edges of its faces.
  const double slope = std::tan(M_PI / 6), a = 0.7 * 3 * 0.05 / std::cos(M_PI / 6);
  auto fillet = [&](double x) {
    const double t = std::abs(x);
    // z' = tan(30 degrees * t / a) inside, tan 30 outside
    const double k = (M_PI / 6) / a;
    return t <= a ? -std::log(std::cos(k * t)) / k : -std::log(std::cos(M_PI / 6)) / k + (t - a) * slope;
  };
  auto run = [](const fs_test::Soup& s, double narrower) {
    const SM m = fs_test::to_mesh<SM>(s);
    const I::Mesh_indexing<SM> idx(m);
    const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
    const std::vector<char> is_crease = side_means(m, idx, g, g.normal, {}, false, narrower).is_crease;
    std::size_t middle = 0, other = 0;
    double farthest = 0.; // the largest |x| of the other edges' ends
    for(std::size_t e = 0; e < is_crease.size(); ++e)
    {
      if(!is_crease[e]) continue;
      const auto h = halfedge(idx.edge_at(e), m);
      const double x0 = std::abs(m.point(source(h, m)).x()), x1 = std::abs(m.point(target(h, m)).x());
      if(x0 < 1e-9 && x1 < 1e-9) ++middle;
      else
      {
        ++other;
        farthest = (std::max)(farthest, (std::max)(x0, x1));
      }
    }
    return std::make_tuple(middle, other, farthest);
  };
  const fs_test::Soup filleted = profile_grid(fillet), ridged = profile_grid([&](double x) { return std::abs(x) * slope; });
  const auto heavy = run(filleted, I::Side_mean_creases::narrower);
  const auto light = run(filleted, I::Side_mean_creases::narrower_light);
  const auto ridge = run(ridged, I::Side_mean_creases::narrower_light);
  BOOST_TEST_MESSAGE("fillet: " << std::get<0>(heavy) << " + " << std::get<1>(heavy) << " edges at ratio 0.4 (within "
                     << std::get<2>(heavy) << "), " << std::get<0>(light) << " + " << std::get<1>(light)
                     << " at 0.65; ridge: " << std::get<0>(ridge) << " + " << std::get<1>(ridge) << " (within "
                     << std::get<2>(ridge) << ")");
  BOOST_TEST(std::get<0>(heavy) == 40u);
  BOOST_TEST(std::get<2>(heavy) <= 0.05 + 1e-9);
  BOOST_TEST(std::get<0>(light) + std::get<1>(light) == 0u);
  BOOST_TEST(std::get<0>(ridge) == 40u);
  BOOST_TEST(std::get<2>(ridge) <= 0.05 + 1e-9);
}

#ifdef CGAL_LINKED_WITH_TBB
// Each edge is tested on its own, in ranges of at least 4,096 edges that TBB's threads
// share: the noisy cylinder and cone (4,800 edges, two ranges) gets the same creases and
// bends at 1, 2 and 8 threads as in one sequential pass.
BOOST_AUTO_TEST_CASE(the_same_creases_at_any_thread_count)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_cylinder_and_cone(0.1));
  const I::Mesh_indexing<SM> idx(m);
  const Geometry g = geometry_of(idx);
  BOOST_TEST(idx.number_of_edges() > 4096u);
  auto run = [&](bool parallel) {
    const Side_means r = side_means(m, idx, g, g.filtered, {}, parallel);
    return std::make_pair(r.is_crease, r.angle);
  };
  const auto sequential = run(false);
  BOOST_TEST(count(sequential.first) > 0u);
  for(int threads : { 1, 2, 8 })
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const auto parallel = run(true);
    BOOST_TEST((parallel.first == sequential.first), threads << " threads");
    BOOST_TEST((parallel.second == sequential.second), threads << " threads");
  }
}
#endif

BOOST_AUTO_TEST_SUITE_END()
