// Principal curvatures against analytic values: a sphere, a cylinder and a saddle, each
// at two resolutions with the error shrinking, on two mesh types and two kernels.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/principal_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

template <typename Mesh>
struct Curvature_errors
{
  double max_k1 = 0, max_k2 = 0, max_dir = 0; // absolute errors
};

template <typename Mesh, typename Check>
Curvature_errors<Mesh> run(const fs_test::Soup& soup, int rings, Check check)
{
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef FS::Principal_curvatures<K> PC;
  Mesh m = fs_test::to_mesh<Mesh>(soup);
  auto cmap = get(CGAL::dynamic_vertex_property_t<PC>(), m);
  FS::estimate_principal_curvatures(m, cmap, FS::parameters::neighborhood_rings(rings));
  Curvature_errors<Mesh> err;
  for(auto v : vertices(m))
    check(get(CGAL::vertex_point, m, v), get(cmap, v), err);
  return err;
}

template <typename Mesh>
void sphere_test()
{
  const double r = 2.;
  double previous = 1e300;
  // measured: 0.047 (level 3, 642 vertices), 0.016 (level 4): second-order convergence
  for(auto [level, tol] : {std::pair<int, double>{3, 0.06}, {4, 0.02}})
  {
    auto err = run<Mesh>(fs_test::icosphere(r, level), 2, [&](const auto&, const auto& c, auto& e) {
      e.max_k1 = std::max(e.max_k1, std::abs(CGAL::to_double(c.k1) - 1. / r));
      e.max_k2 = std::max(e.max_k2, std::abs(CGAL::to_double(c.k2) - 1. / r));
    });
    const double rel = std::max(err.max_k1, err.max_k2) * r;
    BOOST_TEST_MESSAGE("sphere r=2 level " << level << ": max relative curvature error " << rel);
    BOOST_TEST(rel < tol);
    BOOST_TEST(rel < previous); // converges under refinement
    previous = rel;
  }
}

template <typename Mesh>
void cylinder_test()
{
  const double r = 1., hgt = 4.;
  double previous_k = 1e300, previous_dir = 1e300;
  // measured: 0.028 (48x48), 0.0069 (96x96); directions exact by symmetry
  for(auto [n, tol] : {std::pair<int, double>{48, 0.035}, {96, 0.009}})
  {
    const double band = hgt / 2 - 4 * hgt / n; // away from the two border circles
    auto err = run<Mesh>(fs_test::cylinder(r, hgt, n, n), 2, [&](const auto& p, const auto& c, auto& e) {
      if(std::abs(CGAL::to_double(p.z())) > band) return;
      e.max_k1 = std::max(e.max_k1, std::abs(CGAL::to_double(c.k1) - 1. / r));
      e.max_k2 = std::max(e.max_k2, std::abs(CGAL::to_double(c.k2)));
      // d2 along the axis: 1 - |d2 . z|
      e.max_dir = std::max(e.max_dir, 1. - std::abs(CGAL::to_double(c.d2.z())));
    });
    BOOST_TEST_MESSAGE("cylinder r=1 " << n << "x" << n << ": |k1-1/r| " << err.max_k1
                       << ", |k2| " << err.max_k2 << ", 1-|d2.z| " << err.max_dir);
    const double kerr = std::max(err.max_k1, err.max_k2);
    BOOST_TEST(kerr < tol);
    BOOST_TEST(err.max_dir < 1e-6);
    BOOST_TEST(kerr < previous_k);
    BOOST_TEST(err.max_dir <= previous_dir + 1e-12);
    previous_k = kerr; previous_dir = err.max_dir;
  }
}

template <typename Mesh>
void saddle_test()
{
  // z = x^2 - y^2 with upward normal: at the origin k = -2 along x, +2 along y.
  double previous = 1e300;
  // measured: 0.0017 (20x20), 0.00043 (40x40)
  for(auto [n, tol] : {std::pair<int, double>{20, 0.003}, {40, 0.0008}})
  {
    double k_x = 0, k_y = 0, dir_err = 1;
    run<Mesh>(fs_test::saddle(0.5, n), 2, [&](const auto& p, const auto& c, auto&) {
      if(std::abs(CGAL::to_double(p.x())) > 1e-9 || std::abs(CGAL::to_double(p.y())) > 1e-9) return;
      const bool d1_is_x = std::abs(CGAL::to_double(c.d1.x())) > std::abs(CGAL::to_double(c.d1.y()));
      k_x = CGAL::to_double(d1_is_x ? c.k1 : c.k2);
      k_y = CGAL::to_double(d1_is_x ? c.k2 : c.k1);
      dir_err = 1. - std::abs(CGAL::to_double(d1_is_x ? c.d1.x() : c.d2.x()));
    });
    const double err = std::max(std::abs(k_x + 2.), std::abs(k_y - 2.));
    BOOST_TEST_MESSAGE("saddle n=" << n << ": k along x " << k_x << ", along y " << k_y
                       << ", error " << err << ", direction error " << dir_err);
    BOOST_TEST(err < tol);
    BOOST_TEST(dir_err < 1e-3);
    BOOST_TEST(err < previous);
    previous = err;
  }
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Simple_cartesian<double> SC;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<SC> Poly;

} // namespace

