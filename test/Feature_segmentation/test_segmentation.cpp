// Automatic segmentation: exact patch counts on shapes whose features are known, the
// face rule, the cut cost output, per-edge alpha, determinism, two mesh types and kernels.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/face_patches.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/edge_weights.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#include <cmath>
#include <set>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;

template <typename Mesh>
std::size_t patches(const Mesh& m, double alpha)
{
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
  return FS::segment_along_features(m, vp, FS::parameters::alpha(alpha));
}

// The four-lobed torus has four ridge circles and four valley circles (test_crest_lines).
// alpha <= 0.4: no feature edge is negative enough to pay for a closed cut: 1 patch.
// alpha = 0.6: the ridge circles, where the anisotropy (2.4 vs 1.3 in profile curvature)
// and so the award are largest, are cut: 4 bands. alpha = 1: all 8 circles: 8 bands.
template <typename Mesh>
void lobed_torus_counts()
{
  Mesh m = fs_test::to_mesh<Mesh>(fs_test::Lobed_torus{}.soup(80, 64));
  BOOST_TEST(patches(m, 0.4) == 1u);
  BOOST_TEST(patches(m, 0.6) == 4u);
  BOOST_TEST(patches(m, 1.0) == 8u);
  BOOST_TEST(patches(m, 1.5) == 8u);
}

} // namespace

BOOST_AUTO_TEST_SUITE(segmentation)

BOOST_AUTO_TEST_CASE(lobed_torus_surface_mesh) { lobed_torus_counts<SM>(); }
BOOST_AUTO_TEST_CASE(lobed_torus_polyhedron) { lobed_torus_counts<Poly>(); }

BOOST_AUTO_TEST_CASE(featureless_shapes_are_one_patch)
{
  BOOST_TEST(patches(fs_test::to_mesh<SM>(fs_test::icosphere(1., 3)), 1.0) == 1u);
  BOOST_TEST(patches(fs_test::to_mesh<SM>(fs_test::plane(1., 10)), 1.0) == 1u);
  BOOST_TEST(patches(fs_test::to_mesh<Poly>(fs_test::icosphere(2., 3)), 1.0) == 1u);
}

// Each ridge band is one patch: vertices with the same label lie between two
// consecutive ridge circles (tube angle phi in [k pi/2, (k+1) pi/2)).
BOOST_AUTO_TEST_CASE(bands_follow_the_ridges)
{
  fs_test::Lobed_torus torus;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  auto vp = m.add_property_map<SM::Vertex_index, std::size_t>("v:patch").first;
  BOOST_REQUIRE(FS::segment_along_features(m, vp, FS::parameters::alpha(0.6)) == 4u);
  std::vector<std::set<std::size_t> > quadrant_labels(4);
  for(auto v : m.vertices())
  {
    const auto& p = m.point(v);
    double phi = std::atan2(p.z(), std::hypot(p.x(), p.y()) - torus.R);
    if(phi < 0) phi += 2 * M_PI;
    const double q = phi / (M_PI / 2);
    if(std::abs(q - std::round(q)) < 0.1) continue; // on a ridge circle: either side
    quadrant_labels[std::size_t(q) % 4].insert(vp[v]);
  }
  std::set<std::size_t> all;
  for(const auto& s : quadrant_labels) { BOOST_TEST(s.size() == 1u); all.insert(s.begin(), s.end()); }
  BOOST_TEST(all.size() == 4u);
}

