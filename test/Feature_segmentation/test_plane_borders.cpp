// The borders of planes on noisy meshes (plane_borders.h, part of the crease detection
// when tangent_discontinuities is on): a floor and a wall joined by a quarter-cylinder
// fillet, tangent to each other, with noise along the normals, so that no edge is a
// crease and the flat regions of a clean tessellation do not exist. The plane borders
// lie on the two tangent lines (within the two fillet rows that the 6-degree growth
// and the filter's blur may take into a plane) and give the three faces of the part; a
// noisy open cylinder has no plane, so no border; a noisy square is one plane without
// border; a Polyhedron_3 gets the borders of a Surface_mesh.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/internal/crease_detection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "crease_test_geometry.h"
#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

// the suite's namespace holds its helpers (one unity build unit: its names come first)
BOOST_AUTO_TEST_SUITE(plane_borders)

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;

const double pi = 3.14159265358979323846;
const double fillet_radius = 0.3;
const int floor_segments = 20, fillet_segments = 12, wall_segments = 20, rulings = 20;
const int profile_points = floor_segments + fillet_segments + wall_segments + 1;

// Profile point i in the (x, z) plane and its unit normal: the floor from x = -1 to 0 at
// z = 0, the fillet around (0, r) in steps of 7.5 degrees, the wall x = r up to z = r + 1.
void profile(int i, double& x, double& z, double& nx, double& nz)
{
  if(i <= floor_segments) { x = -1. + double(i) / floor_segments; z = 0.; nx = 0.; nz = 1.; return; }
  if(i <= floor_segments + fillet_segments)
  {
    const double t = 0.5 * pi * double(i - floor_segments) / fillet_segments;
    x = fillet_radius * std::sin(t);
    z = fillet_radius * (1. - std::cos(t));
    nx = -std::sin(t);
    nz = std::cos(t);
    return;
  }
  x = fillet_radius;
  z = fillet_radius + double(i - floor_segments - fillet_segments) / wall_segments;
  nx = -1.;
  nz = 0.;
}

// Arc length along the profile from point i to the nearer tangent line.
double to_tangent_line(double i)
{
  const double step = 0.5 * pi * fillet_radius / fillet_segments;
  const double a = i - floor_segments, b = i - floor_segments - fillet_segments;
  auto length = [&](double d, double outside) { return d < 0 ? -d * outside : d * step; };
  return (std::min)(length(a, 1. / floor_segments), length(-b, 1. / wall_segments));
}

fs_test::Soup noisy_filleted_corner(double amplitude)
{
  fs_test::Soup s = fs_test::parametric_grid(profile_points - 1, rulings, false, false, [](double u, double v) {
    double x, z, nx, nz;
    profile(int(std::lround(u * (profile_points - 1))), x, z, nx, nz);
    return std::array<double, 3>{ x, v, z };
  });
  std::vector<std::array<double, 3> > normal;
  for(std::size_t v = 0; v < s.points.size(); ++v)
  {
    double x, z, nx, nz;
    profile(int(v % profile_points), x, z, nx, nz);
    normal.push_back({ nx, 0., nz });
  }
  fs_test::add_noise_along(s, normal, amplitude);
  return s;
}

// The crease detection's marks (1 creases, 2 curvature discontinuities) by the edge ids
// of `idx`, and whether the mesh counts as noisy (raw roughness above the smooth models').
template <typename Mesh>
std::vector<char> crease_marks(const FS::internal::Mesh_indexing<Mesh>& idx, bool& noisy)
{
  namespace I = FS::internal;
  const auto vpm = get(CGAL::vertex_point, idx.mesh());
  std::vector<Eigen::Vector3d> normal, centroid;
  std::vector<double> area, angle;
  I::face_geometry(idx, vpm, normal, area, centroid);
  std::vector<std::uint32_t> begin, ring;
  I::vertex_adjacent_faces(idx, begin, ring);
  noisy = I::normal_roughness(normal, begin, ring) > I::Crease_gap::raw_roughness;
  bool clean = false, cad = false;
  return I::detect_creases(idx, vpm, 20., 40, true, angle, clean, cad);
}

std::vector<char> crease_marks(const SM& m, bool& noisy)
{
  return crease_marks(FS::internal::Mesh_indexing<SM>(m), noisy);
}

