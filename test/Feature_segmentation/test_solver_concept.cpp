// The CorrelationClusteringSolver concept: an archetype, a class with exactly what the
// concept requires (a copy constructor and the const operator(); no default constructor,
// no assignment, no nested types), is passed to segment_along_features. That the test
// compiles proves the segmentation uses nothing outside the concept; that its result is
// the archetype's own answer on the weights of compute_edge_weights proves the solver
// is really the one called, on the graph the documentation describes (nodes = vertices,
// edges = mesh edges, weights = compute_edge_weights). The shipped models go through the
// same path.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/edge_weights.h>
#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Greedy_additive_edge_contraction.h>
#include <CGAL/Feature_segmentation/Kernighan_lin_with_joins.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#include <cstddef>
#include <type_traits>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;

// What the archetype saw; shared by all its copies through a pointer, since the
// segmentation works on its own copy of the solver.
struct Call_record
{
  std::size_t calls = 0;
  bool labels_empty_on_entry = true;
};

// The archetype. Its answer is the connected components of the graph restricted to the
// edges of positive weight: a real partition, checkable independently (no positive edge
// is cut, every cluster is connected by positive edges), and different from what any
// shipped solver returns, so the test can tell who did the work.
class Solver_archetype
{
public:
  // Not a requirement of the concept: the test needs some way to make the first object.
  explicit Solver_archetype(Call_record* record) : m_record(record) {}
  Solver_archetype(const Solver_archetype&) = default;
  Solver_archetype& operator=(const Solver_archetype&) = delete;

  std::size_t operator()(const FS::Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    ++m_record->calls;
    m_record->labels_empty_on_entry = labels.empty();
    const std::size_t n = g.number_of_nodes();
    std::vector<std::size_t> parent(n);
    for(std::size_t i = 0; i < n; ++i) parent[i] = i;
    auto find = [&parent](std::size_t i) {
      while(parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for(std::size_t e = 0; e < g.number_of_edges(); ++e)
      if(g.weight(e) > 0) parent[find(g.source(e))] = find(g.target(e));
    labels.resize(n);
    for(std::size_t i = 0; i < n; ++i) labels[i] = find(i);
    return FS::normalize_labels(labels);
  }

private:
  Call_record* m_record;
};

static_assert(!std::is_default_constructible<Solver_archetype>::value,
              "the archetype must not offer more than the concept");
static_assert(!std::is_copy_assignable<Solver_archetype>::value,
              "the archetype must not offer more than the concept");
static_assert(std::is_copy_constructible<FS::Greedy_additive_edge_contraction>::value, "");
static_assert(std::is_copy_constructible<FS::Kernighan_lin_with_joins>::value, "");
static_assert(std::is_copy_constructible<
                FS::Solver_sequence<FS::Greedy_additive_edge_contraction, FS::Kernighan_lin_with_joins> >::value, "");
static_assert(std::is_copy_constructible<FS::Default_correlation_clustering_solver>::value, "");

// The documented graph, built independently of the package's internals: node i is the
// i-th vertex of vertices(m), edge j the j-th edge of edges(m), its weight from
// compute_edge_weights with the same options as the segmentation.
template <typename Mesh>
FS::Correlation_clustering_graph weighted_vertex_graph(const Mesh& m, double alpha)
{
  auto weight = get(CGAL::dynamic_edge_property_t<double>(), m);
  FS::compute_edge_weights(m, weight, FS::parameters::alpha(alpha));
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
  std::size_t n = 0;
  for(auto v : vertices(m)) put(index, v, n++);
  FS::Correlation_clustering_graph g(n);
  for(auto e : edges(m))
    g.add_edge(get(index, source(e, m)), get(index, target(e, m)), get(weight, e));
  return g;
}

// Runs segment_along_features with `solver` on the full vertex graph (the graph built
// above, which the test can compare with) and returns the vertex labels in the order of
// vertices(m); `cost` and `count` receive the cut cost and the returned patch count.
template <typename Mesh, typename Solver>
std::vector<std::size_t> segment_with(const Mesh& m, double alpha, const Solver& solver,
                                      double& cost, std::size_t& count)
{
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
  count = FS::segment_along_features(
    m, vp, FS::parameters::alpha(alpha).solver(solver).use_oversegmentation(false).cut_cost_output(&cost));
  std::vector<std::size_t> labels;
  for(auto v : vertices(m)) labels.push_back(get(vp, v));
  return labels;
}

// Independent check that `labels` are the components of the positive edges of `g`.
bool are_positive_components(const FS::Correlation_clustering_graph& g, const std::vector<std::size_t>& labels,
                             std::size_t k)
{
  std::vector<std::vector<std::size_t> > positive(g.number_of_nodes());
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
  {
    if(!(g.weight(e) > 0)) continue;
    if(labels[g.source(e)] != labels[g.target(e)]) return false; // a cut positive edge
    positive[g.source(e)].push_back(g.target(e));
    positive[g.target(e)].push_back(g.source(e));
  }
  // One traversal per cluster must reach the whole cluster.
  std::vector<char> seen(g.number_of_nodes(), 0);
  std::size_t traversals = 0;
  for(std::size_t s = 0; s < g.number_of_nodes(); ++s)
  {
    if(seen[s]) continue;
    ++traversals;
    std::vector<std::size_t> stack{s};
    seen[s] = 1;
    while(!stack.empty())
    {
      const std::size_t u = stack.back();
      stack.pop_back();
      for(std::size_t w : positive[u])
        if(!seen[w]) { seen[w] = 1; stack.push_back(w); }
    }
  }
  return traversals == k;
}

template <typename Mesh>
void archetype_test(const Mesh& m, double alpha, std::size_t expected_patches)
{
  Call_record record;
  record.labels_empty_on_entry = false;
  const Solver_archetype archetype(&record);
  double cost = 0;
  std::size_t count = 0;
  const std::vector<std::size_t> segmented = segment_with(m, alpha, archetype, cost, count);

  BOOST_TEST(record.calls == 1u);               // the segmentation used the archetype, once
  BOOST_TEST(record.labels_empty_on_entry);     // and gave it no initial partition

  const FS::Correlation_clustering_graph g = weighted_vertex_graph(m, alpha);
  std::vector<std::size_t> expected;
  const std::size_t k = archetype(g, expected);
  BOOST_TEST(record.calls == 2u);
  BOOST_TEST(are_positive_components(g, expected, k));
  BOOST_TEST(k == expected_patches);
  BOOST_TEST(count == k);
  BOOST_TEST(segmented == expected, boost::test_tools::per_element());
  BOOST_TEST(cost == FS::cut_cost(g, expected), boost::test_tools::tolerance(1e-12));
}

// A shipped model through the same path: the segmentation's answer is the model's own
// answer on the documented graph (the models are deterministic).
template <typename Mesh, typename Solver>
double shipped_model_test(const Mesh& m, double alpha, const Solver& solver)
{
  const Solver copy(solver);
  double cost = 0;
  std::size_t count = 0;
  const std::vector<std::size_t> segmented = segment_with(m, alpha, copy, cost, count);
  const FS::Correlation_clustering_graph g = weighted_vertex_graph(m, alpha);
  std::vector<std::size_t> expected;
  BOOST_TEST(copy(g, expected) == count);
  BOOST_TEST(segmented == expected, boost::test_tools::per_element());
  BOOST_TEST(cost == FS::cut_cost(g, expected), boost::test_tools::tolerance(1e-12));
  return cost;
}

} // namespace

BOOST_AUTO_TEST_SUITE(solver_concept)

// On the four-lobed torus at alpha 1, the edges crossed by the four ridge and the four
// valley circles are negative enough to be cut (test_segmentation: 8 bands), and each
// band between two circles is held together by positive edges: 8 components.
BOOST_AUTO_TEST_CASE(archetype_on_lobed_torus_surface_mesh)
{
  archetype_test(fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64)), 1.0, 8u);
}

