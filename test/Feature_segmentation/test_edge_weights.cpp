// Edge weights (Eq. 3-6) on meshes whose weights are known in closed form, and the sign
// pattern on fandisk.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/edge_weights.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "test_meshes.h"

#include <string>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef FS::Principal_curvatures<K> PC;

K::Point_3 centroid(const SM& m, SM::Face_index f)
{
  auto h = m.halfedge(f);
  return CGAL::centroid(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
}

// A curvature map that is the same everywhere: k1 = kappa along x, k2 = 0 along y.
auto constant_curvature(SM& m, double kappa)
{
  auto c = m.add_property_map<SM::Vertex_index, PC>("v:test_curvature").first;
  PC pc;
  pc.k1 = kappa; pc.k2 = 0; pc.d1 = K::Vector_3(1, 0, 0); pc.d2 = K::Vector_3(0, 1, 0);
  for(auto v : m.vertices()) c[v] = pc;
  return c;
}

} // namespace

BOOST_AUTO_TEST_SUITE(edge_weights)

// In a flat, feature-free region both metrics agree: Similarity = Award = the distance
// between the two face centroids; on the border, from the centroid to the edge midpoint.
BOOST_AUTO_TEST_CASE(flat_similarity_equals_award)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 12));
  auto sim = m.add_property_map<SM::Edge_index, double>("e:sim").first;
  auto award = m.add_property_map<SM::Edge_index, double>("e:award").first;
  auto no_features = m.add_property_map<SM::Edge_index, bool>("e:f", false).first;
  FS::compute_similarity_and_award(m, sim, award, FS::parameters::edge_is_feature_map(no_features));
  for(auto e : m.edges())
  {
    auto h = m.halfedge(e);
    double expected;
    if(m.is_border(e))
    {
      auto f = m.is_border(h) ? m.face(m.opposite(h)) : m.face(h);
      expected = std::sqrt(CGAL::squared_distance(centroid(m, f), CGAL::midpoint(m.point(m.source(h)), m.point(m.target(h)))));
    }
    else
      expected = std::sqrt(CGAL::squared_distance(centroid(m, m.face(h)), centroid(m, m.face(m.opposite(h)))));
    BOOST_TEST(sim[e] == expected, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(award[e] == expected, boost::test_tools::tolerance(1e-12));
  }
}

// With k1 = kappa along x and k2 = 0, every triangle's metric is diag(1, lambda2) in
// (x, y), lambda2 = 1 / (1 + gamma kappa L)^2 with L the largest side of the bounding
// box: Similarity = sqrt(wx^2 + lambda2 wy^2) for the dual segment w, Award = |w|.
BOOST_AUTO_TEST_CASE(anisotropic_metric_in_closed_form)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 10)); // [-1, 1]^2: L = 2
  const double kappa = 7., gamma = 0.05, L = 2.;
  auto curv = constant_curvature(m, kappa);
  auto sim = m.add_property_map<SM::Edge_index, double>("e:sim").first;
  auto award = m.add_property_map<SM::Edge_index, double>("e:award").first;
  auto no_features = m.add_property_map<SM::Edge_index, bool>("e:f", false).first;
  FS::compute_similarity_and_award(m, sim, award, FS::parameters::principal_curvature_map(curv)
                                                   .edge_is_feature_map(no_features).gamma(gamma));
  const double lambda2 = 1. / ((1 + gamma * kappa * L) * (1 + gamma * kappa * L));
  std::size_t checked = 0;
  for(auto e : m.edges())
  {
    if(m.is_border(e)) continue;
    auto h = m.halfedge(e);
    const K::Vector_3 w = centroid(m, m.face(m.opposite(h))) - centroid(m, m.face(h));
    BOOST_TEST(sim[e] == std::sqrt(w.x() * w.x() + lambda2 * w.y() * w.y()), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(award[e] == std::sqrt(w.squared_length()), boost::test_tools::tolerance(1e-12));
    ++checked;
  }
  BOOST_TEST(checked == 3u * 10 * 10 - 2 * 10); // interior edges of a 10x10 quad grid split in two
}

// The weight is Similarity - alpha_e Award with alpha_e = alpha on feature edges only,
// or read from an edge map.
BOOST_AUTO_TEST_CASE(weight_combines_the_terms)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 8));
  auto curv = constant_curvature(m, 3.);
  auto sim = m.add_property_map<SM::Edge_index, double>("e:sim").first;
  auto award = m.add_property_map<SM::Edge_index, double>("e:award").first;
  auto w = m.add_property_map<SM::Edge_index, double>("e:w").first;
  auto feat = m.add_property_map<SM::Edge_index, bool>("e:f", false).first;
  std::size_t n = 0;
  for(auto e : m.edges()) if((n++) % 3 == 0) feat[e] = true;
  auto np = FS::parameters::principal_curvature_map(curv).edge_is_feature_map(feat);
  FS::compute_similarity_and_award(m, sim, award, np);
  const std::size_t nfeat = FS::compute_edge_weights(m, w, np.alpha(0.7));
  BOOST_TEST(nfeat == (m.number_of_edges() + 2) / 3);
  for(auto e : m.edges())
    BOOST_TEST(w[e] == sim[e] - (feat[e] ? 0.7 : 0.) * award[e], boost::test_tools::tolerance(1e-12));
  auto alpha_map = m.add_property_map<SM::Edge_index, double>("e:alpha", 0.25).first;
  FS::compute_edge_weights(m, w, np.edge_alpha_map(alpha_map));
  for(auto e : m.edges())
    BOOST_TEST(w[e] == sim[e] - 0.25 * award[e], boost::test_tools::tolerance(1e-12));
}

