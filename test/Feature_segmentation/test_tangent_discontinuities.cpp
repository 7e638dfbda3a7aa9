// Curvature discontinuities of CAD tessellations (tangent_discontinuities, on by
// default): a floor, a quarter-cylinder fillet and a wall, tangent to each other,
// tessellated as a CAD tessellator does (vertices on the straight rulings). No edge bends
// by 20 degrees, so there is no crease; the two tangent lines are the only edges with a
// plane on one side, and they give exactly the three faces of the part.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/internal/seam_lines.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "crease_meshes.h"
#include "fandisk_reference.h"
#include "test_meshes.h"

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;

const double pi = 3.14159265358979323846;
const double fillet_radius = 0.3;
const int floor_segments = 4, fillet_segments = 6, wall_segments = 4;

// The profile point i (of floor_segments + fillet_segments + wall_segments + 1) in the
// (x, z) plane: the floor from x = -1 to 0 at z = 0, the fillet of fillet_radius around
// (0, r) in steps of 90 / fillet_segments = 15 degrees (the tangent lines bend by half
// a step, 7.5 degrees), the wall at x = r up to z = r + 1.
std::pair<double, double> profile(int i)
{
  if(i <= floor_segments) return { -1. + double(i) / floor_segments, 0. };
  if(i <= floor_segments + fillet_segments)
  {
    const double t = 0.5 * pi * double(i - floor_segments) / fillet_segments;
    return { fillet_radius * std::sin(t), fillet_radius * (1. - std::cos(t)) };
  }
  return { fillet_radius, fillet_radius + double(i - floor_segments - fillet_segments) / wall_segments };
}

// The profile swept along y over [0, 1] in `rulings` steps.
fs_test::Soup filleted_corner(int rulings)
{
  const int nu = floor_segments + fillet_segments + wall_segments;
  return fs_test::parametric_grid(nu, rulings, false, false, [nu](double u, double v) {
    const auto p = profile(int(std::lround(u * nu)));
    return std::array<double, 3>{ p.first, v, p.second };
  });
}

// 0 on the floor, 1 on the fillet, 2 on the wall, from the face's centroid.
int part_of(const SM& m, SM::Face_index f)
{
  double x = 0, z = 0;
  for(auto v : vertices_around_face(halfedge(f, m), m)) { x += m.point(v).x() / 3; z += m.point(v).z() / 3; }
  if(z < 1e-9) return 0;
  return x > fillet_radius - 1e-9 ? 2 : 1;
}

// Whether edge e lies on one of the two tangent lines (x = 0, z = 0 or x = z = r).
bool on_tangent_line(const SM& m, SM::Edge_index e)
{
  const auto& p = m.point(source(halfedge(e, m), m));
  const auto& q = m.point(target(halfedge(e, m), m));
  auto on = [](const Epick::Point_3& a, double x, double z) { return std::abs(a.x() - x) < 1e-12 && std::abs(a.z() - z) < 1e-12; };
  return (on(p, 0., 0.) && on(q, 0., 0.)) || (on(p, fillet_radius, fillet_radius) && on(q, fillet_radius, fillet_radius));
}

void corner_is_floor_fillet_and_wall(const fs_test::Soup& s, std::size_t tangent_edges)
{
  const SM m = fs_test::to_mesh<SM>(s);
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == tangent_edges);
  for(auto e : edges(m))
  {
    BOOST_TEST(seg.is_crease_edge(e) == on_tangent_line(m, e));
    if(seg.is_crease_edge(e)) BOOST_TEST(seg.weight(e) < 0.); // cutting there pays at the default alpha
  }
  BOOST_TEST(seg.number_of_patches() == 3u);
  std::set<std::pair<std::size_t, int> > pairs;
  for(auto f : faces(m)) pairs.insert({ seg.patch(f), part_of(m, f) });
  BOOST_TEST(pairs.size() == 3u); // each face on its own side of both tangent lines
}

