// The meshes and checks of the crease tests (test_creases.cpp, test_crease_rules.cpp):
// solids whose faces are known, and whether a segmentation's patches are those faces.
#ifndef FS_TEST_CREASE_MESHES_H
#define FS_TEST_CREASE_MESHES_H

#include <boost/test/unit_test.hpp>
#include <boost/property_map/property_map.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>
#include <CGAL/Feature_segmentation/internal/crease_cut.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include "test_meshes.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

// The meshes of the tests (in the unnamed namespace, as every suite declares them).
namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;

} // namespace

namespace fs_test {


// Whether the face patches are exactly the sides of a box (or any solid with
// `number_of_sides` faces): as many patches as sides, and two faces share a patch if and
// only if they share a side.
template <typename Mesh, typename PatchOf>
bool patches_are_sides(const Mesh& m, PatchOf patch_of, const std::vector<int>& side, std::size_t number_of_sides)
{
  std::set<std::pair<std::size_t, int> > pairs;
  std::set<std::size_t> patches;
  std::size_t i = 0;
  for(auto f : faces(m))
  {
    pairs.insert({ patch_of(f), side[i++] });
    patches.insert(patch_of(f));
  }
  return pairs.size() == number_of_sides && patches.size() == number_of_sides;
}

template <typename Mesh>
bool patches_are_sides(const Mesh& m, const FS::Feature_aligned_segmentation<Mesh>& seg,
                       const std::vector<int>& side, std::size_t number_of_sides = 6)
{
  return patches_are_sides(m, [&](auto f) { return seg.patch(f); }, side, number_of_sides);
}

template <typename Mesh>
void box_is_its_six_sides(double a, double b, double c, int n)
{
  std::vector<int> side;
  const Mesh m = fs_test::to_mesh<Mesh>(fs_test::box(a, b, c, n, side));
  FS::Feature_aligned_segmentation<Mesh> seg(m, FS::parameters::crease_angle(20.));
  // the 12 box edges, n mesh edges each; the flat diagonals bend by 0 degrees
  BOOST_TEST(seg.number_of_crease_edges() == std::size_t(12 * n));
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(patches_are_sides(m, seg, side));
  // the working mesh: the box cut open along its 12 edges, the 8 corners in 3 copies
  // and the other box-edge vertices in 2
  const std::size_t nv = num_vertices(m);
  BOOST_TEST(num_vertices(seg.working_mesh()) == nv + 8 * 2 + 12 * (n - 1));
  BOOST_TEST(num_faces(seg.working_mesh()) == num_faces(m));
  std::size_t creases = 0;
  for(auto e : edges(m))
    if(seg.is_crease_edge(e))
    {
      ++creases;
      // cutting along a 90 degree crease is rewarded at the default alpha
      BOOST_TEST(seg.weight(e) < 0.);
      BOOST_TEST(seg.alpha(e) == 0.6);
    }
  BOOST_TEST(creases == std::size_t(12 * n));
}

// The plate [0,1]x[0,0.6]x[0,0.2] pierced by a slot [0.45,0.46]x[0.1,0.5], each grid cell
// refined `refine` times in x and y (and the walls in as many layers): the slot is 0.01
// wide, narrower than the curvature fit's radius (1% of the diagonal, 0.0118), and its
// walls face each other across it.
template <typename Mesh>
void slotted_plate_is_its_ten_faces(int refine)
{
  auto breakpoints = [&](std::vector<double> v) {
    std::vector<double> r;
    for(std::size_t i = 0; i + 1 < v.size(); ++i)
      for(int k = 0; k < refine; ++k) r.push_back(v[i] + (v[i + 1] - v[i]) * k / refine);
    r.push_back(v.back());
    return r;
  };
  const std::vector<double> xs = breakpoints({0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.46, 0.5, 0.6, 0.7, 0.8, 0.9, 1.});
  const std::vector<double> ys = breakpoints({0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
  std::vector<int> side;
  const Mesh m = fs_test::to_mesh<Mesh>(
    fs_test::slotted_plate(xs, ys, 5 * refine, 6 * refine, 1 * refine, 5 * refine, 0.2, 2 * refine, side));
  BOOST_REQUIRE(CGAL::is_closed(m));
  FS::Feature_aligned_segmentation<Mesh> seg(m); // the defaults
  BOOST_TEST(seg.number_of_patches() == 10u);
  BOOST_TEST(patches_are_sides(m, seg, side, 10));
  // the face rule of the final boundaries: every boundary is a crease, a border of the
  // working mesh, so the smoothing has nothing to move and every face keeps its side
  FS::Patch_boundaries<Mesh> b = seg.patch_boundaries();
  BOOST_TEST(b.curves().empty());
  FS::smooth_patch_boundaries(b);
  std::map<typename boost::graph_traits<Mesh>::face_descriptor, std::size_t> patch;
  seg.face_patches(b, boost::make_assoc_property_map(patch));
  BOOST_TEST(patches_are_sides(m, [&](auto f) { return patch.at(f); }, side, 10));
}

// A convex solid from its planar polygons, each with its outward normal, fanned into
// triangles; side[f]: the polygon of triangle f.
inline Soup convex_polyhedron(const std::vector<std::pair<std::vector<std::array<double, 3> >, std::array<double, 3> > >& polygons,
                              std::vector<int>& side)
{
  typedef std::array<double, 3> P;
  fs_test::Soup s;
  std::map<P, std::size_t> id;
  auto point = [&](const P& p) {
    auto it = id.find(p);
    if(it != id.end()) return it->second;
    s.points.push_back(p);
    return id[p] = s.points.size() - 1;
  };
  side.clear();
  for(std::size_t k = 0; k < polygons.size(); ++k)
  {
    std::vector<P> q = polygons[k].first;
    const P& a = q[0]; const P& b = q[1]; const P& c = q[2];
    const P u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const P n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const P& out = polygons[k].second;
    if(n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0) std::reverse(q.begin(), q.end());
    for(std::size_t i = 1; i + 1 < q.size(); ++i) // convex: a fan
    {
      s.faces.push_back({point(q[0]), point(q[i]), point(q[i + 1])});
      side.push_back(int(k));
    }
  }
  return s;
}

// The unit cube with its corner (1,1,1) cut off by the plane 2x + y + z = 3.8: one
// triangle, A = (0.9,1,1), B = (1,0.8,1), C = (1,1,0.8), the pentagons fanned into
// triangles. `side[f]`: 0..5 for x=0, x=1, y=0, y=1, z=0, z=1, and 6 for the triangle.
// The triangle's normal (2,1,1)/sqrt(6) bends by 35.3 degrees from the side x=1 and by
// 65.9 from y=1 and z=1: three creases around one face.
inline Soup cube_with_a_cut_corner(std::vector<int>& side)
{
  return convex_polyhedron({ // the polygon, its outward normal
    {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {-1, 0, 0}},
    {{{1, 0, 0}, {1, 1, 0}, {1, 1, 0.8}, {1, 0.8, 1}, {1, 0, 1}}, {1, 0, 0}},
    {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {0, -1, 0}},
    {{{0, 1, 0}, {1, 1, 0}, {1, 1, 0.8}, {0.9, 1, 1}, {0, 1, 1}}, {0, 1, 0}},
    {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, -1}},
    {{{0, 0, 1}, {1, 0, 1}, {1, 0.8, 1}, {0.9, 1, 1}, {0, 1, 1}}, {0, 0, 1}},
    {{{0.9, 1, 1}, {1, 0.8, 1}, {1, 1, 0.8}}, {2, 1, 1}}}, side);
}

// The unit cube with its edge x = y = 1 cut off by the plane x + 2y = 2.85: a chamfer
// quad of two triangles, from (1, 0.925, z) to (0.85, 1, z). `side[f]`: 0..5 for x=0,
// x=1, y=0, y=1, z=0, z=1, and 6 for the chamfer. The chamfer's normal (1,2,0)/sqrt(5)
// bends by 26.6 degrees from the side y=1, 63.4 from x=1 and 90 from z=0 and z=1.
inline Soup cube_with_a_chamfered_edge(std::vector<int>& side)
{
  return convex_polyhedron({
    {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {-1, 0, 0}},
    {{{1, 0, 0}, {1, 0.925, 0}, {1, 0.925, 1}, {1, 0, 1}}, {1, 0, 0}},
    {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {0, -1, 0}},
    {{{0, 1, 0}, {0.85, 1, 0}, {0.85, 1, 1}, {0, 1, 1}}, {0, 1, 0}},
    {{{0, 0, 0}, {1, 0, 0}, {1, 0.925, 0}, {0.85, 1, 0}, {0, 1, 0}}, {0, 0, -1}},
    {{{0, 0, 1}, {1, 0, 1}, {1, 0.925, 1}, {0.85, 1, 1}, {0, 1, 1}}, {0, 0, 1}},
    {{{1, 0.925, 0}, {0.85, 1, 0}, {0.85, 1, 1}, {1, 0.925, 1}}, {1, 2, 0}}}, side);
}

// The box of box() with noise along the normals: every vertex inside a side (not on a
// box edge) moves along its side's normal by a deterministic pseudo-random amount,
// uniform in [-amplitude, amplitude].
inline Soup noisy_box(double amplitude, int n, std::vector<int>& side)
{
  fs_test::Soup s = fs_test::box(1., 1., 1., n, side);
  unsigned long long state = 12345;
  for(auto& p : s.points)
  {
    int on_faces = 0, axis = 0;
    for(int k = 0; k < 3; ++k)
      if(p[k] == 0. || p[k] == 1.) { ++on_faces; axis = k; }
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = double(state >> 11) / double(1ULL << 53); // [0, 1)
    if(on_faces == 1) p[axis] += (p[axis] == 0. ? -1. : 1.) * amplitude * (2 * u - 1);
  }
  return s;
}

// A closed rod along z, of the given length, whose cross-section at height z has radius
// radius(a, z) at the angle a: `around` x `along` quadrilaterals on its side (planar
// when the radius is a product of a function of a and one of z: each of two coplanar
// triangles, a clean tessellation), a fan on each end; side: 0 on the side, 1 and 2 on
// the ends.
template <typename Radius>
Soup closed_rod(Radius radius, double length, int around, int along, std::vector<int>& side)
{
  fs_test::Soup s;
  for(int j = 0; j <= along; ++j)
    for(int i = 0; i < around; ++i)
    {
      const double a = 2 * M_PI * i / around, z = length * j / along, r = radius(a, z);
      s.points.push_back({r * std::cos(a), r * std::sin(a), z});
    }
  const std::size_t bottom = s.points.size(), top = bottom + 1;
  s.points.push_back({0., 0., 0.});
  s.points.push_back({0., 0., length});
  const auto at = [&](int i, int j) { return std::size_t(j * around + (i % around)); };
  side.clear();
  for(int j = 0; j < along; ++j)
    for(int i = 0; i < around; ++i)
    {
      s.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      side.insert(side.end(), {0, 0});
    }
  for(int i = 0; i < around; ++i)
  {
    s.faces.push_back({bottom, at(i + 1, 0), at(i, 0)});
    s.faces.push_back({top, at(i, along), at(i + 1, along)});
    side.insert(side.end(), {1, 2});
  }
  return s;
}

} // namespace fs_test

#endif // FS_TEST_CREASE_MESHES_H
