// Patch boundaries: the curves of a labelling (ends, sides, counts), their smoothing
// (straightening on a plane, moving onto a crease, monotone energy, unchanged adjacency)
// and the per-face patches (majority area, refined mesh), on Surface_mesh and Polyhedron_3.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>
#include <CGAL/Feature_segmentation/face_patches.h>
#include <CGAL/Feature_segmentation/IO/write_refined_segmentation.h>
#include <CGAL/Feature_segmentation/internal/boundary_state.h>
#include <CGAL/Feature_segmentation/internal/ordered_text.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <random>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
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
  BOOST_TEST_MESSAGE("zigzag: initial " << c0.length() << " straight " << straight);
  BOOST_TEST(c0.length() > 1.05 * straight);
  const FS::Boundary_smoothing_report r = FS::smooth_patch_boundaries(b);
  const auto& c = b.curves()[0];
  const double chord = distance(c.points.front().point, c.points.back().point);
  BOOST_TEST_MESSAGE("zigzag: after " << r.number_of_iterations << " iterations " << c.length() << " chord " << chord
            << " moves " << r.number_of_vertex_moves);
  BOOST_TEST(c.length() <= 1.02 * chord);
  for(std::size_t i = 1; i < r.energy.size(); ++i) BOOST_TEST(r.energy[i] <= r.energy[i - 1]);
}


// Three sectors of the plane around (0.03, 0.02) (no vertex on a sector's side).
std::size_t sector(double x, double y)
{
  double a = std::atan2(y - 0.02, x - 0.03);
  if(a < 0) a += 2 * M_PI;
  return std::size_t(a / (2 * M_PI / 3)) % 3;
}

// The roof z = 0.4 (1 - |x|) over [-1,1]^2, 20 x 20 quads: a crease along x = 0, on
// mesh edges (column 10 of the grid).
fs_test::Soup roof()
{
  return fs_test::parametric_grid(20, 20, false, false, [](double u, double v) {
    const double x = 2 * u - 1, y = 2 * v - 1;
    return std::array<double, 3>{x, y, 0.4 * (1 - std::abs(x))};
  });
}

template <typename Mesh>
std::multiset<std::pair<int, int> > end_types(const FS::Patch_boundaries<Mesh>& b)
{
  std::multiset<std::pair<int, int> > s;
  for(const auto& c : b.curves()) s.insert({ int(c.front), int(c.back) });
  return s;
}

// Checks what the smoothing must keep: monotone energy, the same curves (count, ends),
// patch pairs, junctions and number of patches.
template <typename Mesh>
FS::Boundary_smoothing_report smooth_and_check(FS::Patch_boundaries<Mesh>& b, std::size_t iterations)
{
  const auto pairs = b.adjacent_patches();
  const auto ends = end_types(b);
  const std::size_t junctions = b.number_of_junctions(), patches = b.number_of_patches(), curves = b.curves().size();
  const FS::Boundary_smoothing_report r =
    FS::smooth_patch_boundaries(b, FS::parameters::smoothing_iterations(iterations).smoothing_tolerance(0.));
  BOOST_TEST(r.energy.size() == r.number_of_iterations + 1);
  for(std::size_t i = 1; i < r.energy.size(); ++i) BOOST_TEST(r.energy[i] <= r.energy[i - 1]);
  BOOST_TEST(std::abs(r.energy.back() - b.anisotropic_length()) <= 1e-12 * r.energy.back());
  BOOST_TEST(std::abs(r.length.back() - b.length()) <= 1e-12 * r.length.back());
  BOOST_TEST((b.adjacent_patches() == pairs));
  BOOST_TEST((end_types(b) == ends));
  BOOST_TEST(b.number_of_junctions() == junctions);
  BOOST_TEST(b.number_of_patches() == patches);
  BOOST_TEST(b.curves().size() == curves);
  return r;
}

