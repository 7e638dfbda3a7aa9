// The editing class: agreement with the free function, the effect and locality of each
// edit on fixtures built to show it, and exact undo.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/face_patches.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>
#include <map>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef FS::Feature_aligned_segmentation<SM> Segmentation;

std::vector<std::size_t> labels(const SM& m, const Segmentation& s)
{
  std::vector<std::size_t> l;
  for(auto v : m.vertices()) l.push_back(s.patch(v));
  return l;
}

// Two labellings agree on a vertex subset up to renumbering.
bool same_partition(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b,
                    const std::vector<char>& subset)
{
  std::map<std::size_t, std::size_t> ab, ba;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    if(!subset[i]) continue;
    if(ab.emplace(a[i], b[i]).first->second != b[i]) return false;
    if(ba.emplace(b[i], a[i]).first->second != a[i]) return false;
  }
  return true;
}

// tube angle of a point of the lobed torus, in [0, 2 pi)
double tube_angle(const K::Point_3& p, double R)
{
  double phi = std::atan2(p.z(), std::hypot(p.x(), p.y()) - R);
  return phi < 0 ? phi + 2 * M_PI : phi;
}

} // namespace

BOOST_AUTO_TEST_SUITE(editing)

BOOST_AUTO_TEST_CASE(agrees_with_the_free_function)
{
  SM m = fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64));
  Segmentation seg(m, FS::parameters::alpha(0.6));
  for(double a : {0.6, 1.0, 0.8})
  {
    seg.set_alpha(a);
    auto vp = m.add_property_map<SM::Vertex_index, std::size_t>("v:p").first;
    double cost = 0;
    const std::size_t n = FS::segment_along_features(m, vp, FS::parameters::alpha(a).cut_cost_output(&cost));
    BOOST_TEST(seg.number_of_patches() == n);
    for(auto v : m.vertices()) BOOST_TEST(seg.patch(v) == vp[v]);
    BOOST_TEST(seg.cut_cost() == cost, boost::test_tools::tolerance(1e-9));
    m.remove_property_map(vp);
  }
}

// At alpha 0.6 the torus is cut along its 4 ridge circles only (4 bands). Raising
// alpha_e around one valley circle cuts that valley too: its band splits (5 patches);
// the three other bands keep their vertices. Undo restores the labels exactly.
BOOST_AUTO_TEST_CASE(local_refine_is_local_and_undoable)
{
  fs_test::Lobed_torus torus;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  Segmentation seg(m, FS::parameters::alpha(0.6));
  BOOST_REQUIRE(seg.number_of_patches() == 4u);
  const auto before = labels(m, seg);
  // the region: faces within 0.3 rad of the valley circle at phi = pi/4
  std::vector<SM::Face_index> region;
  for(auto f : m.faces())
  {
    const auto h = m.halfedge(f);
    if(std::abs(tube_angle(m.point(m.target(h)), torus.R) - M_PI / 4) < 0.3) region.push_back(f);
  }
  const std::size_t n = seg.add_to_alpha(region, 0.6);
  BOOST_TEST(n == 5u);
  // vertices away from the edited band (phi outside [0, pi/2]) keep their partition
  std::vector<char> far(m.number_of_vertices(), 0);
  std::size_t i = 0;
  for(auto v : m.vertices()) { const double phi = tube_angle(m.point(v), torus.R); far[i++] = (phi > M_PI / 2 + 0.1 && phi < 2 * M_PI - 0.1); }
  BOOST_TEST(same_partition(before, labels(m, seg), far));
  // coarsening back by the same amount gives the 4 bands again
  BOOST_TEST(seg.add_to_alpha(region, -0.6) == 4u);
  BOOST_TEST(seg.undo());
  BOOST_TEST(seg.undo());
  BOOST_TEST((labels(m, seg) == before));
  BOOST_TEST(!seg.undo());
}