// A degenerate (zero-area) triangle has no plane: its metric is the Euclidean one, and
// the weights stay finite.
BOOST_AUTO_TEST_CASE(degenerate_triangle_is_euclidean)
{
  SM m;
  auto a = m.add_vertex(K::Point_3(0, 0, 0)), b = m.add_vertex(K::Point_3(2, 0, 0));
  auto c = m.add_vertex(K::Point_3(1, 0, 0)), d = m.add_vertex(K::Point_3(1, 1, 0));
  m.add_face(a, c, b); // collinear: zero area
  m.add_face(a, b, d);
  auto curv = constant_curvature(m, 5.);
  auto sim = m.add_property_map<SM::Edge_index, double>("e:sim").first;
  auto award = m.add_property_map<SM::Edge_index, double>("e:award").first;
  auto no_features = m.add_property_map<SM::Edge_index, bool>("e:f", false).first;
  FS::compute_similarity_and_award(m, sim, award, FS::parameters::principal_curvature_map(curv)
                                                   .edge_is_feature_map(no_features));
  for(auto e : m.edges())
  {
    BOOST_TEST(std::isfinite(sim[e]));
    BOOST_TEST(std::isfinite(award[e]));
  }
  // the shared edge (a, b): dual segment from (1, 0, 0) to (1, 1/3, 0), along y: the
  // degenerate face measures it Euclidean, the other with lambda2 (L = 2, gamma 0.05)
  auto ab = m.edge(m.halfedge(a, b));
  const double lambda2 = 1. / ((1 + 0.05 * 5. * 2.) * (1 + 0.05 * 5. * 2.));
  BOOST_TEST(award[ab] == 1. / 3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(sim[ab] == 0.5 * (1. / 3 + std::sqrt(lambda2) / 3), boost::test_tools::tolerance(1e-12));
}

// On fandisk with alpha = 0.6 the edges of strong crest lines are mostly negative: their
// Award outweighs the Similarity that the curvature across them shrinks. (That every
// non-feature edge is positive follows from w = Similarity, a length, and is not tested:
// the lengths themselves are, against hand computations, above.)
BOOST_AUTO_TEST_CASE(fandisk_sign_pattern)
{
  SM m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m));
  auto feat = m.add_property_map<SM::Edge_index, bool>("e:f", false).first;
  FS::Feature_lines<SM> lines = FS::detect_feature_lines(m, feat);
  auto w = m.add_property_map<SM::Edge_index, double>("e:w").first;
  FS::compute_edge_weights(m, w, FS::parameters::feature_lines(lines).alpha(0.6));
  // salient: edges holding a point of a line of strength >= 10
  std::size_t salient = 0, negative = 0;
  for(const auto& l : lines.lines)
    if(l.strength >= 10.)
      for(const auto& p : l.points) { ++salient; negative += (w[m.edge(p.halfedge)] < 0); }
  const double fraction = double(negative) / double(salient);
  BOOST_TEST_MESSAGE("fandisk, alpha 0.6: " << negative << " of " << salient
                     << " salient feature edges negative (" << fraction << ")");
  BOOST_TEST(salient > 500u);
  BOOST_TEST(fraction > 0.9); // measured 0.915
}

#ifdef CGAL_LINKED_WITH_TBB
// With concurrency_tag Parallel_tag, the curvatures, the per-face metrics and the per-edge
// terms are computed by TBB's threads; every face and edge is its own, so the weights at
// 1, 2 and 8 threads are exactly the sequential ones.
BOOST_AUTO_TEST_CASE(parallel_weights_equal_the_sequential_ones_at_any_thread_count)
{
  SM m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m));
  auto weights = [&](auto tag) {
    auto w = m.add_property_map<SM::Edge_index, double>("e:w").first;
    FS::compute_edge_weights(m, w, FS::parameters::alpha(0.6).concurrency_tag(tag));
    std::vector<double> out;
    for(SM::Edge_index e : m.edges()) out.push_back(w[e]);
    m.remove_property_map(w);
    return out;
  };
  const std::vector<double> sequential = weights(CGAL::Sequential_tag());
  BOOST_TEST(sequential.size() == m.number_of_edges());
  for(std::size_t threads : {1u, 2u, 8u})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    BOOST_TEST((weights(CGAL::Parallel_tag()) == sequential), threads << " threads");
  }
}
#endif

BOOST_AUTO_TEST_CASE(rejects_bad_options)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 4));
  auto w = m.add_property_map<SM::Edge_index, double>("e:w").first;
  BOOST_CHECK_THROW(FS::compute_edge_weights(m, w, FS::parameters::gamma(-1.)), FS::Invalid_input);
  BOOST_CHECK_THROW(FS::compute_edge_weights(m, w, FS::parameters::alpha(std::nan(""))), FS::Invalid_input);
}

BOOST_AUTO_TEST_SUITE_END()