// The refined mesh: its patches are the connected components of its faces with the
// boundary edges as constraints (one component per patch, when patches are connected),
// and no new vertex is closer to another vertex than snapping_ratio times the smallest
// altitude of the input's triangles.
template <typename Mesh>
void check_refinement(const FS::Patch_boundaries<Mesh>& b, std::size_t expected_patches, double delta)
{
  SM out;
  auto fp = out.add_property_map<SM::Face_index, std::size_t>("f:patch", 0).first;
  auto constrained = out.add_property_map<SM::Edge_index, bool>("e:constrained", false).first;
  const std::size_t split = FS::refine_mesh_along_boundaries(
    b, out, fp, FS::parameters::snapping_ratio(delta).edge_is_constrained_map(constrained));
  BOOST_TEST(CGAL::is_valid_polygon_mesh(out));
  // written without the mesh: the same file, byte for byte, and the same sizes
  std::ostringstream from_mesh, direct;
  FS::write_PLY_segmentation(from_mesh, out, fp);
  const FS::Refined_segmentation_sizes sizes =
    FS::write_PLY_refined_segmentation(direct, b, FS::parameters::snapping_ratio(delta));
  BOOST_TEST(direct.str() == from_mesh.str());
  BOOST_TEST(sizes.number_of_vertices == num_vertices(out));
  BOOST_TEST(sizes.number_of_faces == num_faces(out));
  BOOST_TEST(sizes.number_of_split_faces == split);
  BOOST_TEST(CGAL::is_triangle_mesh(out));
  auto cc = out.add_property_map<SM::Face_index, std::size_t>("f:cc", 0).first;
  const std::size_t ncc = CGAL::Polygon_mesh_processing::connected_components(
    out, cc, CGAL::parameters::edge_is_constrained_map(constrained));
  BOOST_TEST(ncc == expected_patches);
  std::map<std::size_t, std::set<std::size_t> > patches_of_component, components_of_patch;
  for(auto f : out.faces()) { patches_of_component[cc[f]].insert(fp[f]); components_of_patch[fp[f]].insert(cc[f]); }
  for(const auto& p : patches_of_component) BOOST_TEST(p.second.size() == 1u);
  for(const auto& p : components_of_patch) BOOST_TEST(p.second.size() == 1u);
  BOOST_TEST(components_of_patch.size() == expected_patches);
  // the same surface: areas agree
  double area_in = 0, area_out = 0, min_altitude = 1e300, min_edge = 1e300;
  const Mesh& m = b.mesh();
  for(auto f : faces(m))
  {
    auto h = halfedge(f, m);
    const auto &p = get(CGAL::vertex_point, m, source(h, m)), &q = get(CGAL::vertex_point, m, target(h, m)),
               &r = get(CGAL::vertex_point, m, target(next(h, m), m));
    const double a = std::sqrt(CGAL::to_double(CGAL::squared_area(p, q, r)));
    area_in += a;
    for(double l : {CGAL::squared_distance(p, q), CGAL::squared_distance(q, r), CGAL::squared_distance(r, p)})
      min_altitude = std::min(min_altitude, 2 * a / std::sqrt(CGAL::to_double(l)));
  }
  for(auto f : out.faces()) area_out += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, out));
  for(auto e : out.edges()) min_edge = std::min(min_edge, std::sqrt(CGAL::to_double(CGAL::Polygon_mesh_processing::squared_edge_length(e, out))));
  BOOST_TEST(std::abs(area_out - area_in) <= 1e-9 * area_in);
  BOOST_TEST(min_edge >= 0.99 * delta * min_altitude);
}

} // namespace

BOOST_AUTO_TEST_SUITE(boundaries)

BOOST_AUTO_TEST_CASE(zigzag_surface_mesh) { zigzag_becomes_straight<SM>(); }
BOOST_AUTO_TEST_CASE(zigzag_polyhedron) { zigzag_becomes_straight<Poly>(); }