BOOST_AUTO_TEST_CASE(global_refine_and_multiply)
{
  SM m = fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64));
  Segmentation seg(m, FS::parameters::alpha(0.4));
  BOOST_TEST(seg.number_of_patches() == 1u);
  BOOST_TEST(seg.set_alpha(0.6) == 4u);
  BOOST_TEST(seg.set_alpha(1.0) == 8u);
  std::vector<SM::Face_index> all(m.faces().begin(), m.faces().end());
  BOOST_TEST(seg.multiply_alpha(all, 0.) == 1u); // alpha_e = 0: every weight positive
  BOOST_TEST(seg.undo());
  BOOST_TEST(seg.number_of_patches() == 8u);
  BOOST_CHECK_THROW(seg.set_alpha(std::nan("")), FS::Invalid_input);
  // The history is bounded by memory. An alpha edit writes nothing per edge or per
  // vertex: its state holds a new alpha and the patch of every oversegment (one size_t
  // each) and shares everything else, so each earlier state costs 8 bytes per node of
  // G', far less than a double per edge and a label per vertex (8 (E + V) bytes). With
  // a limit of five of them, five edits stay undoable, whatever the number made.
  const std::size_t per_state = 8 * seg.number_of_oversegments();
  BOOST_TEST(seg.number_of_oversegments() > 8u);
  BOOST_TEST(per_state * 20 < 8u * (num_edges(m) + num_vertices(m)));
  seg.set_undo_memory_limit(5 * per_state);
  BOOST_TEST(seg.number_of_undoable_edits() <= 5u);
  const std::size_t recorded_before = seg.number_of_recorded_edits();
  std::vector<std::vector<std::size_t> > kept;
  for(std::size_t i = 0; i < 20; ++i)
  {
    seg.set_alpha(0.6 + 0.4 * double(i % 2));
    kept.push_back(labels(m, seg));
  }
  BOOST_TEST(seg.number_of_undoable_edits() == 5u);
  BOOST_TEST(seg.undo_memory() == 5 * per_state);
  // every one was recorded, the oldest dropped: after the kept ones, undo() refuses;
  // each undo gives back exactly the labels of the edit before
  BOOST_TEST(seg.number_of_recorded_edits() == recorded_before + 20);
  for(std::size_t i = 0; i < 5; ++i)
  {
    BOOST_TEST(seg.undo());
    BOOST_TEST((labels(m, seg) == kept[18 - i]));
  }
  BOOST_TEST(!seg.undo());
  // undone states count too, and a smaller limit drops them first; after an edit, the
  // state before it always stays, whatever the limit
  BOOST_TEST(seg.number_of_redoable_edits() == 5u);
  BOOST_TEST(seg.undo_memory() == 5 * per_state);
  seg.set_undo_memory_limit(0);
  BOOST_TEST(seg.number_of_redoable_edits() == 0u);
  BOOST_TEST(seg.undo_memory() == 0u);
  BOOST_TEST(!seg.redo());
  BOOST_TEST((labels(m, seg) == kept[14]));
  seg.set_alpha(0.6);
  BOOST_TEST(seg.number_of_undoable_edits() == 1u);
  BOOST_TEST(seg.undo_memory() == per_state);
  BOOST_TEST(seg.undo());
  BOOST_TEST((labels(m, seg) == kept[14]));
  seg.set_undo_memory_limit(std::size_t(256) << 20);
  BOOST_CHECK_THROW(seg.multiply_alpha(all, -1.), FS::Invalid_input);
}