// A round rod of radius 1 bent by a quarter turn: a straight cylinder of length 6 along
// z, a quarter torus (the bend's radius 4) and a second cylinder of length 6 along x,
// each meeting the next tangentially, 32 facets round, with flat ends. `side` gets the
// part of every face: 0 and 2 the cylinders, 1 the torus, 3 and 4 the ends.
const double rod_radius = 1., bend_radius = 4., straight_length = 6.;
fs_test::Soup bent_rod(std::vector<int>& side)
{
  const int around = 32, straight_rings = 12, bend_rings = 16;
  fs_test::Soup s;
  std::vector<int> ring_part; // per ring interval
  // the rings: centre, the in-plane normal N (the y axis is the other direction)
  auto add_ring = [&](const std::array<double, 3>& c, const std::array<double, 3>& n) {
    for(int i = 0; i < around; ++i)
    {
      const double a = 2 * pi * i / around, cn = rod_radius * std::cos(a), sn = rod_radius * std::sin(a);
      s.points.push_back({ c[0] + cn * n[0], c[1] + sn, c[2] + cn * n[2] });
    }
  };
  for(int j = 0; j <= straight_rings; ++j)
    add_ring({ 0., 0., straight_length * j / straight_rings }, { 1., 0., 0. });
  for(int j = 1; j <= bend_rings; ++j)
  {
    const double phi = 0.5 * pi * j / bend_rings;
    add_ring({ bend_radius * (1 - std::cos(phi)), 0., straight_length + bend_radius * std::sin(phi) },
             { std::cos(phi), 0., -std::sin(phi) });
  }
  for(int j = 1; j <= straight_rings; ++j)
    add_ring({ bend_radius + straight_length * j / straight_rings, 0., straight_length + bend_radius }, { 0., 0., -1. });
  const int rings = 2 * straight_rings + bend_rings + 1;
  for(int j = 0; j + 1 < rings; ++j) ring_part.push_back(j < straight_rings ? 0 : j < straight_rings + bend_rings ? 1 : 2);
  const std::size_t first_end = s.points.size();
  s.points.push_back({ 0., 0., 0. });
  s.points.push_back({ bend_radius + straight_length, 0., straight_length + bend_radius });
  auto at = [&](int i, int j) { return std::size_t(j * around + (i % around)); };
  side.clear();
  for(int j = 0; j + 1 < rings; ++j)
    for(int i = 0; i < around; ++i)
    {
      s.faces.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      s.faces.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
      side.insert(side.end(), { ring_part[j], ring_part[j] });
    }
  for(int i = 0; i < around; ++i)
  {
    s.faces.push_back({ first_end, at(i + 1, 0), at(i, 0) });
    s.faces.push_back({ first_end + 1, at(i, rings - 1), at(i + 1, rings - 1) });
    side.insert(side.end(), { 3, 4 });
  }
  return s;
}

} // namespace

BOOST_AUTO_TEST_SUITE(tangent_discontinuities)

// The bent rod: no edge of its side bends by 20 degrees (11.25 round, 5.6 along the
// bend), and its cylinders and torus are tessellated alike, in flat quadrilaterals, so
// no flat region tells them apart; where they meet, k2 (0 on a cylinder, cos(t) / (4 +
// cos(t)) on the torus at the angle t from the bend's outside) jumps by up to 0.2 of k1
// (1). Seam lines run along both seam circles, except where the bend's sides leave k2
// continuous, and the segmentation closes them: the rod is its five faces. Without
// tangent discontinuities it is its ends and its side.
BOOST_AUTO_TEST_CASE(a_bent_rod_is_cut_at_its_seam_lines)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(bent_rod(side));
  BOOST_REQUIRE(CGAL::is_closed(m) && CGAL::is_triangle_mesh(m));
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == 64u); // the two ends
  std::size_t seams = 0;
  for(const auto& line : seg.feature_lines().lines)
  {
    if(line.type != FS::Feature_line_type::SEAM) continue;
    ++seams;
    for(const auto& p : line.points)
    {
      // on the first seam circle (z = 6) or the second (x = 4), within two rings
      const auto q = p.point(seg.working_mesh(), seg.working_mesh().points());
      BOOST_TEST((std::min)(std::abs(q.z() - straight_length), std::abs(q.x() - bend_radius)) < 1.);
    }
  }
  BOOST_TEST(seams >= 2u);
  BOOST_TEST(seg.number_of_patches() == 5u);
  // each side is mostly one patch of its own; the boundaries follow the seam circles to
  // within two rings (0.5 long along the cylinders, 0.39 along the torus): the faces of a
  // side outside its patch lie within 1 of a seam circle's plane, and they are few
  std::map<std::pair<int, std::size_t>, std::size_t> count; // (side, patch) -> faces
  std::size_t i = 0;
  for(auto f : faces(m)) ++count[{ side[i++], seg.patch(f) }];
  std::map<int, std::size_t> main_patch;
  for(int k = 0; k < 5; ++k)
  {
    std::size_t best = 0;
    for(const auto& c : count)
      if(c.first.first == k && c.second > best) { best = c.second; main_patch[k] = c.first.second; }
  }
  std::set<std::size_t> distinct;
  for(const auto& p : main_patch) distinct.insert(p.second);
  BOOST_TEST(distinct.size() == 5u);
  std::size_t outside = 0;
  i = 0;
  for(auto f : faces(m))
  {
    const int k = side[i++];
    if(seg.patch(f) == main_patch[k]) continue;
    ++outside;
    double x = 0, z = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) { x += m.point(v).x() / 3; z += m.point(v).z() / 3; }
    BOOST_TEST((std::min)(std::abs(z - straight_length), std::abs(x - bend_radius)) < 1.);
  }
  BOOST_TEST(outside < num_faces(m) / 50);

  FS::Feature_aligned_segmentation<SM> without(m, FS::parameters::tangent_discontinuities(false));
  for(const auto& line : without.feature_lines().lines) BOOST_TEST((line.type != FS::Feature_line_type::SEAM));
  BOOST_TEST(without.number_of_patches() == 3u);
}