// Three sectors: one junction, three curves from it to the border; the left patch is on
// the left of the walking direction (the plane's normal is +z).
template <typename Mesh>
void junction_curves()
{
  Mesh m = fs_test::to_mesh<Mesh>(fs_test::plane(1., 20));
  auto vp = label_vertices(m, [](double x, double y, double) { return sector(x, y); });
  FS::Patch_boundaries<Mesh> b = FS::compute_patch_boundaries(m, vp);
  BOOST_TEST(b.number_of_patches() == 3u);
  BOOST_TEST(b.number_of_junctions() == 1u);
  BOOST_REQUIRE(b.curves().size() == 3u);
  const std::vector<std::pair<std::size_t, std::size_t> > pairs = { {0, 1}, {0, 2}, {1, 2} };
  BOOST_TEST((b.adjacent_patches() == pairs));
  for(const auto& c : b.curves())
  {
    BOOST_TEST(int(c.front) == int(FS::Boundary_end::JUNCTION));
    BOOST_TEST(int(c.back) == int(FS::Boundary_end::BORDER));
    BOOST_TEST(!c.points.front().is_on_edge());
    BOOST_TEST(c.points.back().is_on_edge());
    BOOST_TEST(CGAL::is_border(c.points.back().halfedge, m) == false); // the halfedge with the face
    BOOST_TEST(CGAL::is_border(edge(c.points.back().halfedge, m), m));
    // all curves start at the same junction point
    BOOST_TEST(distance(c.points.front().point, b.curves()[0].points.front().point) == 0.);
    for(std::size_t i = 0; i < c.points.size(); ++i)
    {
      BOOST_TEST(c.points[i].is_on_edge() == (i % 2 == 1)); // alternately in a face, on an edge
      if(i % 2 == 0 || i + 1 == c.points.size()) continue;
      // the crossed edge's end on the left of the walking direction is in the left patch
      const auto &p = c.points[i - 1].point, &q = c.points[i + 1].point, &x = c.points[i].point;
      const auto h = c.points[i].halfedge;
      for(auto v : {source(h, m), target(h, m)})
      {
        const auto& pv = get(CGAL::vertex_point, m, v);
        const double side = (q[0] - p[0]) * (CGAL::to_double(pv.y()) - x[1]) - (q[1] - p[1]) * (CGAL::to_double(pv.x()) - x[0]);
        BOOST_TEST(get(vp, v) == (side > 0 ? c.left_patch : c.right_patch));
      }
    }
    // every point's location reproduces its coordinates
    for(const auto& q : c.points)
    {
      const auto p = CGAL::Polygon_mesh_processing::construct_point(q.location, m);
      BOOST_TEST(std::abs(CGAL::to_double(p.x()) - q.point[0]) < 1e-12);
      BOOST_TEST(std::abs(CGAL::to_double(p.y()) - q.point[1]) < 1e-12);
    }
  }
  smooth_and_check(b, 20);
  check_refinement(b, 3, 0.1);
}

BOOST_AUTO_TEST_CASE(junction_surface_mesh) { junction_curves<SM>(); }
BOOST_AUTO_TEST_CASE(junction_polyhedron) { junction_curves<Poly>(); }

// A cap of the sphere: one closed curve, near the circle z = 0.5 (length 2 pi sqrt(3)/2
// = 5.441); smoothing shortens it in its band of triangles (it cannot shrink away: a
// vertex moves only if it had a cut edge) and keeps it closed.
BOOST_AUTO_TEST_CASE(closed_curve)
{
  SM m = fs_test::to_mesh<SM>(fs_test::icosphere(1., 4));
  auto vp = label_vertices(m, [](double, double, double z) { return z > 0.5 ? 7u : 2u; });
  FS::Patch_boundaries<SM> b = FS::compute_patch_boundaries(m, vp);
  BOOST_REQUIRE(b.curves().size() == 1u);
  const auto& c = b.curves()[0];
  BOOST_TEST(c.is_closed());
  BOOST_TEST(int(c.back) == int(FS::Boundary_end::CLOSED));
  BOOST_TEST(c.points.front().is_on_edge());
  BOOST_TEST(std::min(c.left_patch, c.right_patch) == 2u);
  BOOST_TEST(std::max(c.left_patch, c.right_patch) == 7u);
  BOOST_TEST(b.length() == c.length(), boost::test_tools::tolerance(1e-9));
  const double circle = 2 * M_PI * std::sqrt(0.75);
  BOOST_TEST_MESSAGE("closed: " << c.length() << " circle " << circle);
  BOOST_TEST(c.length() > 1.2 * circle); // the dual polyline zigzags: 7.08
  const FS::Boundary_smoothing_report r = smooth_and_check(b, 20);
  BOOST_TEST_MESSAGE("closed after: " << b.length() << " moves " << r.number_of_vertex_moves);
  BOOST_TEST(b.length() < r.length.front());
  BOOST_TEST(std::abs(b.length() - circle) < 0.1 * circle);
  BOOST_TEST(b.curves()[0].is_closed());
  check_refinement(b, 2, 0.1);
}