BOOST_AUTO_TEST_SUITE(principal_curvatures)

BOOST_AUTO_TEST_CASE(sphere_surface_mesh) { sphere_test<SM>(); }
BOOST_AUTO_TEST_CASE(sphere_polyhedron) { sphere_test<Poly>(); }
BOOST_AUTO_TEST_CASE(cylinder_surface_mesh) { cylinder_test<SM>(); }
BOOST_AUTO_TEST_CASE(cylinder_polyhedron) { cylinder_test<Poly>(); }
BOOST_AUTO_TEST_CASE(saddle_surface_mesh) { saddle_test<SM>(); }
BOOST_AUTO_TEST_CASE(saddle_polyhedron) { saddle_test<Poly>(); }

// A slab 1 x 1 x 0.02: beyond the rings, the neighbourhood radius (here 0.1 of the
// diagonal, 5.6 edges of the top's 40 x 40 grid) reaches the rim, but the normal cone
// (30 degrees) keeps out the rim's vertices (normals at 45 degrees) and the side walls
// (90): every top vertex three rings or more from the rim sees a plane, curvature 0.
// Without the cone, vertices 3 to 5 rings in fitted the walls and bent.
// Both radii (about 5 and 10 mean edges) span more than 3 mean edges, so the search
// beyond the rings goes over clusters of vertices, which the cone keeps out of the walls
// in the same way.
void thin_wall_test(double radius)
{
  std::vector<int> side;
  const int n = 40;
  SM m = fs_test::to_mesh<SM>(fs_test::box(1., 1., 0.02, n, side));
  auto cmap = get(CGAL::dynamic_vertex_property_t<FS::Principal_curvatures<Epick> >(), m);
  FS::estimate_principal_curvatures(m, cmap, FS::parameters::neighborhood_radius(radius));
  std::size_t checked = 0;
  double worst = 0;
  for(auto v : vertices(m))
  {
    const auto& p = m.point(v);
    const double lo = 3. / n - 1e-9, hi = 1. - lo;
    if(p.z() != 0.02 || p.x() < lo || p.x() > hi || p.y() < lo || p.y() > hi)
      continue;
    ++checked;
    worst = std::max({ worst, std::abs(get(cmap, v).k1), std::abs(get(cmap, v).k2) });
  }
  BOOST_TEST(checked == std::size_t((n - 5) * (n - 5))); // x, y in 3/40 .. 37/40
  BOOST_TEST(worst < 1e-9);
}

BOOST_AUTO_TEST_CASE(radius_does_not_wrap_round_a_thin_wall) { thin_wall_test(0.1); }
BOOST_AUTO_TEST_CASE(radius_over_clusters_does_not_wrap_round_a_thin_wall) { thin_wall_test(0.2); }

// On a sphere the radius only enlarges the neighbourhood: the curvature stays 1/r.
BOOST_AUTO_TEST_CASE(radius_keeps_the_sphere_round)
{
  SM m = fs_test::to_mesh<SM>(fs_test::icosphere(2., 4)); // 5120 faces, edge ~0.08
  auto cmap = get(CGAL::dynamic_vertex_property_t<FS::Principal_curvatures<Epick> >(), m);
  // 0.05 of the diagonal (4 x 2 sqrt 3): a radius of 0.69, about 8 rings, thinned to 32
  FS::estimate_principal_curvatures(m, cmap, FS::parameters::neighborhood_radius(0.05));
  double worst = 0;
  for(auto v : vertices(m))
    worst = std::max({ worst, std::abs(get(cmap, v).k1 - 0.5), std::abs(get(cmap, v).k2 - 0.5) });
  BOOST_TEST(worst < 0.01);
}