BOOST_AUTO_TEST_CASE(filleted_corner_is_its_three_faces_at_two_resolutions)
{
  corner_is_floor_fillet_and_wall(filleted_corner(4), 2 * 4);
  // the same shape subdivided flat: twice the rulings on each tangent line
  fs_test::Soup fine = filleted_corner(4);
  fs_test::subdivide_flat(fine);
  corner_is_floor_fillet_and_wall(fine, 2 * 8);
}

BOOST_AUTO_TEST_CASE(without_them_the_corner_has_no_crease)
{
  const SM m = fs_test::to_mesh<SM>(filleted_corner(4));
  FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::tangent_discontinuities(false));
  BOOST_TEST(seg.number_of_crease_edges() == 0u);
  BOOST_TEST(&seg.working_mesh() == &m); // nothing to cut
}

// A cylinder's strips all bend alike (1/r): no side is a plane, nothing is marked.
BOOST_AUTO_TEST_CASE(cylinder_has_no_discontinuity)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::cylinder(0.5, 1., 24, 6));
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == 0u);
}

// On fandisk, a clean tessellation cut open along creases, the crest lines weigh less
// than the creases by default: their alpha_e is alpha - 0.5 (0.1 at the default alpha),
// a crease's is alpha; crest_lines_on_clean_tessellations(true) gives them the full
// alpha (the paper's features). Both find the same crest lines. The figures (crease and
// seam edges, crest lines, patches) are those of data/fandisk.json.
BOOST_AUTO_TEST_CASE(clean_tessellation_crest_lines_weigh_less)
{
  using fs_test::fandisk_reference;
  SM m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m));
  FS::Feature_aligned_segmentation<SM> full(m, FS::parameters::crest_lines_on_clean_tessellations(true)), weak(m);
  BOOST_TEST(fandisk_reference("crease_edges") ==
             fandisk_reference("sharp_crease_edges") + fandisk_reference("seam_edges"));
  BOOST_TEST(full.number_of_crease_edges() == fandisk_reference("crease_edges"));
  BOOST_TEST(weak.number_of_crease_edges() == full.number_of_crease_edges());
  // the same crest lines; the CAD part's seam lines join them (alpha + 1: seam_lines.h)
  const auto crest_lines = [](const FS::Feature_lines<SM>& l) {
    return l.number_of_lines(FS::Feature_line_type::RIDGE) + l.number_of_lines(FS::Feature_line_type::VALLEY);
  };
  BOOST_TEST(full.feature_lines().lines.size() == fandisk_reference("crest_lines"));
  BOOST_TEST(crest_lines(weak.feature_lines()) == fandisk_reference("crest_lines"));
  BOOST_TEST(weak.feature_lines().number_of_lines(FS::Feature_line_type::SEAM) == fandisk_reference("seam_lines"));
  BOOST_TEST(weak.feature_lines().lines.size() == fandisk_reference("crest_lines") + fandisk_reference("seam_lines"));
  std::size_t crest_edges = 0, seam_line_edges = 0, crease_edges = 0;
  for(auto e : edges(m))
  {
    if(weak.is_crease_edge(e))
    {
      ++crease_edges;
      BOOST_TEST(weak.alpha(e) == 0.6, boost::test_tools::tolerance(1e-12));
    }
    else if(weak.is_feature_edge(e) && std::abs(weak.alpha(e) - 1.6) < 1e-12)
      ++seam_line_edges;
    else if(weak.is_feature_edge(e))
    {
      ++crest_edges;
      BOOST_TEST(weak.alpha(e) == 0.1, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(full.alpha(e) == 0.6, boost::test_tools::tolerance(1e-12));
    }
  }
  BOOST_TEST(crease_edges == fandisk_reference("crease_edges"));
  BOOST_TEST(crest_edges > 0u);
  BOOST_TEST((seam_line_edges > 0u) == (fandisk_reference("seam_lines") > 0));
  BOOST_TEST(crest_edges + seam_line_edges + crease_edges <= weak.number_of_feature_edges()); // on the working mesh
  // a global alpha edit moves the crest lines' alpha_e with it, 0.5 below, and the seam
  // lines', 1 above
  weak.set_alpha(1.5);
  for(auto e : edges(m))
    if(weak.is_feature_edge(e) && !weak.is_crease_edge(e))
      BOOST_TEST((std::abs(weak.alpha(e) - 1.0) < 1e-12 || std::abs(weak.alpha(e) - 2.5) < 1e-12));
  BOOST_TEST(FS::Feature_aligned_segmentation<SM>(m).number_of_patches() == fandisk_reference("patches"));
}