// A boundary next to a crease moves onto it. The roof's crease is the column x = 0;
// patch 0 is x < -0.05: the boundary starts in the strip of triangles between the
// columns x = -0.1 and x = 0, through their centroids (no feature edges are given, so
// the dual vertices are centroids), on average 0.05 from the crease. The curvature is
// given: k1 = -10 across the crease on its vertices, 0 elsewhere, so a triangle of the
// strip with two crease vertices has s = 20/3 (times 2, the largest side) and
// sqrt(lambda2) = 1/(1 + 0.05 * 13.3) = 0.6, one with a single crease vertex 0.75: a
// boundary along the crease (through the first kind only) has length 0.6 per unit,
// one through the middle of the strip 0.675. So the boundary is pressed onto the
// crease: 1/1000 of an edge away where it passes a crease vertex, along the crease
// between them.
template <typename Mesh>
void moves_onto_crease()
{
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type>::Kernel K;
  Mesh m = fs_test::to_mesh<Mesh>(roof());
  auto vp = label_vertices(m, [&](double x, double, double) { return x < -0.05 ? 0u : 1u; });
  auto no_features = get(CGAL::dynamic_edge_property_t<bool>(), m);
  for(auto e : edges(m)) put(no_features, e, false);
  auto curvature = get(CGAL::dynamic_vertex_property_t<FS::Principal_curvatures<K> >(), m);
  for(auto v : vertices(m))
  {
    FS::Principal_curvatures<K> c;
    const bool on_crease = std::abs(CGAL::to_double(get(CGAL::vertex_point, m, v).x())) < 1e-9;
    c.k1 = on_crease ? -10 : 0;
    c.d1 = typename K::Vector_3(1, 0, 0);
    c.d2 = typename K::Vector_3(0, 1, 0);
    put(curvature, v, c);
  }
  FS::Patch_boundaries<Mesh> b = FS::compute_patch_boundaries(
    m, vp, FS::parameters::edge_is_feature_map(no_features).principal_curvature_map(curvature));
  BOOST_REQUIRE(b.curves().size() == 1u);
  auto spread = [&]() {
    double worst = 0, sum = 0;
    for(const auto& q : b.curves()[0].points) { worst = std::max(worst, std::abs(q.point[0])); sum += std::abs(q.point[0]); }
    return std::make_pair(worst, sum / b.curves()[0].points.size());
  };
  const auto before = spread();
  const FS::Boundary_smoothing_report r = smooth_and_check(b, 20);
  const auto after = spread();
  BOOST_TEST_MESSAGE("crease: |x| max/mean before " << before.first << "/" << before.second << " after "
            << after.first << "/" << after.second << ", energy " << r.energy.front() << " -> " << r.energy.back()
            << ", moves " << r.number_of_vertex_moves);
  BOOST_TEST(before.second > 0.03);
  BOOST_TEST(after.first < 0.001);
}

BOOST_AUTO_TEST_CASE(crease_surface_mesh) { moves_onto_crease<SM>(); }
BOOST_AUTO_TEST_CASE(crease_polyhedron) { moves_onto_crease<Poly>(); }