BOOST_AUTO_TEST_CASE(outputs_are_consistent)
{
  // the circles midway between rings of vertices, so each boundary crosses one ring of quads
  fs_test::Lobed_torus torus;
  torus.phase = M_PI / 64;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  auto vp = m.add_property_map<SM::Vertex_index, std::size_t>("v:patch").first;
  auto fp = m.add_property_map<SM::Face_index, int>("f:patch").first;
  double cost = 0;
  const std::size_t n = FS::segment_along_features(m, vp, FS::parameters::alpha(1.0).face_patch_map(fp).cut_cost_output(&cost));
  // labels normalised: 0..n-1, first appearance in vertex order
  std::size_t next = 0;
  std::vector<char> seen(n, 0);
  for(auto v : m.vertices())
  {
    BOOST_REQUIRE(vp[v] < n);
    if(!seen[vp[v]]) { BOOST_TEST(vp[v] == next); ++next; seen[vp[v]] = 1; }
  }
  // face rule: the patch covering most of the face's area under the boundaries of the
  // vertex patches (computed here by the free functions, from the vertex patches alone);
  // a face whose corners share a patch has it
  auto fa = m.add_property_map<SM::Face_index, std::size_t>("f:area").first;
  FS::majority_face_patches(FS::compute_patch_boundaries(m, vp, FS::parameters::alpha(1.0)), fa);
  std::size_t uniform = 0;
  for(auto f : m.faces())
  {
    auto h = m.halfedge(f);
    std::size_t a = vp[m.source(h)], b = vp[m.target(h)], c = vp[m.target(m.next(h))];
    if(a == b && b == c) { BOOST_TEST(std::size_t(fp[f]) == a); ++uniform; }
    BOOST_TEST(std::size_t(fp[f]) == fa[f]);
  }
  BOOST_TEST(uniform == m.number_of_faces() - 8u * 80u * 2u); // 8 circles cross 160 faces each
  // the cut cost is the sum of the weights of the cut edges (Eq. 1)
  auto w = m.add_property_map<SM::Edge_index, double>("e:w").first;
  FS::compute_edge_weights(m, w, FS::parameters::alpha(1.0));
  double expected_cost = 0;
  for(auto e : m.edges())
    if(vp[m.source(m.halfedge(e))] != vp[m.target(m.halfedge(e))]) expected_cost += w[e];
  BOOST_TEST(cost == expected_cost, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(cost < 0.);
  // deterministic
  auto vp2 = m.add_property_map<SM::Vertex_index, std::size_t>("v:patch2").first;
  FS::segment_along_features(m, vp2, FS::parameters::alpha(1.0));
  for(auto v : m.vertices()) BOOST_TEST(vp[v] == vp2[v]);
}

BOOST_AUTO_TEST_CASE(edge_alpha_map_controls_the_weights)
{
  // the circles midway between rings of vertices, so each boundary crosses one ring of quads
  fs_test::Lobed_torus torus;
  torus.phase = M_PI / 64;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  auto vp = m.add_property_map<SM::Vertex_index, std::size_t>("v:patch").first;
  // alpha_e = 0 everywhere: every weight is positive, nothing to cut
  auto zero = m.add_property_map<SM::Edge_index, double>("e:zero", 0.).first;
  BOOST_TEST(FS::segment_along_features(m, vp, FS::parameters::edge_alpha_map(zero).alpha(1.0)) == 1u);
  // alpha_e = 1 on feature edges, 0 elsewhere: the same as alpha = 1
  auto feat = m.add_property_map<SM::Edge_index, bool>("e:f", false).first;
  FS::detect_feature_lines(m, feat);
  auto one = m.add_property_map<SM::Edge_index, double>("e:one", 0.).first;
  for(auto e : m.edges()) one[e] = feat[e] ? 1. : 0.;
  BOOST_TEST(FS::segment_along_features(m, vp, FS::parameters::edge_alpha_map(one)) == 8u);
}

BOOST_AUTO_TEST_CASE(rejects_bad_input)
{
  SM empty;
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), empty);
  BOOST_CHECK_THROW(FS::segment_along_features(empty, vp), FS::Invalid_input);
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 4));
  auto vq = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
  BOOST_CHECK_THROW(FS::segment_along_features(m, vq, FS::parameters::alpha(INFINITY)), FS::Invalid_input);
  BOOST_CHECK_THROW(FS::segment_along_features(m, vq, FS::parameters::gamma(-0.1)), FS::Invalid_input);
  m.point(*m.vertices().begin()) = Epick::Point_3(std::nan(""), 0, 0);
  BOOST_CHECK_THROW(FS::segment_along_features(m, vq), FS::Invalid_input);
}

BOOST_AUTO_TEST_SUITE_END()