BOOST_AUTO_TEST_CASE(noisy_fillet_is_floor_fillet_and_wall)
{
  // noise of up to 0.008 (0.4% of the diagonal 1.92, 16% of an edge): raw normals
  // tilted by up to 18 degrees, far above the fillet's 7.5-degree steps
  const SM m = fs_test::to_mesh<SM>(noisy_filleted_corner(0.008));
  bool noisy = false;
  const std::vector<char> marks = crease_marks(m, noisy);
  BOOST_REQUIRE(noisy);
  std::size_t borders = 0;
  std::set<int> lines;
  for(auto e : edges(m))
  {
    const std::size_t e_id = e.idx();
    BOOST_TEST(marks[e_id] != 1); // no edge bends by 20 degrees
    if(marks[e_id] != 2) continue;
    ++borders;
    // the edge's place along the profile, from its vertices' profile indices
    const double i = 0.5 * double(source(halfedge(e, m), m).idx() % profile_points +
                                  target(halfedge(e, m), m).idx() % profile_points);
    BOOST_TEST(to_tangent_line(i) <= 2.01 * 0.5 * pi * fillet_radius / fillet_segments);
    lines.insert(i < floor_segments + 0.5 * fillet_segments ? 0 : 1);
  }
  BOOST_TEST(lines.size() == 2u);         // both tangent lines
  BOOST_TEST(borders >= 2u * rulings);   // along their whole length

  // the segmentation: three patches, each the faces of one part (the faces of the
  // rows next to the tangent lines aside)
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_patches() == 3u);
  std::map<int, std::set<std::size_t> > patches_of_part;
  for(auto f : faces(m))
  {
    double i = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) i += double(v.idx() % profile_points) / 3.;
    if(to_tangent_line(i) < 3 * 0.5 * pi * fillet_radius / fillet_segments) continue;
    const int part = i < floor_segments ? 0 : i < floor_segments + fillet_segments ? 1 : 2;
    patches_of_part[part].insert(seg.patch(f));
  }
  BOOST_TEST(patches_of_part.size() == 3u);
  std::set<std::size_t> all;
  for(const auto& p : patches_of_part)
  {
    BOOST_TEST(p.second.size() == 1u);
    all.insert(p.second.begin(), p.second.end());
  }
  BOOST_TEST(all.size() == 3u);

  // without the curvature discontinuities, nothing separates the three
  FS::Feature_aligned_segmentation<SM> without(m, FS::parameters::tangent_discontinuities(false));
  BOOST_TEST(without.number_of_patches() < 3u);
}

// The marked edges as (smaller vertex id, larger vertex id, mark), vertex ids in the
// soup's order.
template <typename Mesh>
std::set<std::array<std::size_t, 3> > marked_edges(const Mesh& m)
{
  const FS::internal::Mesh_indexing<Mesh> idx(m);
  bool noisy = false;
  const std::vector<char> marks = crease_marks(idx, noisy);
  std::set<std::array<std::size_t, 3> > out;
  for(std::size_t e = 0; e < marks.size(); ++e)
  {
    if(!marks[e]) continue;
    const auto h = halfedge(idx.edge_at(e), m);
    const std::size_t a = idx.id(source(h, m)), b = idx.id(target(h, m));
    out.insert({ (std::min)(a, b), (std::max)(a, b), std::size_t(marks[e]) });
  }
  return out;
}

BOOST_AUTO_TEST_CASE(polyhedron_gets_the_same_borders)
{
  typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;
  const fs_test::Soup s = noisy_filleted_corner(0.008);
  const auto on_surface_mesh = marked_edges(fs_test::to_mesh<SM>(s));
  BOOST_TEST(on_surface_mesh.size() >= 2u * rulings);
  BOOST_TEST((on_surface_mesh == marked_edges(fs_test::to_mesh<Poly>(s))));
}

BOOST_AUTO_TEST_CASE(noisy_cylinder_has_no_plane)
{
  // radius 1, 64 facets round (5.6 degrees a step), noise of up to 0.6% of the diagonal:
  // regions grown on its filtered normals are strips whose normals turn steadily
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_cylinder(1., 4., 64, 64, 0.027));
  bool noisy = false;
  const std::vector<char> marks = crease_marks(m, noisy);
  BOOST_REQUIRE(noisy);
  BOOST_TEST(std::count(marks.begin(), marks.end(), char(2)) == 0);
}

BOOST_AUTO_TEST_CASE(noisy_square_is_one_plane_without_border)
{
  fs_test::Soup s = fs_test::plane(1., 40);
  fs_test::add_noise_along(s, std::vector<std::array<double, 3> >(s.points.size(), std::array<double, 3>{ 0., 0., 1. }), 0.01);
  const SM m = fs_test::to_mesh<SM>(s);
  bool noisy = false;
  const std::vector<char> marks = crease_marks(m, noisy);
  BOOST_REQUIRE(noisy);
  BOOST_TEST(std::count(marks.begin(), marks.end(), char(2)) == 0);
  BOOST_TEST(std::count(marks.begin(), marks.end(), char(1)) == 0);
}