// The initial point of a cut edge: where the shortest path between the dual vertices
// of its faces crosses it. Edge (0,0,0)-(1,0,0), d0 = (0.2, 1, 0) at distance 1 from
// the line, d1 at distance 3 above x = 0.8: the path crosses at 0.2 + 0.6 / 4 = 0.35,
// wherever d1 is turned about the line. On random edges the closed form is at the
// minimum of the length found by dense sampling, within the margin.
BOOST_AUTO_TEST_CASE(initial_edge_point)
{
  typedef FS::internal::Boundary_state<SM> B;
  typedef Eigen::Vector3d V;
  const V p0(0, 0, 0), p1(1, 0, 0);
  BOOST_TEST(std::abs(B::initial_edge_t(p0, p1, V(0.2, 1, 0), V(0.8, -3, 0)) - 0.35) < 1e-15);
  BOOST_TEST(std::abs(B::initial_edge_t(p0, p1, V(0.2, 1, 0), V(0.8, 0, 3)) - 0.35) < 1e-15);
  BOOST_TEST(std::abs(B::initial_edge_t(p1, p0, V(0.2, 1, 0), V(0.8, 0, 3)) - 0.65) < 1e-15);
  // beyond the ends: clamped to the margin
  BOOST_TEST(B::initial_edge_t(p0, p1, V(-2, 1, 0), V(-1, -1, 0)) == B::edge_margin);
  BOOST_TEST(B::initial_edge_t(p0, p1, V(2, 1, 0), V(3, 0, 1)) == 1 - B::edge_margin);
  // both on the line: the middle of their projections; a degenerate edge: its middle
  BOOST_TEST(std::abs(B::initial_edge_t(p0, p1, V(0.1, 0, 0), V(0.5, 0, 0)) - 0.3) < 1e-15);
  BOOST_TEST(B::initial_edge_t(p0, p0, V(0.1, 1, 0), V(0.5, -1, 0)) == 0.5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for(int i = 0; i < 200; ++i)
  {
    const V a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), d0(u(rng), u(rng), u(rng)), d1(u(rng), u(rng), u(rng));
    const auto length = [&](double t) { const V p = (1 - t) * a + t * b; return (p - d0).norm() + (p - d1).norm(); };
    const double t = B::initial_edge_t(a, b, d0, d1);
    BOOST_TEST((t >= B::edge_margin && t <= 1 - B::edge_margin));
    double best = length(B::edge_margin);
    for(int k = 0; k <= 100000; ++k) best = (std::min)(best, length(B::edge_margin + (1 - 2 * B::edge_margin) * k / 100000.));
    BOOST_TEST(length(t) <= best + 1e-12);
  }
}

// One triangle, vertex 0 alone in patch 0: its quadrilateral (vertex, the two edge
// midpoints, the centroid) covers 1/6 of the area 1/2, so the face goes to patch 1; with
// vertices 1 and 2 in patch 0 and vertex 0 in patch 1, to patch 0.
BOOST_AUTO_TEST_CASE(majority_one_triangle)
{
  fs_test::Soup s;
  s.points = { {0, 0, 0}, {1, 0, 0}, {0, 1, 0} };
  s.faces = { {0, 1, 2} };
  SM m = fs_test::to_mesh<SM>(s);
  for(int flip = 0; flip < 2; ++flip)
  {
    auto vp = m.add_property_map<SM::Vertex_index, int>("v:p" + std::to_string(flip), 0).first;
    for(auto v : m.vertices()) vp[v] = ((std::size_t(v) == 0) != (flip == 1)) ? 0 : 1;
    FS::Patch_boundaries<SM> b = FS::compute_patch_boundaries(m, vp);
    BOOST_REQUIRE(b.curves().size() == 1u);
    BOOST_TEST(b.curves()[0].points.size() == 3u); // border, centroid, border
    auto fp = m.add_property_map<SM::Face_index, int>("f:p" + std::to_string(flip), -1).first;
    BOOST_TEST(FS::majority_face_patches(b, fp) == 1u);
    BOOST_TEST(fp[*m.faces().begin()] == (flip == 0 ? 1 : 0));
  }
}

// Majority patches agree with the refinement without snapping: the patch of a face is
// the one whose refined triangles inside it cover most of its area.
BOOST_AUTO_TEST_CASE(majority_matches_refinement)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 10));
  auto vp = label_vertices(m, [](double x, double y, double) { return sector(x, y); });
  FS::Patch_boundaries<SM> b = FS::compute_patch_boundaries(m, vp);
  auto fp = m.add_property_map<SM::Face_index, std::size_t>("f:majority", 0).first;
  const std::size_t crossed = FS::majority_face_patches(b, fp);
  BOOST_TEST(crossed > 10u);
  SM out;
  auto ofp = out.add_property_map<SM::Face_index, std::size_t>("f:patch", 0).first;
  FS::refine_mesh_along_boundaries(b, out, ofp, FS::parameters::snapping_ratio(0.));
  std::size_t checked = 0;
  for(auto f : m.faces())
  {
    auto h = m.halfedge(f);
    const auto &a = m.point(m.source(h)), &bb = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
    std::map<std::size_t, double> area;
    for(auto g : out.faces())
    {
      auto k = out.halfedge(g);
      const auto cen = CGAL::centroid(out.point(out.source(k)), out.point(out.target(k)), out.point(out.target(out.next(k))));
      if(CGAL::orientation(a, bb, cen, Epick::Point_3(0, 0, 1)) == CGAL::NEGATIVE) continue;
      const Epick::Point_2 a2(a.x(), a.y()), b2(bb.x(), bb.y()), c2(c.x(), c.y()), p2(cen.x(), cen.y());
      if(CGAL::orientation(a2, b2, p2) == CGAL::NEGATIVE || CGAL::orientation(b2, c2, p2) == CGAL::NEGATIVE ||
         CGAL::orientation(c2, a2, p2) == CGAL::NEGATIVE) continue;
      area[ofp[g]] += CGAL::Polygon_mesh_processing::face_area(g, out);
    }
    std::size_t best = 0;
    double best_area = -1;
    for(const auto& x : area) if(x.second > best_area + 1e-12) { best = x.first; best_area = x.second; }
    BOOST_TEST(fp[f] == best);
    if(area.size() > 1) ++checked;
  }
  BOOST_TEST(checked == crossed);
}

