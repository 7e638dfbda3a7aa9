// The creases of heavily noisy meshes (crease_staircase.h): the staircase test on
// candidate lines of a flat grid (a line with parallel candidates on both sides within
// four edge lengths is a step, the outer lines and a lone line are not), and the normal
// filter along the gradient on a plane (exact) and on a noisy coarse cylinder (no steps
// where the bilateral filter makes them); the creases of the narrow filter
// (crease_narrow_filter.h): their lines' sizes on a grid (exact), and on a lightly noisy
// turned surface the cone's crease of 26.6 degrees, which the bilateral filter blurs.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/crease_detection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "crease_test_geometry.h"
#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

BOOST_AUTO_TEST_SUITE(crease_staircase)

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
namespace I = FS::internal;

typedef fs_test::Face_geometry Geometry;

Geometry geometry_of(const I::Mesh_indexing<SM>& idx) { return fs_test::face_geometry_of(idx); }

BOOST_AUTO_TEST_CASE(middle_of_three_parallel_lines_is_a_step)
{
  // a 40 x 40 grid over [-1, 1]^2 (cells of 0.05; mean edge length 0.057 with the
  // diagonals); candidates along the grid lines y = -0.5, -0.4, -0.3 (two cells apart,
  // well within four mean edge lengths) and a lone line x = 0.5 for y > 0
  const SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 40));
  const I::Mesh_indexing<SM> idx(m);
  const Geometry g = geometry_of(idx);
  std::vector<char> candidate(idx.number_of_edges(), 0);
  auto on_line = [&](std::size_t e, int axis, double at) {
    const auto h = halfedge(idx.edge_at(e), m);
    const auto& p = m.point(source(h, m));
    const auto& q = m.point(target(h, m));
    return std::abs(p[axis] - at) < 1e-9 && std::abs(q[axis] - at) < 1e-9;
  };
  auto line_of = [&](std::size_t e) {
    for(int k = 0; k < 3; ++k)
      if(on_line(e, 1, -0.5 + 0.1 * k)) return k;
    const auto h = halfedge(idx.edge_at(e), m);
    if(on_line(e, 0, 0.5) && m.point(source(h, m)).y() > 0 && m.point(target(h, m)).y() > 0) return 3;
    return -1;
  };
  std::array<std::size_t, 4> count = { 0, 0, 0, 0 };
  for(std::size_t e = 0; e < candidate.size(); ++e)
    if(line_of(e) >= 0) { candidate[e] = 1; ++count[std::size_t(line_of(e))]; }
  BOOST_TEST(count[0] == 40u);
  BOOST_TEST(count[3] == 19u);
  const std::vector<char> step = I::staircase_creases(idx, get(CGAL::vertex_point, m), candidate, g.normal, g.centroid);
  std::array<std::size_t, 4> steps = { 0, 0, 0, 0 };
  for(std::size_t e = 0; e < step.size(); ++e)
  {
    if(!candidate[e]) BOOST_TEST(!step[e]);
    else if(step[e]) ++steps[std::size_t(line_of(e))];
  }
  BOOST_TEST(steps[0] == 0u); // the outer lines: parallel candidates on one side only
  BOOST_TEST(steps[2] == 0u);
  BOOST_TEST(steps[3] == 0u); // the lone line
  // the middle line, but for its end edges at the grid's border (no face beyond)
  BOOST_TEST(steps[1] >= 38u);
}

BOOST_AUTO_TEST_CASE(filter_along_gradient_keeps_a_plane_and_smooths_a_coarse_cylinder)
{
  // a plane: every gradient is zero and every normal stays (0, 0, 1)
  {
    const SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 10));
    const I::Mesh_indexing<SM> idx(m);
    const Geometry g = geometry_of(idx);
    for(const Eigen::Vector3d& n :
        I::filter_face_normals_along_gradient(g.normal, g.area, g.centroid, g.begin, g.ring, 40, 0.3))
      BOOST_TEST((n - Eigen::Vector3d(0, 0, 1)).norm() < 1e-12);
  }
  // a cylinder of radius 1 and 20 facets round (18 degrees from facet to facet), noise
  // of up to 0.05 along the normals: the bilateral filter gathers the turn into steps
  // far above 18 degrees; along the gradient none reaches the crease angle (20)
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_cylinder(1., 2., 20, 12, 0.05));
  const I::Mesh_indexing<SM> idx(m);
  const Geometry g = geometry_of(idx);
  const std::vector<double> bilateral = I::dihedral_angles(
    idx, I::filter_face_normals(g.normal, g.roughness, g.area, g.centroid, g.begin, g.ring, 40, 0.3, 0.));
  const std::vector<double> along = I::dihedral_angles(
    idx, I::filter_face_normals_along_gradient(g.normal, g.area, g.centroid, g.begin, g.ring, 40, 0.3));
  const double most_bilateral = *std::max_element(bilateral.begin(), bilateral.end());
  const double most_along = *std::max_element(along.begin(), along.end());
  BOOST_TEST_MESSAGE("largest filtered angle: bilateral " << most_bilateral << ", along the gradient " << most_along);
  BOOST_TEST(most_bilateral > 30.);
  BOOST_TEST(most_along < 20.);
}