// An alpha edit writes no alpha_e: the feature edges' values follow the state's alpha.
// After alpha 1.0 and back to 0.6, every weight is the construction's to the last bit
// (shifting each alpha_e there and back would round), and so are the labels and the cut
// cost. A local coarsening in between writes the alpha_e of its edges only (stored at
// the construction's alpha): back at 0.6, the others are untouched.
BOOST_AUTO_TEST_CASE(alpha_there_and_back_is_exact)
{
  SM m = fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64));
  Segmentation seg(m, FS::parameters::alpha(0.6));
  BOOST_REQUIRE(seg.number_of_patches() == 4u);
  auto weights = [&] {
    std::vector<double> w;
    for(auto e : m.edges()) w.push_back(seg.weight(e));
    return w;
  };
  const std::vector<double> w0 = weights();
  const std::vector<std::size_t> l0 = labels(m, seg);
  const double cost0 = seg.cut_cost();
  BOOST_TEST(seg.set_alpha(1.0) == 8u);
  BOOST_TEST(seg.set_alpha(0.6) == 4u);
  BOOST_TEST((weights() == w0));
  BOOST_TEST((labels(m, seg) == l0));
  BOOST_TEST(seg.cut_cost() == cost0);
  // one face's feature edges coarsened at alpha 1.0: back at 0.6, only they differ
  std::vector<SM::Face_index> one;
  for(auto f : m.faces())
  {
    bool has_feature = false;
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) has_feature |= seg.is_feature_edge(m.edge(h));
    if(has_feature) { one.push_back(f); break; }
  }
  BOOST_REQUIRE(one.size() == 1u);
  std::set<SM::Edge_index> changed;
  for(auto h : CGAL::halfedges_around_face(m.halfedge(one[0]), m))
    if(seg.is_feature_edge(m.edge(h))) changed.insert(m.edge(h));
  seg.set_alpha(1.0);
  seg.add_to_alpha(one, -0.25);
  seg.set_alpha(0.6);
  std::size_t i = 0;
  for(auto e : m.edges())
  {
    if(changed.count(e)) BOOST_TEST(seg.alpha(e) == ((0.6 + (1.0 - 0.6)) + -0.25) - (1.0 - 0.6));
    else BOOST_TEST(seg.weight(e) == w0[i]);
    ++i;
  }
}

// Merging the patches a stroke touches gives one patch, kept by later solves.
BOOST_AUTO_TEST_CASE(merge_reduces_and_persists)
{
  fs_test::Lobed_torus torus;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  Segmentation seg(m, FS::parameters::alpha(1.0));
  BOOST_REQUIRE(seg.number_of_patches() == 8u);
  // faces across the ridge circle at phi = pi/2: they touch its two neighbouring bands
  std::vector<SM::Face_index> stroke;
  for(auto f : m.faces())
  {
    const auto h = m.halfedge(f);
    if(std::abs(tube_angle(m.point(m.target(h)), torus.R) - M_PI / 2) < 0.15) stroke.push_back(f);
  }
  BOOST_TEST(seg.merge_patches(stroke) == 7u);
  BOOST_TEST(seg.set_alpha(1.2) == 7u); // the merge is a constraint of later solves
  BOOST_TEST(seg.undo());
  BOOST_TEST(seg.undo());
  BOOST_TEST(seg.number_of_patches() == 8u);
}

