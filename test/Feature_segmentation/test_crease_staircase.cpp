// The creases of heavily noisy meshes (crease_staircase.h): the staircase test on
// candidate lines of a flat grid (a line with parallel candidates on both sides within
// four edge lengths is a step, the outer lines and a lone line are not), and the normal
// filter along the gradient on a plane (exact) and on a noisy coarse cylinder (no steps
// where the bilateral filter makes them).
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/crease_detection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

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

struct Geometry
{
  std::vector<Eigen::Vector3d> normal, centroid;
  std::vector<double> area;
  std::vector<std::uint32_t> begin, ring;
  double roughness = 0;
};

Geometry geometry_of(const I::Mesh_indexing<SM>& idx)
{
  Geometry g;
  I::face_geometry(idx, get(CGAL::vertex_point, idx.mesh()), g.normal, g.area, g.centroid);
  I::vertex_adjacent_faces(idx, g.begin, g.ring);
  g.roughness = I::normal_roughness(g.normal, g.begin, g.ring);
  return g;
}

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

BOOST_AUTO_TEST_SUITE_END()