// A radius of many rings: 0.05 of the diagonal is 0.35 on the sphere of radius 2 at
// level 6 (81,920 faces), 9 mean edges, so the search beyond the rings goes over
// clusters of 18 vertices (the ball holds about 3.6 x 9^2 vertices, 16 clusters), each
// standing for its first. The fit still gives 1/r: measured 0.0057 at worst, against
// 0.0055 vertex by vertex.
BOOST_AUTO_TEST_CASE(radius_over_clusters_keeps_the_sphere_round)
{
  SM m = fs_test::to_mesh<SM>(fs_test::icosphere(2., 6));
  auto cmap = get(CGAL::dynamic_vertex_property_t<FS::Principal_curvatures<Epick> >(), m);
  FS::estimate_principal_curvatures(m, cmap, FS::parameters::neighborhood_radius(0.05));
  double worst = 0;
  for(auto v : vertices(m))
    worst = std::max({ worst, std::abs(get(cmap, v).k1 - 0.5), std::abs(get(cmap, v).k2 - 0.5) });
  BOOST_TEST_MESSAGE("sphere, radius over clusters: largest curvature error " << worst);
  BOOST_TEST(worst < 0.007);
}

BOOST_AUTO_TEST_CASE(rejects_bad_radius)
{
  SM m = fs_test::to_mesh<SM>(fs_test::icosphere(1., 1));
  auto cmap = get(CGAL::dynamic_vertex_property_t<FS::Principal_curvatures<Epick> >(), m);
  for(double r : { -0.01, 1.5, std::nan("") })
    BOOST_CHECK_THROW(FS::estimate_principal_curvatures(m, cmap, FS::parameters::neighborhood_radius(r)),
                      FS::Invalid_input);
}

BOOST_AUTO_TEST_CASE(rejects_bad_rings)
{
  SM m = fs_test::to_mesh<SM>(fs_test::icosphere(1., 1));
  auto cmap = get(CGAL::dynamic_vertex_property_t<FS::Principal_curvatures<Epick> >(), m);
  BOOST_CHECK_THROW(FS::estimate_principal_curvatures(m, cmap, FS::parameters::neighborhood_rings(0)),
                    FS::Invalid_input);
}

#ifdef CGAL_LINKED_WITH_TBB
// The parallel fit (concurrency_tag Parallel_tag) gives, at 1, 2 and 8 threads, exactly
// the sequential curvatures: every vertex's fit is its own, whatever thread runs it, and
// the vertex normals and the extremality gradients sum their faces in face order.
BOOST_AUTO_TEST_CASE(parallel_fits_equal_the_sequential_ones_at_any_thread_count)
{
  SM m;
  BOOST_REQUIRE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m));
  typedef FS::Principal_curvatures<Epick> PC;
  auto estimate = [&](auto tag) {
    auto map = m.add_property_map<SM::Vertex_index, PC>("v:fs_pc").first;
    FS::estimate_principal_curvatures(m, map, FS::parameters::concurrency_tag(tag));
    std::vector<PC> out;
    for(SM::Vertex_index v : m.vertices()) out.push_back(map[v]);
    m.remove_property_map(map);
    return out;
  };
  const std::vector<PC> sequential = estimate(CGAL::Sequential_tag());
  for(std::size_t threads : {1u, 2u, 8u})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const std::vector<PC> parallel = estimate(CGAL::Parallel_tag());
    std::size_t different = 0;
    for(std::size_t i = 0; i < sequential.size(); ++i)
      if(parallel[i].k1 != sequential[i].k1 || parallel[i].k2 != sequential[i].k2 ||
         parallel[i].d1 != sequential[i].d1 || parallel[i].d2 != sequential[i].d2 ||
         parallel[i].dk1 != sequential[i].dk1 || parallel[i].dk2 != sequential[i].dk2)
        ++different;
    BOOST_TEST(different == 0u, threads << " threads: " << different << " vertices differ");
  }
}

// The same with the search over clusters (the fine sphere of
// radius_over_clusters_keeps_the_sphere_round): the clusters are grown once, in vertex
// order, before the fits.
BOOST_AUTO_TEST_CASE(parallel_fits_over_clusters_equal_the_sequential_ones)
{
  SM m = fs_test::to_mesh<SM>(fs_test::icosphere(2., 6));
  typedef FS::Principal_curvatures<Epick> PC;
  auto estimate = [&](auto tag) {
    auto map = get(CGAL::dynamic_vertex_property_t<PC>(), m);
    FS::estimate_principal_curvatures(m, map, FS::parameters::neighborhood_radius(0.05).concurrency_tag(tag));
    std::vector<double> out;
    for(SM::Vertex_index v : m.vertices()) out.insert(out.end(), { get(map, v).k1, get(map, v).k2, get(map, v).dk1 });
    return out;
  };
  const std::vector<double> sequential = estimate(CGAL::Sequential_tag());
  for(std::size_t threads : {1u, 2u, 8u})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    BOOST_TEST((estimate(CGAL::Parallel_tag()) == sequential), threads << " threads");
  }
}
#endif

BOOST_AUTO_TEST_SUITE_END()