BOOST_AUTO_TEST_CASE(lightly_noisy_fillet_gets_borders_where_planes_dominate)
{
  // noise of up to 0.002 (0.1% of the diagonal, 4% of an edge): rougher than a clean
  // tessellation, smoother than the noisy meshes, as a smooth model
  namespace I = FS::internal;
  const SM m = fs_test::to_mesh<SM>(noisy_filleted_corner(0.002));
  const I::Mesh_indexing<SM> idx(m);
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  const std::vector<Eigen::Vector3d>& normal = g.normal;
  const double roughness = g.roughness;
  BOOST_TEST_MESSAGE("roughness " << roughness);
  BOOST_REQUIRE(roughness > I::crease_filter_roughness);
  BOOST_REQUIRE(roughness <= I::Crease_gap::raw_roughness);

  // the floor and the wall (2 of the area 2 + 0.3 pi / 2 = 2.47, give or take the fillet
  // rows the growth takes) hold more than crease_rough_plane_share: their borders are
  // marked on both tangent lines, as on a noisy mesh
  bool noisy = true;
  const std::vector<char> marks = crease_marks(idx, noisy);
  BOOST_TEST(!noisy);
  std::set<int> lines;
  for(auto e : edges(m))
  {
    if(marks[e.idx()] != 2) continue;
    const double i = 0.5 * double(source(halfedge(e, m), m).idx() % profile_points +
                                  target(halfedge(e, m), m).idx() % profile_points);
    BOOST_TEST(to_tangent_line(i) <= 2.01 * 0.5 * pi * fillet_radius / fillet_segments);
    lines.insert(i < floor_segments + 0.5 * fillet_segments ? 0 : 1);
  }
  BOOST_TEST(lines.size() == 2u);

  // the planes' share as mark_plane_borders() measures it on the filtered normals; asked
  // for more, it marks nothing
  const std::vector<Eigen::Vector3d> filtered =
    I::filter_face_normals(normal, roughness, g.area, g.centroid, g.begin, g.ring, I::crease_smooth_filter_iterations,
                           I::crease_filter_sigma_r, I::crease_filter_roughness);
  const double total = 2. + 0.5 * pi * fillet_radius, row = 0.5 * pi * fillet_radius / fillet_segments;
  std::vector<char> none(idx.number_of_edges(), 0), all(idx.number_of_edges(), 0);
  const double share = I::mark_plane_borders(idx, filtered, normal, g.area, g.centroid, 2., all, 0.);
  BOOST_TEST(share >= (2. - 4 * row) / total);
  BOOST_TEST(share <= (2. + 4 * row) / total);
  BOOST_TEST(std::count(all.begin(), all.end(), char(2)) >= 2 * rulings);
  BOOST_TEST(I::mark_plane_borders(idx, filtered, normal, g.area, g.centroid, 2., none, share + 0.01) == share);
  BOOST_TEST(std::count(none.begin(), none.end(), char(0)) == std::ptrdiff_t(none.size()));
}

// A bar with rounded edges (the generated part filleted_bar's section): a square of side
// 1.5 whose corners are quarter circles of radius 0.4, so four flat sides 0.7 wide
// (9 facets) and four fillets (8 facets), extruded over 9 (116 rows), open at its ends.
namespace rounded_bar {
const int flat_segments = 9, corner_segments = 8, side = flat_segments + corner_segments, around = 4 * side;
const int rows = 116;
const double half_flat = 0.35, radius = 0.4, length = 9.;

// Profile point i (0 <= i < around) and its unit normal in the (x, y) plane.
void profile(int i, double& x, double& y, double& nx, double& ny)
{
  const int k = i / side, j = i % side;
  const double theta = 0.5 * pi * k;
  const double n[2] = { std::cos(theta), std::sin(theta) }, t[2] = { -n[1], n[0] };
  if(j < flat_segments)
  {
    const double s = -half_flat + 2 * half_flat * double(j) / flat_segments;
    x = (half_flat + radius) * n[0] + s * t[0];
    y = (half_flat + radius) * n[1] + s * t[1];
    nx = n[0];
    ny = n[1];
    return;
  }
  const double phi = theta + 0.5 * pi * double(j - flat_segments) / corner_segments;
  nx = std::cos(phi);
  ny = std::sin(phi);
  x = half_flat * (n[0] + t[0]) + radius * nx;
  y = half_flat * (n[1] + t[1]) + radius * ny;
}

fs_test::Soup noisy(double amplitude)
{
  fs_test::Soup s = fs_test::parametric_grid(around, rows, true, false, [](double u, double v) {
    double x, y, nx, ny;
    profile(int(std::lround(u * around)) % around, x, y, nx, ny);
    return std::array<double, 3>{ x, y, length * v };
  });
  std::vector<std::array<double, 3> > normal;
  for(std::size_t v = 0; v < s.points.size(); ++v)
  {
    double x, y, nx, ny;
    profile(int(v % around), x, y, nx, ny);
    normal.push_back({ nx, ny, 0. });
  }
  fs_test::add_noise_along(s, normal, amplitude);
  return s;
}

// The profile position (in facets, 0 <= i < around) of the midpoint of the vertices
// with profile indices a and b.
double middle(std::size_t a, std::size_t b)
{
  double i = double(a % around), j = double(b % around);
  if(std::abs(i - j) > 0.5 * around) (i < j ? i : j) += around;
  return std::fmod(0.5 * (i + j), double(around));
}

// The tangent line nearest to profile position i (0 to 7: line 2k + 1 ends flat side k)
// and the distance to it in facets.
int nearest_line(double i, double& distance)
{
  int best = 0;
  distance = 1e9;
  for(int line = 0; line < 8; ++line)
  {
    const double at = (line / 2) * side + (line % 2) * flat_segments;
    double d = std::abs(i - at);
    d = (std::min)(d, around - d);
    if(d < distance) { distance = d; best = line; }
  }
  return best;
}
} // namespace rounded_bar