// CGAL's fandisk segmented with the defaults: smoothing keeps the topology, lowers the
// energy, and the refinement gives back the patches as constrained components.
BOOST_AUTO_TEST_CASE(fandisk)
{
  SM m;
  BOOST_REQUIRE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m));
  auto vp = m.add_property_map<SM::Vertex_index, std::size_t>("v:patch", 0).first;
  // the paper's pipeline (no crease cut): boundary curves of a vertex labelling of the
  // input mesh, whose creases are crossed by curves rather than cut open
  const std::size_t n = FS::segment_along_features(m, vp, FS::parameters::crease_angle(180.));
  FS::Patch_boundaries<SM> b = FS::compute_patch_boundaries(m, vp);
  BOOST_TEST(b.number_of_patches() == n);
  const FS::Boundary_smoothing_report r = smooth_and_check(b, 10);
  BOOST_TEST_MESSAGE("fandisk: " << n << " patches, " << b.curves().size() << " curves, energy " << r.energy.front()
            << " -> " << r.energy.back() << ", length " << r.length.front() << " -> " << r.length.back() << ", moves "
            << r.number_of_vertex_moves);
  // the initial curves already pass through the feature points (the dual vertices of the
  // triangles on features), so the gain is smaller than on a zigzag: 5.19 -> 4.73
  BOOST_TEST(r.energy.back() < 0.95 * r.energy.front());
  // the patches are connected in the vertex graph: one component each
  check_refinement(b, n, 0.1);
  auto vp2 = m.add_property_map<SM::Vertex_index, std::size_t>("v:patch2", 0).first;
  b.write_vertex_patches(vp2);
  std::size_t moved = 0;
  for(auto v : m.vertices()) if(vp[v] != vp2[v]) ++moved;
  BOOST_TEST(moved <= r.number_of_vertex_moves);
}

BOOST_AUTO_TEST_CASE(invalid_values)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 4));
  auto vp = label_vertices(m, [](double x, double, double) { return x > 0.1 ? 1u : 0u; });
  FS::Patch_boundaries<SM> b = FS::compute_patch_boundaries(m, vp);
  BOOST_CHECK_THROW(FS::smooth_patch_boundaries(b, FS::parameters::smoothing_tolerance(-1.)), FS::Invalid_input);
  BOOST_CHECK_THROW(FS::smooth_patch_boundaries(b, FS::parameters::smoothing_iterations(-2)), FS::Invalid_input);
  SM out;
  auto ofp = out.add_property_map<SM::Face_index, int>("f:patch", 0).first;
  BOOST_CHECK_THROW(FS::refine_mesh_along_boundaries(b, out, ofp, FS::parameters::snapping_ratio(0.5)), FS::Invalid_input);
  std::ostringstream os;
  BOOST_CHECK_THROW(FS::write_PLY_refined_segmentation(os, b, FS::parameters::snapping_ratio(-0.1)), FS::Invalid_input);
  auto neg = m.add_property_map<SM::Vertex_index, int>("v:neg", -1).first;
  BOOST_CHECK_THROW(FS::compute_patch_boundaries(m, neg), FS::Invalid_input);
}

