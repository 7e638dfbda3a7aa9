// Crest lines: a torus with a four-lobed tube has four analytic ridge circles and four
// valley circles; a sphere and a plane have none; fandisk's sharp creases are found.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/crest_lines.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>

#include "test_meshes.h"

#include <string>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;

template <typename Mesh>
FS::Feature_lines<Mesh> lines_of(const Mesh& m, double threshold = FS::default_strength_threshold)
{
  auto efm = get(CGAL::dynamic_edge_property_t<bool>(), m);
  return FS::detect_feature_lines(m, efm, FS::parameters::strength_threshold(threshold));
}

template <typename Mesh>
void lobed_torus_test()
{
  fs_test::Lobed_torus torus;
  Mesh m = fs_test::to_mesh<Mesh>(torus.soup(160, 128));
  auto lines = lines_of(m);
  const double tube_edge = 2 * M_PI * torus.r0 / 128;
  // Every point of a strong line lies near a circle of its kind ...
  double worst = 0;
  std::vector<std::vector<int> > hits(2, std::vector<int>(torus.lobes * 36, 0));
  for(const auto& l : lines.lines)
  {
    const bool ridge = (l.type == FS::Feature_line_type::RIDGE);
    for(const auto& fp : l.points)
    {
      const auto p = fp.point(m, get(CGAL::vertex_point, m));
      std::array<double, 3> q{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
      worst = std::max(worst, torus.distance_to_circles(q, ridge));
      // ... and which circle and which tenth-of-a-radian sector around z it covers
      const double theta = std::atan2(q[1], q[0]) + M_PI;
      const double phi = std::atan2(q[2], std::hypot(q[0], q[1]) - torus.R) + 2 * M_PI;
      const int circle = int(std::lround(phi / (2 * M_PI / torus.lobes) - (ridge ? 0. : 0.5))) % torus.lobes;
      hits[ridge ? 0 : 1][circle * 36 + std::min(35, int(theta / (2 * M_PI) * 36))] = 1;
    }
  }
  int covered = 0;
  for(const auto& h : hits) for(int x : h) covered += x;
  for(int k=0;k<2;++k) for(int i=0;i<(int)hits[k].size();++i) if(!hits[k][i]) BOOST_TEST_MESSAGE("missing " << (k?"valley":"ridge") << " circle " << i/36 << " sector " << i%36);
  BOOST_TEST_MESSAGE("lobed torus: " << lines.lines.size() << " lines ("
                     << lines.number_of_lines(FS::Feature_line_type::RIDGE) << " ridges), worst distance "
                     << worst / tube_edge << " tube edges, sectors covered " << covered << "/" << 2 * torus.lobes * 36);
  // one closed line per circle, nothing else
  BOOST_TEST(lines.number_of_lines(FS::Feature_line_type::RIDGE) == std::size_t(torus.lobes));
  BOOST_TEST(lines.number_of_lines(FS::Feature_line_type::VALLEY) == std::size_t(torus.lobes));
  for(const auto& l : lines.lines) BOOST_TEST(l.is_closed);
  BOOST_TEST(worst < 0.25 * tube_edge);                // measured 0.10 tube edges
  BOOST_TEST(covered == 2 * torus.lobes * 36);          // all eight circles, all the way round
}

} // namespace

BOOST_AUTO_TEST_SUITE(crest_lines)

BOOST_AUTO_TEST_CASE(lobed_torus_surface_mesh) { lobed_torus_test<SM>(); }
BOOST_AUTO_TEST_CASE(lobed_torus_polyhedron) { lobed_torus_test<Poly>(); }

BOOST_AUTO_TEST_CASE(sphere_and_plane_have_no_lines)
{
  SM sphere = fs_test::to_mesh<SM>(fs_test::icosphere(1., 4));
  BOOST_TEST(lines_of(sphere).lines.size() == 0u);
  SM plane = fs_test::to_mesh<SM>(fs_test::plane(1., 30));
  BOOST_TEST(lines_of(plane, 0.).lines.size() == 0u); // not even below the threshold
}

BOOST_AUTO_TEST_CASE(lines_are_well_formed_and_deterministic)
{
  fs_test::Lobed_torus torus;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  auto a = lines_of(m, 0.), b = lines_of(m, 0.);
  BOOST_REQUIRE(a.lines.size() == b.lines.size());
  for(std::size_t i = 0; i < a.lines.size(); ++i)
  {
    BOOST_TEST(a.lines[i].points.size() == b.lines[i].points.size());
    BOOST_TEST(a.lines[i].strength == b.lines[i].strength);
    if(i > 0) BOOST_TEST(a.lines[i - 1].strength >= a.lines[i].strength);
    const auto& pts = a.lines[i].points;
    BOOST_TEST(pts.size() >= 2u);
    // consecutive points lie on two edges of one triangle
    const std::size_t nseg = a.lines[i].is_closed ? pts.size() : pts.size() - 1;
    for(std::size_t k = 0; k < nseg; ++k)
    {
      auto h = pts[k].halfedge, g = pts[(k + 1) % pts.size()].halfedge;
      bool share = false;
      for(auto hh : {h, opposite(h, m)})
        if(!is_border(hh, m))
          for(auto x : CGAL::halfedges_around_face(hh, m))
            share = share || edge(x, m) == edge(g, m);
      BOOST_TEST(share);
      BOOST_TEST((pts[k].t >= 0. && pts[k].t <= 1.));
    }
  }
}

BOOST_AUTO_TEST_CASE(fandisk_creases_are_found)
{
  SM m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m));
  auto efm = get(CGAL::dynamic_edge_property_t<bool>(), m);
  auto lines = FS::detect_feature_lines(m, efm);
  auto sharp = get(CGAL::dynamic_edge_property_t<bool>(), m);
  CGAL::Polygon_mesh_processing::detect_sharp_edges(m, 30, sharp);
  // a crease edge counts as found when a feature edge shares one of its vertices
  std::size_t n_sharp = 0, found = 0;
  for(auto e : edges(m))
  {
    if(!get(sharp, e)) continue;
    ++n_sharp;
    bool near = false;
    for(auto v : {source(halfedge(e, m), m), target(halfedge(e, m), m)})
      for(auto h : CGAL::halfedges_around_target(v, m))
        near = near || get(efm, edge(h, m));
    found += near;
  }
  const double fraction = double(found) / double(n_sharp);
  BOOST_TEST_MESSAGE("fandisk: " << lines.lines.size() << " lines, " << n_sharp
                     << " edges above 30 degrees, fraction with a feature point within one ring " << fraction);
  BOOST_TEST(n_sharp == 722u); // fandisk.off of CGAL's data
  BOOST_TEST(fraction > 0.98); // measured 0.993 with the defaults
}

BOOST_AUTO_TEST_CASE(rejects_bad_options)
{
  SM m = fs_test::to_mesh<SM>(fs_test::icosphere(1., 1));
  auto efm = get(CGAL::dynamic_edge_property_t<bool>(), m);
  BOOST_CHECK_THROW(FS::detect_feature_lines(m, efm, FS::parameters::strength_threshold(-1.)), FS::Invalid_input);
  BOOST_CHECK_THROW(FS::detect_feature_lines(m, efm, FS::parameters::umbilic_ratio(1.5)), FS::Invalid_input);
  SM empty;
  BOOST_CHECK_THROW(FS::detect_feature_lines(empty, efm), FS::Invalid_input);
}

BOOST_AUTO_TEST_SUITE_END()
