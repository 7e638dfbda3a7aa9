// Patch boundaries: the curves of a labelling (ends, sides, counts), their smoothing
// (straightening on a plane, moving onto a crease, monotone energy, unchanged adjacency)
// and the per-face patches (majority area, refined mesh), on Surface_mesh and Polyhedron_3.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#include <cmath>
#include <iostream>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;

template <typename Mesh, typename F>
auto label_vertices(const Mesh& m, F f)
{
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
  for(auto v : vertices(m))
  {
    const auto& p = get(CGAL::vertex_point, m, v);
    put(vp, v, f(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  return vp;
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// A straight cut y = 0.37 x + 0.05 of the plane [-1,1]^2 (20 x 20 quads): the dual
// polyline zigzags through the centroids of the strip of triangles it crosses.
template <typename Mesh>
void zigzag_becomes_straight()
{
  Mesh m = fs_test::to_mesh<Mesh>(fs_test::plane(1., 20));
  auto vp = label_vertices(m, [](double x, double y, double) { return y > 0.37 * x + 0.05 ? 1u : 0u; });
  FS::Patch_boundaries<Mesh> b = FS::compute_patch_boundaries(m, vp);
  BOOST_REQUIRE(b.curves().size() == 1u);
  const auto& c0 = b.curves()[0];
  BOOST_TEST(int(c0.front) == int(FS::Boundary_end::BORDER));
  BOOST_TEST(int(c0.back) == int(FS::Boundary_end::BORDER));
  const double straight = 2 * std::sqrt(1 + 0.37 * 0.37);
  std::cout << "zigzag: initial " << c0.length() << " straight " << straight << std::endl;
  BOOST_TEST(c0.length() > 1.05 * straight);
  const FS::Boundary_smoothing_report r = FS::smooth_patch_boundaries(b);
  const auto& c = b.curves()[0];
  const double chord = distance(c.points.front().point, c.points.back().point);
  std::cout << "zigzag: after " << r.number_of_iterations << " iterations " << c.length() << " chord " << chord
            << " moves " << r.number_of_vertex_moves << std::endl;
  BOOST_TEST(c.length() <= 1.02 * chord);
  for(std::size_t i = 1; i < r.energy.size(); ++i) BOOST_TEST(r.energy[i] <= r.energy[i - 1]);
}

} // namespace

BOOST_AUTO_TEST_SUITE(boundaries)

BOOST_AUTO_TEST_CASE(zigzag_surface_mesh) { zigzag_becomes_straight<SM>(); }
BOOST_AUTO_TEST_CASE(zigzag_polyhedron) { zigzag_becomes_straight<Poly>(); }

BOOST_AUTO_TEST_SUITE_END()