// Patch ids are the user's, whatever their size: an id beyond 32 bits reaches the refined
// mesh and its file unchanged.
BOOST_AUTO_TEST_CASE(patch_ids_beyond_32_bits)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 4));
  const std::size_t big = 5000000000u;
  auto vp = label_vertices(m, [&](double x, double, double) { return x > 0.1 ? big : std::size_t(7); });
  FS::Patch_boundaries<SM> b = FS::compute_patch_boundaries(m, vp);
  SM out;
  auto ofp = out.add_property_map<SM::Face_index, std::size_t>("f:patch", 0).first;
  FS::refine_mesh_along_boundaries(b, out, ofp);
  std::set<std::size_t> ids;
  for(auto f : out.faces()) ids.insert(ofp[f]);
  BOOST_TEST((ids == std::set<std::size_t>{ 7, big }));
  std::ostringstream os;
  FS::write_PLY_refined_segmentation(os, b);
  BOOST_TEST(os.str().find(" 5000000000 ") != std::string::npos);
}

// The writers' lines are made by TBB's threads in ordered chunks: 100,003 lines in
// chunks of 1,000, seven at a time (101 chunks in 15 batches), give the file that one
// thread appending line after line gives, at 1, 2 and 8 threads; a double's text reads
// back as the same double.
BOOST_AUTO_TEST_CASE(ordered_text_is_the_same_at_any_thread_count)
{
  namespace FSI = CGAL::Feature_segmentation::internal;
  const std::size_t n = 100003;
  auto format = [](std::size_t i, std::string& text) {
    FSI::append_integer(text, static_cast<long long>((i * 7919) % 100003) - 50000, ' ');
    FSI::append_double(text, 1. / double(i + 1), '\n');
  };
  std::string expected;
  for(std::size_t i = 0; i < n; ++i) format(i, expected);
  BOOST_TEST(std::count(expected.begin(), expected.end(), '\n') == std::ptrdiff_t(n));
  std::istringstream lines(expected);
  long long id = 0;
  std::string x;
  for(std::size_t i = 0; i < n && lines >> id >> x; ++i)
    if(std::stod(x) != 1. / double(i + 1)) BOOST_ERROR("line " << i << ": " << x << " is not 1/" << i + 1);
  for(int threads : { 1, 2, 8 })
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
#endif
    std::ostringstream os;
    FSI::write_ordered_text(os, n, format, true, 1000, 7);
    BOOST_TEST(os.str() == expected, threads << " threads");
    std::ostringstream default_chunks;
    FSI::write_ordered_text(default_chunks, n, format);
    BOOST_TEST(default_chunks.str() == expected, threads << " threads, default chunks");
  }
  std::ostringstream empty;
  FSI::write_ordered_text(empty, 0, format);
  BOOST_TEST(empty.str().empty());
}

// The PLY file of a mesh of 81,920 faces (five chunks of lines) and its patch ids: the
// same bytes at 1, 2 and 8 threads, and as many vertex and face lines as the mesh has.
BOOST_AUTO_TEST_CASE(segmentation_files_are_the_same_at_any_thread_count)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::icosphere(1., 6));
  BOOST_TEST(num_faces(m) == 81920u);
  auto fp = get(CGAL::dynamic_face_property_t<long>(), m);
  for(auto f : faces(m)) put(fp, f, long(f.idx() % 37) - 1); // -1: a face without patch
  std::string first_ply, first_ids;
  for(int threads : { 1, 2, 8 })
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
#endif
    std::ostringstream ply, ids;
    FS::write_PLY_segmentation(ply, m, fp);
    FS::write_patch_ids(ids, faces(m), fp);
    if(threads == 1)
    {
      first_ply = ply.str();
      first_ids = ids.str();
      const std::size_t lines = std::size_t(std::count(first_ply.begin(), first_ply.end(), '\n'));
      BOOST_TEST(lines == 14u + num_vertices(m) + num_faces(m)); // 14 header lines
      BOOST_TEST(std::size_t(std::count(first_ids.begin(), first_ids.end(), '\n')) == num_faces(m));
      BOOST_TEST(first_ids.substr(0, 9) == "-1\n0\n1\n2\n");
    }
    else
    {
      BOOST_TEST(ply.str() == first_ply, threads << " threads");
      BOOST_TEST(ids.str() == first_ids, threads << " threads");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