BOOST_AUTO_TEST_CASE(crease_lines_are_the_candidates_sharing_vertices)
{
  // a 10 x 10 grid over [-1, 1]^2 (cells of 0.2): the line y = 0 (10 edges) and the line
  // x = 0 from y = 0.2 up (4 edges, not touching y = 0) as one L with the edge of
  // x = 0 from y = 0 to 0.2 (15 edges); and 3 edges of the line y = -0.6 alone
  const SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 10));
  const I::Mesh_indexing<SM> idx(m);
  std::vector<char> candidate(idx.number_of_edges(), 0);
  std::vector<int> kind(idx.number_of_edges(), 0);
  for(std::size_t e = 0; e < candidate.size(); ++e)
  {
    const auto h = halfedge(idx.edge_at(e), m);
    const auto& p = m.point(source(h, m));
    const auto& q = m.point(target(h, m));
    const bool horizontal = std::abs(p.y() - q.y()) < 1e-9, vertical = std::abs(p.x() - q.x()) < 1e-9;
    if(horizontal && std::abs(p.y()) < 1e-9) kind[e] = 1;
    if(vertical && std::abs(p.x()) < 1e-9 && (std::min)(p.y(), q.y()) > -1e-9) kind[e] = 1;
    if(horizontal && std::abs(p.y() + 0.6) < 1e-9 && (std::max)(p.x(), q.x()) < -0.39) kind[e] = 2;
    candidate[e] = kind[e] != 0 ? 1 : 0;
  }
  const std::vector<std::size_t> size = I::crease_line_sizes(idx, candidate);
  std::array<std::size_t, 3> edges = { 0, 0, 0 };
  for(std::size_t e = 0; e < candidate.size(); ++e)
  {
    ++edges[std::size_t(kind[e])];
    BOOST_TEST(size[e] == (kind[e] == 1 ? 15u : kind[e] == 2 ? 3u : 0u));
  }
  BOOST_TEST(edges[1] == 15u);
  BOOST_TEST(edges[2] == 3u);
}

BOOST_AUTO_TEST_CASE(short_candidate_lines_are_kept_where_they_go_on_from_long_creases)
{
  // the grid above, lines of at least 5 edges. Kept: 3 candidates along y = 0.8 from
  // x = 0 to 0.6, going on from the end of the crease of 5 edges along y = 0.8 for
  // x <= 0; 4 candidates along y = -0.2 from x = -0.4 to 0.4, filling the gap between
  // its creases of 2 edges (x from -0.8 to -0.4) and 3 edges (x >= 0.4); 10 candidates
  // along y = -1 alone. Not kept: a stub of 2 candidates along x = 0 from y = 0.4 down
  // to 0, off the middle of the crease along y = 0.4 (10 edges); 3 candidates along
  // y = 0 from x = -1 to -0.4, turning off at the end of the crease along x = -1 that
  // comes down from that one (y from 0.4 to 0); 3 candidates along y = -0.8 from x = -0.6
  // to 0, going on from the end of a crease of only 2 edges (x <= -0.6).
  const SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 10));
  const I::Mesh_indexing<SM> idx(m);
  const std::size_t ne = idx.number_of_edges();
  std::vector<char> candidate(ne, 0), is_crease(ne, 0);
  std::vector<int> kind(ne, 0); // 1 kept, 2 not kept
  std::vector<double> value(ne, 50.), angle(ne, 10.);
  auto near = [](double a, double b) { return std::abs(a - b) < 1e-9; };
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), m);
    const auto& p = m.point(source(h, m));
    const auto& q = m.point(target(h, m));
    const bool horizontal = near(p.y(), q.y()), vertical = near(p.x(), q.x());
    const double x0 = (std::min)(p.x(), q.x()), x1 = (std::max)(p.x(), q.x());
    const double y0 = (std::min)(p.y(), q.y()), y1 = (std::max)(p.y(), q.y());
    if(horizontal && near(p.y(), 0.8) && x1 < 0.01) is_crease[e] = 1;
    if(horizontal && near(p.y(), 0.8) && x0 > -0.01 && x1 < 0.61) kind[e] = 1;
    if(horizontal && near(p.y(), -0.2) && ((x0 > -0.81 && x1 < -0.39) || x0 > 0.39)) is_crease[e] = 1;
    if(horizontal && near(p.y(), -0.2) && x0 > -0.41 && x1 < 0.41) kind[e] = 1;
    if(horizontal && near(p.y(), -1.)) kind[e] = 1;
    if(horizontal && near(p.y(), 0.4)) is_crease[e] = 1;
    if(vertical && near(p.x(), 0.) && y0 > -0.01 && y1 < 0.41) kind[e] = 2;
    if(vertical && near(p.x(), -1.) && y0 > -0.01 && y1 < 0.41) is_crease[e] = 1;
    if(horizontal && near(p.y(), 0.) && x1 < -0.39) kind[e] = 2;
    if(horizontal && near(p.y(), -0.8) && x1 < -0.59) is_crease[e] = 1;
    if(horizontal && near(p.y(), -0.8) && x0 > -0.61 && x1 < 0.01) kind[e] = 2;
    candidate[e] = kind[e] != 0 ? 1 : 0;
  }
  const std::vector<char> creases = is_crease;
  const std::size_t added = I::add_crease_lines_and_extensions(idx, get(CGAL::vertex_point, m), candidate, value, 5, is_crease, angle);
  std::array<std::size_t, 3> edges = { 0, 0, 0 };
  std::size_t crease_edges = 0;
  for(std::size_t e = 0; e < ne; ++e)
  {
    ++edges[std::size_t(kind[e])];
    crease_edges += creases[e] ? 1 : 0;
    BOOST_TEST(int(is_crease[e]) == ((creases[e] || kind[e] == 1) ? 1 : 0));
    BOOST_TEST(angle[e] == (kind[e] == 1 ? 50. : 10.));
  }
  BOOST_TEST(crease_edges == 5u + 5u + 10u + 2u + 2u);
  BOOST_TEST(edges[1] == 3u + 4u + 10u);
  BOOST_TEST(edges[2] == 2u + 3u + 3u);
  BOOST_TEST(added == 17u);
}