BOOST_AUTO_TEST_CASE(narrow_flats_of_a_noisy_rounded_bar)
{
  // noise of up to 0.025 along the normals (a third of an edge, 0.27% of the diagonal
  // 9.2): the filter bends the normals of the flats, 9 facets wide, towards their
  // fillets over their whole width, so that their filtered normals turn almost as
  // steadily as a cylinder's (trends of 2.6 to 2.8 degrees, two of them above
  // Plane_thresholds::trend's 2.7); their raw normals do not turn (raw trends of 0.25 to
  // 0.45 degrees, under Plane_thresholds::raw_trend). Without the raw test, those two
  // flats are taken for strips of cylinders: 4 patches.
  namespace B = rounded_bar;
  const SM m = fs_test::to_mesh<SM>(B::noisy(0.025));
  bool noisy = false;
  const std::vector<char> marks = crease_marks(m, noisy);
  BOOST_REQUIRE(noisy);
  // the plane borders lie one facet inside the flats, along all eight tangent lines; the
  // creases that the noise leaves are all on the fillets, none crosses a flat
  std::map<int, std::size_t> on_line;
  for(auto e : edges(m))
  {
    if(marks[e.idx()] == 0) continue;
    const double at = B::middle(source(halfedge(e, m), m).idx(), target(halfedge(e, m), m).idx());
    const double along_side = std::fmod(at, double(B::side));
    const bool in_flat = along_side > 0 && along_side < B::flat_segments;
    if(marks[e.idx()] == 1)
    {
      BOOST_TEST(!in_flat);
      continue;
    }
    double distance = 0;
    const int line = B::nearest_line(at, distance);
    BOOST_TEST(distance <= 1.01);
    BOOST_TEST((in_flat || distance == 0.));
    ++on_line[line];
  }
  BOOST_TEST(on_line.size() == 8u);
  // along nine tenths of each line's length or more (109 to 117 edges for 116 rows)
  for(const auto& l : on_line) BOOST_TEST(l.second >= std::size_t(0.9 * B::rows));

  // the segmentation: eight patches, the four flats and the four fillets (the faces
  // within three facets of a tangent line aside)
  FS::Feature_aligned_segmentation<SM> seg(m);
  std::map<int, std::set<std::size_t> > patches_of_part;
  std::set<std::size_t> all;
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    const std::size_t a = source(h, m).idx(), b = target(h, m).idx(), c = target(next(h, m), m).idx();
    // the face's place along the profile: the middle of its two profile indices
    const double mid = B::middle(a, a % B::around != b % B::around ? b : c);
    double distance = 0;
    B::nearest_line(mid, distance);
    if(distance < 3.) continue;
    const int part = 2 * (int(mid) / B::side) + (int(mid) % B::side < B::flat_segments ? 0 : 1);
    patches_of_part[part].insert(seg.patch(f));
    all.insert(seg.patch(f));
  }
  BOOST_TEST(patches_of_part.size() == 8u);
  for(const auto& p : patches_of_part) BOOST_TEST(p.second.size() == 1u);
  BOOST_TEST(all.size() == 8u);
}

BOOST_AUTO_TEST_SUITE_END()