BOOST_AUTO_TEST_CASE(archetype_on_lobed_torus_polyhedron)
{
  archetype_test(fs_test::to_mesh<Poly>(fs_test::Lobed_torus{}.soup(80, 64)), 1.0, 8u);
}

// A sphere has no crest line, hence no negative edge: one component.
BOOST_AUTO_TEST_CASE(archetype_on_icosphere)
{
  archetype_test(fs_test::to_mesh<SM>(fs_test::icosphere(1., 3)), 1.0, 1u);
}

// With the default options the solver may be given another graph than the vertex graph
// (the oversegmentation's reduced graph); the archetype must still be the one called,
// once, and the reported cost must be that of the returned vertex patches.
BOOST_AUTO_TEST_CASE(archetype_with_default_options)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64));
  Call_record record;
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
  double cost = 0;
  const std::size_t count = FS::segment_along_features(
    m, vp, FS::parameters::alpha(1.0).solver(Solver_archetype(&record)).cut_cost_output(&cost));
  BOOST_TEST(record.calls == 1u);
  std::vector<std::size_t> labels;
  for(auto v : vertices(m)) labels.push_back(get(vp, v));
  std::vector<std::size_t> normalized = labels;
  BOOST_TEST(FS::normalize_labels(normalized) == count);
  BOOST_TEST(normalized == labels, boost::test_tools::per_element()); // already normalised
  BOOST_TEST(cost == FS::cut_cost(weighted_vertex_graph(m, 1.0), labels), boost::test_tools::tolerance(1e-9));
  BOOST_TEST(count == 8u); // the eight bands between the crest circles, as on the full graph
}

// The library's own composition accepts a user model that is only copy constructible.
BOOST_AUTO_TEST_CASE(archetype_in_a_solver_sequence)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64));
  Call_record record;
  const FS::Solver_sequence<Solver_archetype, FS::Kernighan_lin_with_joins> sequence{
    Solver_archetype(&record), FS::Kernighan_lin_with_joins()};
  const double sequence_cost = shipped_model_test(m, 0.6, sequence);
  BOOST_TEST(record.calls == 2u); // once in the segmentation, once on the test's graph

  // KLj never returns a worse partition than the one it starts from.
  Call_record alone;
  double archetype_cost = 0;
  std::size_t count = 0;
  segment_with(m, 0.6, Solver_archetype(&alone), archetype_cost, count);
  BOOST_TEST(sequence_cost <= archetype_cost + 1e-9);
}

BOOST_AUTO_TEST_CASE(shipped_models_through_the_segmentation)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::Lobed_torus{}.soup(80, 64));
  for(double alpha : {0.6, 1.0})
  {
    const double gaec = shipped_model_test(m, alpha, FS::Greedy_additive_edge_contraction());
    shipped_model_test(m, alpha, FS::Kernighan_lin_with_joins());
    const double sequence = shipped_model_test(
      m, alpha, FS::Solver_sequence<FS::Greedy_additive_edge_contraction, FS::Kernighan_lin_with_joins>());
    const double best = shipped_model_test(m, alpha, FS::Default_correlation_clustering_solver());
    BOOST_TEST_MESSAGE("lobed torus, alpha " << alpha << ": cut cost GAEC " << gaec
                       << ", default " << best << ", sequence " << sequence);
    // KLj starts from GAEC's partition and only applies improving moves.
    BOOST_TEST(best <= gaec);
    // The default solver is documented as the same result as the sequence of its stages.
    BOOST_TEST(best == sequence, boost::test_tools::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_SUITE_END()