// A plane has no feature: one patch. A sketch from border to border across it makes
// its crossed edges feature edges with alpha_e = 2 (w = -Award on flat ground): two
// patches, split along the sketch.
BOOST_AUTO_TEST_CASE(sketch_splits_a_featureless_plane)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 20));
  Segmentation seg(m, FS::parameters::alpha(0.6));
  BOOST_REQUIRE(seg.number_of_patches() == 1u);
  // a vertical stroke at x = 0.03, from y = -1 to y = 1
  auto face_at = [&](double x, double y) {
    for(auto f : m.faces())
    {
      auto h = m.halfedge(f);
      K::Triangle_3 t(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
      if(t.has_on(K::Point_3(x, y, 0))) return f;
    }
    return SM::Face_index();
  };
  std::vector<Segmentation::Sketch_point> sketch;
  for(double y : {-0.99, 0., 0.99}) sketch.push_back({face_at(0.03, y), K::Point_3(0.03, y, 0)});
  const std::size_t n = seg.add_sketch(sketch);
  BOOST_TEST(n == 2u);
  std::size_t crossing_features = 0;
  for(auto e : m.edges())
  {
    const auto& p = m.point(m.source(m.halfedge(e)));
    const auto& q = m.point(m.target(m.halfedge(e)));
    if(seg.is_feature_edge(e)) { ++crossing_features; BOOST_TEST(seg.alpha(e) == 2.0); BOOST_TEST((p.x() - 0.03) * (q.x() - 0.03) <= 0.); }
  }
  BOOST_TEST(crossing_features >= 20u); // at least one per row of the 20x20 grid
  // the two patches are the two sides of the stroke
  std::size_t left = std::size_t(-1), right = std::size_t(-1);
  for(auto v : m.vertices())
  {
    const double x = m.point(v).x();
    if(x < 0.03) { if(left == std::size_t(-1)) left = seg.patch(v); BOOST_TEST(seg.patch(v) == left); }
    else { if(right == std::size_t(-1)) right = seg.patch(v); BOOST_TEST(seg.patch(v) == right); }
  }
  BOOST_TEST(left != right);
  BOOST_TEST(seg.undo());
  BOOST_TEST(seg.number_of_patches() == 1u);
  for(auto e : m.edges()) BOOST_TEST(!seg.is_feature_edge(e));
  BOOST_CHECK_THROW(seg.add_sketch(sketch, 1.0), FS::Invalid_input);
}