// The windows of the seam lines read their means from a grid of cells (Window_grid):
// vertices on a grid of spacing 0.1 in the plane z = 0 (normals up), jump 0 for x < 0 and
// 1 for x > 0, k2 0.25 everywhere, and under it a wall at z = -0.01 (normals down) with
// jump 5 and k2 -1; cells of side 0.2. The means far enough from x = 0 are exactly
// those of their side, the wall's never mix with the plane's, and nothing is found
// where there is no vertex.
BOOST_AUTO_TEST_CASE(seam_line_windows_average_their_side_only)
{
  std::vector<Eigen::Vector3d> points, normal;
  std::vector<double> jump, k2;
  for(int i = -20; i <= 20; ++i)
    for(int j = -20; j <= 20; ++j)
    {
      const double x = 0.1 * i + 0.05, y = 0.1 * j + 0.05; // no vertex on x = 0
      points.emplace_back(x, y, 0.);
      normal.emplace_back(0., 0., 2.); // any length: only its side counts
      jump.push_back(x > 0 ? 1. : 0.);
      k2.push_back(0.25);
      points.emplace_back(x, y, -0.01);
      normal.emplace_back(0., 0., -1.);
      jump.push_back(5.);
      k2.push_back(-1.);
    }
  const Eigen::Vector3d lo(-2.05, -2.05, -0.01);
  const FS::internal::Window_grid grid(points, normal, jump, k2, lo, 0.2);
  const Eigen::Vector3d up(0., 0., 1.), down(0., 0., -1.);
  // at x = +-0.6 the eight cells round the point lie on one side of x = 0
  const auto right = grid.mean(Eigen::Vector3d(0.6, 0.3, 0.), up), left = grid.mean(Eigen::Vector3d(-0.6, 0.3, 0.), up);
  BOOST_TEST(right.found);
  BOOST_TEST(right.jump == 1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(right.k2 == 0.25, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(left.found);
  BOOST_TEST(left.jump == 0., boost::test_tools::tolerance(1e-12));
  // across x = 0 the mean lies between the sides
  const auto across = grid.mean(Eigen::Vector3d(0., 0.3, 0.), up);
  BOOST_TEST((across.jump > 0. && across.jump < 1.));
  // the wall below, read with its own normals, is only the wall
  const auto wall = grid.mean(Eigen::Vector3d(0.6, 0.3, -0.01), down);
  BOOST_TEST(wall.found);
  BOOST_TEST(wall.jump == 5., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(wall.k2 == -1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(!grid.mean(Eigen::Vector3d(0., 0., 5.), up).found); // no vertex there
  BOOST_TEST(!grid.mean(Eigen::Vector3d(0.6, 0.3, 0.), Eigen::Vector3d(1., 0., 0.)).found); // no vertex faces +x
}

BOOST_AUTO_TEST_SUITE_END()