BOOST_AUTO_TEST_CASE(narrow_filter_keeps_a_moderate_crease_under_light_noise)
{
  // The cylinder and cone of fs_test::cylinder_and_cone(), whose crease of 26.6 degrees
  // runs along the circle z = 6 (48 edges); noise along the radial direction uniform in
  // +-0.025 (a standard deviation of 0.0144, 0.15% of the diagonal 9.8).
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_cylinder_and_cone(0.025));
  const I::Mesh_indexing<SM> idx(m);
  const Geometry g = geometry_of(idx);
  BOOST_TEST_MESSAGE("raw roughness " << g.roughness);
  // lightly noisy: above the smooth models' range, below the staircase rule's
  BOOST_TEST(g.roughness > I::Crease_gap::raw_roughness);
  BOOST_TEST(g.roughness < I::Crease_staircase::roughness);
  auto on_crease = [&](std::size_t e) {
    const auto h = halfedge(idx.edge_at(e), m);
    return std::abs(m.point(source(h, m)).z() - 6.) < 0.05 && std::abs(m.point(target(h, m)).z() - 6.) < 0.05;
  };
  const int rounds = I::noisy_filter_rounds(g.roughness, 40);
  const std::vector<double> wide = I::dihedral_angles(
    idx, I::filter_face_normals(g.normal, g.roughness, g.area, g.centroid, g.begin, g.ring, rounds,
                                I::crease_filter_sigma_r, 0.));
  std::vector<char> is_crease(idx.number_of_edges(), 0);
  std::size_t wide_on = 0, wide_off = 0;
  for(std::size_t e = 0; e < wide.size(); ++e)
    if(wide[e] >= 20.)
    {
      is_crease[e] = 1;
      ++(on_crease(e) ? wide_on : wide_off);
    }
  std::vector<double> angle = wide;
  const std::size_t added = I::add_narrow_filter_creases(idx, get(CGAL::vertex_point, m), g.normal, g.roughness,
                                                         I::Normal_filter_ring(g.area, g.centroid, g.begin, g.ring),
                                                         rounds, 20., is_crease, angle);
  // an edge off the circle but within one row of it (a diagonal of the quads next to
  // it) is a detour of the crease line
  auto next_to_crease = [&](std::size_t e) {
    const auto h = halfedge(idx.edge_at(e), m);
    return std::abs(m.point(source(h, m)).z() - 6.) < 0.3 && std::abs(m.point(target(h, m)).z() - 6.) < 0.3;
  };
  std::size_t on = 0, off = 0, far = 0;
  for(std::size_t e = 0; e < is_crease.size(); ++e)
    if(is_crease[e])
    {
      ++(on_crease(e) ? on : off);
      if(!next_to_crease(e)) ++far;
    }
  BOOST_TEST_MESSAGE("crease edges of the wide filter on the circle " << wide_on << ", elsewhere " << wide_off
                     << "; with the narrow filter's " << on << ", " << off << " (" << added << " added)");
  BOOST_TEST(on + off == wide_on + wide_off + added);
  // the bilateral filter spreads the crease over a band (none of the circle's 48 edges
  // reaches 20 degrees on this mesh); the narrow filter's creases hold at least seven
  // eighths of the circle as one line, with at most a few detours next to it and
  // nothing farther
  BOOST_TEST(wide_on <= 12u);
  BOOST_TEST(on >= 42u);
  BOOST_TEST(off <= 3u);
  BOOST_TEST(far == 0u);
  // and so do the creases of the whole detection
  const fs_test::Detected_creases detected = fs_test::detect_creases_at_defaults(idx);
  std::size_t detected_on = 0;
  for(std::size_t e = 0; e < detected.is_crease.size(); ++e)
    if(detected.is_crease[e] && on_crease(e)) ++detected_on;
  BOOST_TEST(!detected.clean);
  BOOST_TEST(detected_on >= 42u);
}

BOOST_AUTO_TEST_SUITE_END()