// Undo and redo are exact after every kind of edit: on the torus at alpha 0.6 (4 bands),
// alpha 1.0 gives 8, a merge across one ridge circle 7, then a sketch round the tube adds
// feature edges across the bands, a local coarsening and a local factor change alpha_e
// in a band. Undoing the five and redoing them walks through the same labels, feature
// edges, per-edge alpha and weights and cut costs; a new edit after an undo forgets the
// redo history. A copy of the object shares its history and edits on its own.
BOOST_AUTO_TEST_CASE(redo_makes_every_kind_of_edit_again)
{
  fs_test::Lobed_torus torus;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  Segmentation seg(m, FS::parameters::alpha(0.6));
  BOOST_REQUIRE(seg.number_of_patches() == 4u);
  BOOST_TEST(!seg.redo());
  auto features = [&] {
    std::vector<char> f;
    for(auto e : m.edges()) f.push_back(seg.is_feature_edge(e) ? 1 : 0);
    return f;
  };
  auto alphas = [&] {
    std::vector<double> a;
    for(auto e : m.edges()) { a.push_back(seg.alpha(e)); a.push_back(seg.weight(e)); }
    return a;
  };
  struct Step
  {
    std::vector<std::size_t> labels;
    std::vector<char> features;
    std::vector<double> alphas;
    double cost;
    std::size_t patches;
  };
  auto step = [&] { return Step{ labels(m, seg), features(), alphas(), seg.cut_cost(), seg.number_of_patches() }; };
  std::vector<Step> steps{ step() };
  BOOST_TEST(seg.set_alpha(1.0) == 8u);
  steps.push_back(step());
  std::vector<SM::Face_index> stroke;
  for(auto f : m.faces())
    if(std::abs(tube_angle(m.point(m.target(m.halfedge(f))), torus.R) - M_PI / 2) < 0.15) stroke.push_back(f);
  BOOST_TEST(seg.merge_patches(stroke) == 7u);
  steps.push_back(step());
  // a sketch: the mesh's vertices on one meridian of the tube (a closed loop round it)
  std::vector<Segmentation::Sketch_point> sketch;
  const double theta = 0.05; // the angle round the torus's axis, off the grid's vertices
  for(int i = 0; i <= 48; ++i)
  {
    const std::array<double, 3> t = torus.point(theta, 2 * M_PI * i / 48);
    const K::Point_3 target(t[0], t[1], t[2]);
    SM::Face_index nearest;
    double best = 1e300;
    for(auto f : m.faces())
    {
      auto h = m.halfedge(f);
      const double d = CGAL::to_double(CGAL::squared_distance(
        K::Triangle_3(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))), target));
      if(d < best) { best = d; nearest = f; }
    }
    auto h = m.halfedge(nearest);
    const K::Point_3 p = K::Triangle_3(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))))
                           .supporting_plane().projection(target);
    sketch.push_back({nearest, p});
  }
  seg.add_sketch(sketch);
  steps.push_back(step());
  BOOST_TEST(steps.back().features != steps[2].features); // the sketch added feature edges
  // a band round the valley at phi = pi/4, coarsened by 0.5, then its alpha_e halved
  std::vector<SM::Face_index> band;
  for(auto f : m.faces())
    if(std::abs(tube_angle(m.point(m.target(m.halfedge(f))), torus.R) - M_PI / 4) < 0.3) band.push_back(f);
  seg.add_to_alpha(band, -0.5);
  steps.push_back(step());
  BOOST_TEST(steps.back().alphas != steps[3].alphas);
  seg.multiply_alpha(band, 0.5);
  steps.push_back(step());
  BOOST_TEST(steps.back().alphas != steps[4].alphas);
  const std::size_t last = steps.size() - 1;
  auto check = [&](const Step& s) {
    BOOST_TEST(seg.number_of_patches() == s.patches);
    BOOST_TEST((labels(m, seg) == s.labels));
    BOOST_TEST((features() == s.features));
    BOOST_TEST((alphas() == s.alphas));
    BOOST_TEST(seg.cut_cost() == s.cost);
  };
  for(std::size_t i = last; i > 0; --i)
  {
    BOOST_TEST(seg.undo());
    BOOST_TEST(seg.number_of_redoable_edits() == last + 1 - i);
    check(steps[i - 1]);
  }
  BOOST_TEST(!seg.undo());
  for(std::size_t i = 1; i <= last; ++i)
  {
    BOOST_TEST(seg.redo());
    check(steps[i]);
  }
  BOOST_TEST(!seg.redo());
  // a copy edits on its own: the original keeps its state and its history
  {
    Segmentation copy = seg;
    BOOST_TEST(copy.undo());
    BOOST_TEST(copy.set_alpha(0.6) != 0u);
    check(steps[last]);
    BOOST_TEST(seg.number_of_undoable_edits() == last);
  }
  // undo twice, then a new edit: nothing left to redo
  BOOST_TEST(seg.undo());
  BOOST_TEST(seg.undo());
  check(steps[last - 2]);
  BOOST_TEST(seg.set_alpha(0.6) == 4u);
  BOOST_TEST(seg.number_of_redoable_edits() == 0u);
  BOOST_TEST(!seg.redo());
}

