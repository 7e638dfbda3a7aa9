// The corners of rolling-ball blends (blend_corners.h): the shape operator fitted to exact
// normals of a sphere and a cylinder has their principal curvatures; a cube with every
// edge rounded by a rolling ball (six planes, twelve quarter cylinders, eight sphere
// octants), exact and with noise along its normals, whose plane borders are given, gets
// its eight corners parted from its fillets: 26 regions, each corner's region the true
// octant to within a row of faces; a sphere, a torus and a cylinder, each one region,
// get no corner.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/blend_corners.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "crease_test_geometry.h"
#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

BOOST_AUTO_TEST_SUITE(blend_corners)

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
namespace I = FS::internal;

BOOST_AUTO_TEST_CASE(fitted_curvatures_of_a_sphere_and_a_cylinder)
{
  // exact normals at points around (1, 0, 0) on the sphere of radius 2 about (-1, 0, 0),
  // and on the cylinder of radius 2 about the z axis through (-1, 0, 0): dn = dp / 2 in
  // the tangent plane on the sphere, and only across the axis on the cylinder
  const Eigen::Vector3d centre(-1, 0, 0);
  std::vector<Eigen::Vector3d> cs, ns, cc, nc;
  for(int i = -2; i <= 2; ++i)
    for(int j = -2; j <= 2; ++j)
    {
      const double a = 0.1 * i, b = 0.13 * j;
      const Eigen::Vector3d n(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
      cs.push_back(centre + 2. * n);
      ns.push_back(n);
      const Eigen::Vector3d radial(std::cos(a), std::sin(a), 0.);
      cc.push_back(centre + 2. * radial + Eigen::Vector3d(0, 0, 0.3 * j));
      nc.push_back(radial);
    }
  std::vector<std::size_t> js;
  for(std::size_t k = 0; k < cs.size(); ++k)
    if(k != 12) js.push_back(k); // 12: the middle point (1, 0, 0)
  double k1 = 0, k2 = 0;
  BOOST_TEST(I::fitted_curvatures(12, js, cs, ns, k1, k2));
  BOOST_TEST(k1 == 0.5, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(k2 == 0.5, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(I::fitted_curvatures(12, js, cc, nc, k1, k2));
  BOOST_TEST(k1 == 0.5, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(std::abs(k2) < 1e-9);
  // fewer than three neighbours, or all on one line through the face: no fit
  BOOST_TEST(!I::fitted_curvatures(12, std::vector<std::size_t>{ 11, 13 }, cs, ns, k1, k2));
  BOOST_TEST(!I::fitted_curvatures(12, std::vector<std::size_t>{ 2, 7, 17, 22 }, cc, nc, k1, k2));
}

// The cube [0, 6]^3 (30 x 30 quads a side, steps of 0.2) with every edge rounded by a
// ball of radius 1.2 (six steps): each vertex p goes to q + 1.2 (p - q) / |p - q|, q
// the nearest point of the inner cube [1.2, 4.8]^3, so that the grid lines at 1.2 and
// 4.8 are the seams. `kind` receives each face's true surface by the number of its
// coordinates outside the inner cube (1: a plane, 2: a fillet, 3: a corner) and
// `surface` a label of that surface; with `amplitude`, noise uniform in +-amplitude
// along the normals.
const double radius = 1.2, side = 6.;

fs_test::Soup rounded_cube(double amplitude, std::vector<int>& kind, std::vector<int>& surface)
{
  std::vector<int> box_side;
  fs_test::Soup s = fs_test::box(side, side, side, 30, box_side);
  auto inner = [](double x) { return (std::min)((std::max)(x, radius), side - radius); };
  kind.clear();
  surface.clear();
  for(const auto& f : s.faces)
  {
    int k = 0, code = 0;
    for(int d = 0; d < 3; ++d)
    {
      const double c = (s.points[f[0]][d] + s.points[f[1]][d] + s.points[f[2]][d]) / 3.;
      const int where = c < radius ? 0 : (c > side - radius ? 2 : 1);
      k += where != 1;
      code = 3 * code + where;
    }
    kind.push_back(k);
    surface.push_back(code);
  }
  std::vector<std::array<double, 3> > normal;
  for(auto& p : s.points)
  {
    const std::array<double, 3> q{ inner(p[0]), inner(p[1]), inner(p[2]) };
    const double len = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    std::array<double, 3> n{};
    for(int d = 0; d < 3; ++d)
    {
      n[d] = (p[d] - q[d]) / len;
      p[d] = q[d] + radius * n[d];
    }
    normal.push_back(n);
  }
  if(amplitude > 0) fs_test::add_noise_along(s, normal, amplitude);
  return s;
}

// The blend corners of the rounded cube given its plane borders (the edges between a
// plane's faces and the others marked 2, as plane_borders.h marks them): the regions
// after marking, and per true corner the share of its faces in the region of its
// middle face and the share of that region's faces that are the corner's, at least
// `least_of_corner` and `least_of_region`.
void check_corners(double amplitude, double least_of_corner, double least_of_region)
{
  std::vector<int> kind, surface;
  const SM m = fs_test::to_mesh<SM>(rounded_cube(amplitude, kind, surface));
  const I::Mesh_indexing<SM> idx(m);
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  std::vector<char> is_crease(idx.number_of_edges(), 0);
  for(std::size_t e = 0; e < is_crease.size(); ++e)
  {
    const auto h = halfedge(idx.edge_at(e), m);
    const std::size_t f = idx.face_id(h), k = idx.face_id(opposite(h, m));
    if((kind[f] == 1) != (kind[k] == 1)) is_crease[e] = 2;
  }
  const std::size_t marked = I::mark_blend_corners(idx, g.normal, g.area, g.centroid, g.begin, g.ring, is_crease);
  BOOST_TEST_MESSAGE("noise " << amplitude << ": " << marked << " edges marked");
  BOOST_TEST(marked > 0u);
  const std::vector<std::size_t> root = I::face_components(idx, [&](std::size_t e) { return !is_crease[e]; });
  const std::set<std::size_t> regions(root.begin(), root.end());
  BOOST_TEST(regions.size() == 26u); // 6 planes, 12 fillets, 8 corners
  // each corner against the region of its face nearest the corner's middle direction
  std::map<int, std::vector<std::size_t> > corner_faces;
  for(std::size_t f = 0; f < kind.size(); ++f)
    if(kind[f] == 3) corner_faces[surface[f]].push_back(f);
  BOOST_TEST(corner_faces.size() == 8u);
  for(const auto& c : corner_faces)
  {
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    for(std::size_t f : c.second) direction += g.centroid[f] - Eigen::Vector3d::Constant(side / 2);
    direction.normalize();
    std::size_t middle = c.second.front();
    for(std::size_t f : c.second)
      if((g.centroid[f] - Eigen::Vector3d::Constant(side / 2)).normalized().dot(direction) >
         (g.centroid[middle] - Eigen::Vector3d::Constant(side / 2)).normalized().dot(direction))
        middle = f;
    std::size_t in_region = 0, region_size = 0;
    for(std::size_t f = 0; f < root.size(); ++f)
      if(root[f] == root[middle])
      {
        ++region_size;
        in_region += kind[f] == 3 && surface[f] == c.first;
      }
    BOOST_TEST_MESSAGE("corner " << c.first << ": " << in_region << " of its " << c.second.size()
                                 << " faces in a region of " << region_size);
    BOOST_TEST(double(in_region) >= least_of_corner * double(c.second.size()));
    BOOST_TEST(double(in_region) >= least_of_region * double(region_size));
  }
}

BOOST_AUTO_TEST_CASE(rounded_cube_corners_part_from_fillets)
{
  // exact: each octant of 216 faces (6 x 6 cells of two triangles on three sides) is
  // its region (the curvatures' fits, whose support is 0.6 while a row is 0.31 round a
  // fillet, take up to 10 fillet faces more; the planes where the sphere meets the
  // cylinders part them); with noise +-0.02 along the normals (a standard deviation of
  // 0.012, 0.11% of the diagonal 10.4) too (the fits alone leave up to 6 of its faces
  // out and take up to 16 fillet faces in; without the holes joining their corner, 37
  // regions)
  check_corners(0., 1., 1.);
  check_corners(0.02, 1., 1.);
}

// The number of edges that mark_blend_corners() marks on a mesh with no crease.
std::size_t corners_marked(const fs_test::Soup& s)
{
  const SM m = fs_test::to_mesh<SM>(s);
  const I::Mesh_indexing<SM> idx(m);
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  std::vector<char> is_crease(idx.number_of_edges(), 0);
  return I::mark_blend_corners(idx, g.normal, g.area, g.centroid, g.begin, g.ring, is_crease);
}

BOOST_AUTO_TEST_CASE(sphere_torus_and_cylinder_have_no_corner)
{
  // a sphere has no cylinder; a torus none of sphere-like curvature (k2 / k1 at most
  // r / (R + r) = 0.25 outside, of the opposite sign inside); a cylinder is all cylinder
  BOOST_TEST(corners_marked(fs_test::icosphere(2., 4)) == 0u);
  BOOST_TEST(corners_marked(fs_test::parametric_grid(64, 24, true, true, [](double u, double v) {
               const double a = 2 * M_PI * u, b = 2 * M_PI * v;
               return std::array<double, 3>{ (3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b) };
             })) == 0u);
  BOOST_TEST(corners_marked(fs_test::cylinder(1., 4., 48, 30)) == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