// The class's boundaries reuse its precomputation and equal those the free function
// computes from the same labels.
BOOST_AUTO_TEST_CASE(boundaries_from_the_class)
{
  // the circles a quarter of a ring step from a ring of vertices: each boundary crosses
  // one ring of quads, and cuts some triangles a quarter of the way from their lone corner
  fs_test::Lobed_torus torus;
  torus.phase = M_PI / 128;
  SM m = fs_test::to_mesh<SM>(torus.soup(80, 64));
  Segmentation seg(m, FS::parameters::alpha(1.0));
  const auto b = seg.patch_boundaries();
  BOOST_TEST(b.number_of_patches() == 8u);
  BOOST_TEST(b.curves().size() == 8u); // one closed curve per circle
  auto vp = m.add_property_map<SM::Vertex_index, std::size_t>("v:p").first;
  seg.vertex_patches(vp);
  const auto c = FS::compute_patch_boundaries(m, vp, FS::parameters::alpha(1.0));
  BOOST_TEST(c.curves().size() == b.curves().size());
  BOOST_TEST(c.length() == b.length(), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.anisotropic_length() == b.anisotropic_length(), boost::test_tools::tolerance(1e-12));
  // one face rule: patch(face) is the area majority under these boundaries, face by face
  auto by_area = m.add_property_map<SM::Face_index, std::size_t>("f:area").first;
  auto by_class = m.add_property_map<SM::Face_index, std::size_t>("f:class").first;
  const std::size_t crossed = FS::majority_face_patches(b, by_area);
  seg.face_patches(by_class);
  std::size_t same = 0, differs_from_vertex_majority = 0;
  for(auto f : m.faces())
  {
    same += (get(by_area, f) == seg.patch(f) && get(by_class, f) == seg.patch(f));
    std::array<std::size_t, 3> l = { 0, 0, 0 };
    int k = 0;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) l[k++] = seg.patch(v);
    const std::size_t majority = (l[0] == l[1] || l[0] == l[2]) ? l[0] : l[1];
    differs_from_vertex_majority += (l[1] == l[2] || l[0] == l[1] || l[0] == l[2]) && majority != seg.patch(f);
  }
  BOOST_TEST(same == m.number_of_faces());
  // each of the eight circles runs round the torus through one ring of 80 quads between
  // two rings of vertices, crossing both triangles of every quad
  BOOST_TEST(crossed == 8u * 80u * 2u);
  // the rule is not the vertex majority: where a boundary cuts a triangle far from its
  // lone corner, the corner's patch covers the most area (9/16 at three quarters)
  BOOST_TEST(differs_from_vertex_majority > 0u);
}

// A solver that throws leaves the object as it was before the edit; bad faces and far
// sketch points are refused.
BOOST_AUTO_TEST_CASE(failed_edits_leave_the_state_unchanged)
{
  SM m = fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64));
  std::shared_ptr<int> calls = std::make_shared<int>(0);
  auto solver = [calls](const FS::Correlation_clustering_graph& g, std::vector<std::size_t>& labels) -> std::size_t {
    if(++*calls > 1) throw std::runtime_error("solver failure");
    return FS::Default_correlation_clustering_solver()(g, labels);
  };
  Segmentation seg(m, FS::parameters::alpha(1.0).solver(solver));
  BOOST_REQUIRE(seg.number_of_patches() == 8u);
  const auto before = labels(m, seg);
  const double cost = seg.cut_cost();
  BOOST_CHECK_THROW(seg.set_alpha(0.6), std::runtime_error);
  BOOST_TEST(seg.alpha() == 1.0);
  BOOST_TEST(seg.number_of_patches() == 8u);
  BOOST_TEST((labels(m, seg) == before));
  BOOST_TEST(seg.cut_cost() == cost);
  BOOST_TEST(seg.number_of_undoable_edits() == 0u);
  std::vector<SM::Face_index> bad{SM::Face_index()};
  BOOST_CHECK_THROW(seg.add_to_alpha(bad, 0.1), FS::Invalid_input);
  std::vector<Segmentation::Sketch_point> far{{*m.faces().begin(), K::Point_3(100, 0, 0)},
                                              {*m.faces().begin(), K::Point_3(0, 0, 0)}};
  BOOST_CHECK_THROW(seg.add_sketch(far), FS::Invalid_input);
}

BOOST_AUTO_TEST_CASE(works_on_polyhedron)
{
  typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;
  Poly p = fs_test::to_mesh<Poly>(fs_test::Lobed_torus{}.soup(80, 64));
  FS::Feature_aligned_segmentation<Poly> seg(p, FS::parameters::alpha(1.0));
  BOOST_TEST(seg.number_of_patches() == 8u);
  BOOST_TEST(seg.set_alpha(0.6) == 4u);
  auto fp = get(CGAL::dynamic_face_property_t<int>(), p);
  seg.face_patches(fp);
  for(auto f : faces(p)) BOOST_TEST(std::size_t(get(fp, f)) == seg.patch(f));
}

BOOST_AUTO_TEST_SUITE_END()
