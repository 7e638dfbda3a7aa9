// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the correlation clustering solvers on plain weighted graphs: exact optima of
// small graphs by exhaustive enumeration, instances whose solution is known by
// construction, the local optimality that each solver guarantees, GAEC against a naive
// dense implementation of its definition, and the interface contract (normalised,
// deterministic labels; parallel edges summed).

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Greedy_additive_edge_contraction.h>
#include <CGAL/Feature_segmentation/Kernighan_lin_with_joins.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef std::vector<std::size_t> Labels;

// Uniform in [lo, hi) from the raw 32-bit output, identical on every platform (the
// distributions of <random> are implementation-defined).
double uniform(std::mt19937& rng, double lo, double hi)
{
  return lo + (hi - lo) * (double(rng()) / 4294967296.0);
}

// Each pair of nodes is an edge with probability `density`, weight uniform in [-1, 1).
FS::Correlation_clustering_graph random_graph(std::size_t n, double density, std::mt19937& rng)
{
  FS::Correlation_clustering_graph g(n);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      if(uniform(rng, 0., 1.) < density)
        g.add_edge(i, j, uniform(rng, -1., 1.));
  return g;
}

FS::Correlation_clustering_graph grid_graph(std::size_t width, std::size_t height, double bias,
                                            std::mt19937& rng)
{
  FS::Correlation_clustering_graph g(width * height);
  for(std::size_t y = 0; y < height; ++y)
    for(std::size_t x = 0; x < width; ++x)
    {
      const std::size_t i = y * width + x;
      if(x + 1 < width)
        g.add_edge(i, i + 1, bias + uniform(rng, -1., 1.));
      if(y + 1 < height)
        g.add_edge(i, i + width, bias + uniform(rng, -1., 1.));
    }
  return g;
}

// Minimum cut cost over all set partitions, enumerated as restricted growth strings
// (a[0] = 0, a[i] <= 1 + max(a[0..i-1])): Bell(9) = 21147 partitions for 9 nodes.
double optimum_by_enumeration(const FS::Correlation_clustering_graph& g)
{
  const std::size_t n = g.number_of_nodes();
  if(n == 0)
    return 0.;
  Labels a(n, 0);
  std::vector<std::size_t> prefix_max(n, 0); // max of a[0..i]
  double best = FS::cut_cost(g, a);
  for(;;)
  {
    // Increment the last position that can grow, reset everything after it.
    std::size_t i = n - 1;
    while(i > 0 && a[i] == prefix_max[i - 1] + 1)
      --i;
    if(i == 0)
      break;
    ++a[i];
    prefix_max[i] = (std::max)(prefix_max[i - 1], a[i]);
    for(std::size_t j = i + 1; j < n; ++j)
    {
      a[j] = 0;
      prefix_max[j] = prefix_max[i];
    }
    best = (std::min)(best, FS::cut_cost(g, a));
  }
  return best;
}

// GAEC straight from its definition on a dense matrix of summed weights: O(n^3).
Labels naive_gaec(const FS::Correlation_clustering_graph& g)
{
  const std::size_t n = g.number_of_nodes();
  std::vector<std::vector<double> > w(n, std::vector<double>(n, 0.));
  std::vector<std::vector<bool> > adjacent(n, std::vector<bool>(n, false));
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
  {
    const std::size_t s = g.source(e), t = g.target(e);
    w[s][t] += g.weight(e);
    w[t][s] += g.weight(e);
    adjacent[s][t] = adjacent[t][s] = true;
  }
  Labels labels(n);
  for(std::size_t i = 0; i < n; ++i)
    labels[i] = i;
  std::vector<bool> alive(n, true);
  for(;;)
  {
    double best = 0.;
    std::size_t bi = n, bj = n;
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n; ++j)
        if(alive[i] && alive[j] && adjacent[i][j] && w[i][j] > best)
        {
          best = w[i][j];
          bi = i;
          bj = j;
        }
    if(bi == n)
      break;
    alive[bj] = false;
    for(std::size_t k = 0; k < n; ++k)
    {
      w[bi][k] += w[bj][k];
      w[k][bi] = w[bi][k];
      adjacent[bi][k] = adjacent[k][bi] = adjacent[bi][k] || adjacent[bj][k];
      if(labels[k] == bj)
        labels[k] = bi;
    }
  }
  FS::normalize_labels(labels);
  return labels;
}

// Sum of the weights between every pair of distinct adjacent clusters, in a canonical
// order; used to check that no join improves a solution.
std::vector<double> weights_between_clusters(const FS::Correlation_clustering_graph& g,
                                             const Labels& labels)
{
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, double> > items;
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
  {
    std::size_t a = labels[g.source(e)], b = labels[g.target(e)];
    if(a == b)
      continue;
    if(a > b)
      std::swap(a, b);
    items.push_back(std::make_pair(std::make_pair(a, b), g.weight(e)));
  }
  std::sort(items.begin(), items.end());
  std::vector<double> sums;
  for(std::size_t i = 0; i < items.size(); ++i)
  {
    if(i == 0 || items[i].first != items[i - 1].first)
      sums.push_back(0.);
    sums.back() += items[i].second;
  }
  return sums;
}

// Largest decrease of the cut cost achievable by moving one node to an adjacent cluster
// or into a cluster of its own.
double best_single_move_gain(const FS::Correlation_clustering_graph& g, const Labels& labels)
{
  const std::size_t n = g.number_of_nodes();
  std::vector<std::vector<std::pair<std::size_t, double> > > adjacency(n);
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
  {
    adjacency[g.source(e)].push_back(std::make_pair(g.target(e), g.weight(e)));
    adjacency[g.target(e)].push_back(std::make_pair(g.source(e), g.weight(e)));
  }
  double best = -std::numeric_limits<double>::infinity();
  for(std::size_t x = 0; x < n; ++x)
  {
    double internal = 0.;
    for(const auto& nw : adjacency[x])
      if(labels[nw.first] == labels[x])
        internal += nw.second;
    if(internal != 0.)
      best = (std::max)(best, -internal); // isolate x
    for(const auto& target : adjacency[x])
    {
      const std::size_t to = labels[target.first];
      if(to == labels[x])
        continue;
      double to_weight = 0.;
      for(const auto& nw : adjacency[x])
        if(labels[nw.first] == to)
          to_weight += nw.second;
      best = (std::max)(best, to_weight - internal);
    }
  }
  return best;
}

bool is_normalized(const Labels& labels, std::size_t k)
{
  std::size_t next = 0;
  for(std::size_t l : labels)
  {
    if(l > next)
      return false;
    if(l == next)
      ++next;
  }
  return next == k;
}

// An archetype of CorrelationClusteringSolver: exactly the required operator(), nothing
// else. It puts every node in its own cluster.
struct Singleton_archetype
{
  std::size_t operator()(const FS::Correlation_clustering_graph& g, Labels& labels) const
  {
    labels.resize(g.number_of_nodes());
    for(std::size_t i = 0; i < labels.size(); ++i)
      labels[i] = i;
    return labels.size();
  }
};

} // namespace

BOOST_AUTO_TEST_SUITE(correlation_clustering)

BOOST_AUTO_TEST_CASE(cut_cost_hand_example)
{
  // Path 0-1-2-3 plus chord 0-2; labels {0,1}, {2,3}: cut edges are 1-2 and 0-2.
  FS::Correlation_clustering_graph g(4);
  g.add_edge(0, 1, 1.5);
  g.add_edge(1, 2, -2.0);
  g.add_edge(2, 3, 0.25);
  g.add_edge(0, 2, 4.0);
  BOOST_TEST(FS::cut_cost(g, Labels{7, 7, 3, 3}) == -2.0 + 4.0);
  BOOST_TEST(FS::cut_cost(g, Labels{0, 0, 0, 0}) == 0.);
  BOOST_TEST(FS::cut_cost(g, Labels{0, 1, 2, 3}) == 1.5 - 2.0 + 0.25 + 4.0);
}

BOOST_AUTO_TEST_CASE(normalize_labels_first_appearance)
{
  Labels small{5, 2, 5, 9, 2, 0};
  BOOST_TEST(FS::normalize_labels(small) == 4u);
  BOOST_TEST(small == (Labels{0, 1, 0, 2, 1, 3}), boost::test_tools::per_element());

  // Label values far beyond the size go through the hash-table path.
  const std::size_t big = std::numeric_limits<std::size_t>::max();
  Labels huge{big, 3, big, big - 1, 3};
  BOOST_TEST(FS::normalize_labels(huge) == 3u);
  BOOST_TEST(huge == (Labels{0, 1, 0, 2, 1}), boost::test_tools::per_element());

  Labels empty;
  BOOST_TEST(FS::normalize_labels(empty) == 0u);
}

BOOST_AUTO_TEST_CASE(graph_construction)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges{{0, 1}, {1, 2}, {0, 1}};
  FS::Correlation_clustering_graph g(3, edges, std::vector<double>{1., -1., 0.5});
  BOOST_TEST(g.number_of_nodes() == 3u);
  BOOST_TEST(g.number_of_edges() == 3u);
  BOOST_TEST(g.source(1) == 1u);
  BOOST_TEST(g.target(1) == 2u);
  BOOST_TEST(g.weight(2) == 0.5);
  BOOST_TEST(g.add_node() == 3u);
  BOOST_TEST(g.add_edge(3, 0, 2.) == 3u);
  g.set_weight(3, -2.);
  BOOST_TEST(g.weight(3) == -2.);
}

BOOST_AUTO_TEST_CASE(two_positive_cliques_joined_by_negative_edges)
{
  // Nodes 0..4 and 5..9 form positive cliques (interleaved in index order, to make sure
  // the answer does not come from the numbering); every cross pair is negative.
  const std::vector<std::size_t> side{0, 1, 0, 1, 1, 0, 0, 1, 1, 0};
  FS::Correlation_clustering_graph g(10);
  for(std::size_t i = 0; i < 10; ++i)
    for(std::size_t j = i + 1; j < 10; ++j)
      g.add_edge(i, j, side[i] == side[j] ? 1.0 : -0.5);
  const double expected_cost = -0.5 * 25;

  auto check = [&](const Labels& labels, std::size_t k) {
    BOOST_TEST(k == 2u);
    BOOST_TEST(labels == side, boost::test_tools::per_element());
    BOOST_TEST(FS::cut_cost(g, labels) == expected_cost, boost::test_tools::tolerance(1e-12));
  };
  Labels labels;
  check(labels, FS::Greedy_additive_edge_contraction()(g, labels));
  labels.clear();
  check(labels, FS::Kernighan_lin_with_joins()(g, labels));
  labels.clear();
  check(labels, FS::Default_correlation_clustering_solver()(g, labels));
  labels.assign(10, 0); // KLj must split an all-in-one start as well
  check(labels, FS::Kernighan_lin_with_joins()(g, labels));
}

BOOST_AUTO_TEST_CASE(trivial_graphs)
{
  std::mt19937 rng(7);
  // A connected graph with only positive weights: one cluster, nothing cut.
  FS::Correlation_clustering_graph positive = grid_graph(12, 9, 2.0, rng);
  // Only negative weights: every node alone.
  FS::Correlation_clustering_graph negative = grid_graph(12, 9, -2.0, rng);
  FS::Correlation_clustering_graph no_edges(17);
  FS::Correlation_clustering_graph empty;

  auto run_all = [](const FS::Correlation_clustering_graph& g, std::size_t expected_k) {
    Labels labels;
    BOOST_TEST(FS::Greedy_additive_edge_contraction()(g, labels) == expected_k);
    BOOST_TEST(labels.size() == g.number_of_nodes());
    labels.clear();
    BOOST_TEST(FS::Kernighan_lin_with_joins()(g, labels) == expected_k);
    BOOST_TEST(labels.size() == g.number_of_nodes());
    labels.clear();
    BOOST_TEST(FS::Default_correlation_clustering_solver()(g, labels) == expected_k);
    BOOST_TEST(labels.size() == g.number_of_nodes());
    return labels;
  };
  BOOST_TEST(run_all(positive, 1) == Labels(positive.number_of_nodes(), 0),
             boost::test_tools::per_element());
  Labels identity(negative.number_of_nodes());
  for(std::size_t i = 0; i < identity.size(); ++i)
    identity[i] = i;
  BOOST_TEST(run_all(negative, negative.number_of_nodes()) == identity,
             boost::test_tools::per_element());
  run_all(no_edges, 17);
  run_all(empty, 0);

  // KLj must also break an all-in-one start on the all-negative graph.
  Labels labels(negative.number_of_nodes(), 3);
  BOOST_TEST(FS::Kernighan_lin_with_joins()(negative, labels) == negative.number_of_nodes());
}

BOOST_AUTO_TEST_CASE(parallel_edges_are_summed)
{
  // +1 and -3 between nodes 0 and 1: together -2, so they must be separated, although
  // the first edge alone would be contracted by GAEC.
  FS::Correlation_clustering_graph g(3);
  g.add_edge(0, 1, 1.0);
  g.add_edge(1, 0, -3.0);
  g.add_edge(1, 2, 0.5);
  Labels labels;
  BOOST_TEST(FS::Greedy_additive_edge_contraction()(g, labels) == 2u);
  BOOST_TEST(labels == (Labels{0, 1, 1}), boost::test_tools::per_element());
  labels.clear();
  BOOST_TEST(FS::Kernighan_lin_with_joins()(g, labels) == 2u);
  BOOST_TEST(labels == (Labels{0, 1, 1}), boost::test_tools::per_element());
  labels.clear();
  BOOST_TEST(FS::Default_correlation_clustering_solver()(g, labels) == 2u);
  BOOST_TEST(labels == (Labels{0, 1, 1}), boost::test_tools::per_element());
  BOOST_TEST(FS::cut_cost(g, labels) == -2.0);
}

BOOST_AUTO_TEST_CASE(gaec_matches_naive_definition)
{
  // With continuous random weights there are no ties, so the partition is unique.
  std::mt19937 rng(2024);
  for(int instance = 0; instance < 60; ++instance)
  {
    const std::size_t n = 5 + rng() % 60;
    const double density = uniform(rng, 0.05, 0.6);
    const FS::Correlation_clustering_graph g = random_graph(n, density, rng);
    Labels labels;
    FS::Greedy_additive_edge_contraction()(g, labels);
    BOOST_TEST(labels == naive_gaec(g), boost::test_tools::per_element());
  }
  for(int instance = 0; instance < 10; ++instance)
  {
    const FS::Correlation_clustering_graph g = grid_graph(15, 11, uniform(rng, -0.5, 1.), rng);
    Labels labels;
    FS::Greedy_additive_edge_contraction()(g, labels);
    BOOST_TEST(labels == naive_gaec(g), boost::test_tools::per_element());
  }
}

BOOST_AUTO_TEST_CASE(local_optimality_on_grids)
{
  // GAEC stops when no positive edge is left in the contracted graph: the summed weight
  // between any two adjacent clusters is <= 0. KLj, once converged, additionally admits
  // no single-node move and no join that decreases the cut cost by more than epsilon.
  std::mt19937 rng(99);
  for(int instance = 0; instance < 6; ++instance)
  {
    const FS::Correlation_clustering_graph g = grid_graph(60, 45, 0.25 * instance - 0.5, rng);
    Labels gaec;
    FS::Greedy_additive_edge_contraction()(g, gaec);
    for(double w : weights_between_clusters(g, gaec))
      BOOST_TEST(w <= 0.);

    // The guarantees hold however early move sequences stop (the first move of a
    // sequence is the best single move), so check the shortest setting too.
    for(std::size_t patience : {std::size_t(100), std::size_t(1)})
    {
      Labels klj = gaec;
      FS::Kernighan_lin_with_joins(100, 1e-9, patience)(g, klj);
      for(double w : weights_between_clusters(g, klj))
        BOOST_TEST(w <= 1e-7);
      BOOST_TEST(best_single_move_gain(g, klj) <= 1e-7);
      BOOST_TEST(FS::cut_cost(g, klj) <= FS::cut_cost(g, gaec) + 1e-9);
    }
  }
}

BOOST_AUTO_TEST_CASE(optimum_by_enumeration_on_small_graphs)
{
  const int number_of_instances = 1000;
  int gaec_optimal = 0, sequence_optimal = 0;
  double gaec_worst_gap = 0., sequence_worst_gap = 0.;
  for(int instance = 0; instance < number_of_instances; ++instance)
  {
    std::mt19937 rng(instance); // one seed per instance, to reproduce any one alone
    const std::size_t n = 2 + instance % 8; // 2..9 nodes, evenly
    const double density = uniform(rng, 0.2, 1.0);
    const FS::Correlation_clustering_graph g = random_graph(n, density, rng);
    const double optimum = optimum_by_enumeration(g);

    Labels gaec;
    FS::Greedy_additive_edge_contraction()(g, gaec);
    Labels sequence = gaec;
    FS::Kernighan_lin_with_joins()(g, sequence);
    Labels defaults;
    FS::Default_correlation_clustering_solver()(g, defaults);
    BOOST_TEST(defaults == sequence, boost::test_tools::per_element());

    const double gaec_cost = FS::cut_cost(g, gaec);
    const double sequence_cost = FS::cut_cost(g, sequence);
    BOOST_TEST(gaec_cost >= optimum - 1e-9);
    BOOST_TEST(sequence_cost >= optimum - 1e-9);
    BOOST_TEST(sequence_cost <= gaec_cost + 1e-9);

    // KLj never worsens its input, whatever the input.
    Labels singletons;
    FS::Kernighan_lin_with_joins()(g, singletons);
    Labels identity(n);
    for(std::size_t i = 0; i < n; ++i)
      identity[i] = i;
    BOOST_TEST(FS::cut_cost(g, singletons) <= FS::cut_cost(g, identity) + 1e-9);
    Labels one(n, 42);
    FS::Kernighan_lin_with_joins()(g, one);
    BOOST_TEST(FS::cut_cost(g, one) <= 0. + 1e-9);
    Labels random_start(n);
    for(std::size_t i = 0; i < n; ++i)
      random_start[i] = 1000 + rng() % 3;
    const double random_cost = FS::cut_cost(g, random_start);
    FS::Kernighan_lin_with_joins()(g, random_start);
    BOOST_TEST(FS::cut_cost(g, random_start) <= random_cost + 1e-9);

    // The optimum is <= 0 (one cluster costs 0), and both solvers return a cost <= 0
    // (GAEC leaves only non-positive summed weights between clusters), so a miss implies
    // optimum < 0 and the relative gap (cost - optimum) / |optimum| is well defined.
    if(gaec_cost <= optimum + 1e-9)
      ++gaec_optimal;
    else
      gaec_worst_gap = (std::max)(gaec_worst_gap, (gaec_cost - optimum) / -optimum);
    if(sequence_cost <= optimum + 1e-9)
      ++sequence_optimal;
    else
      sequence_worst_gap = (std::max)(sequence_worst_gap, (sequence_cost - optimum) / -optimum);
  }
  const double gaec_rate = double(gaec_optimal) / number_of_instances;
  const double sequence_rate = double(sequence_optimal) / number_of_instances;
  BOOST_TEST_MESSAGE("enumeration: " << number_of_instances << " graphs with 2..9 nodes; "
                     << "GAEC optimal in " << 100. * gaec_rate << "% (worst gap "
                     << 100. * gaec_worst_gap << "% of |optimum|), GAEC+KLj optimal in "
                     << 100. * sequence_rate << "% (worst gap " << 100. * sequence_worst_gap
                     << "% of |optimum|)");
  // Measured when this test was written: GAEC 92.7%, GAEC+KLj 95.9% (worst gap 29.8%).
  // The misses of GAEC+KLj are genuine local optima of pairwise moves: reaching the
  // optimum would need one node to leave a cluster and another to join a third cluster
  // at the same time.
  BOOST_TEST(gaec_rate >= 0.88);
  BOOST_TEST(sequence_rate >= 0.92);
  BOOST_TEST(sequence_rate >= gaec_rate);
  BOOST_TEST(sequence_worst_gap <= 0.45);
}

BOOST_AUTO_TEST_CASE(deterministic_and_normalized)
{
  std::mt19937 rng(5);
  const FS::Correlation_clustering_graph g = grid_graph(40, 30, 0., rng);
  Labels first, second;
  const std::size_t k1 = FS::Default_correlation_clustering_solver()(g, first);
  const std::size_t k2 = FS::Default_correlation_clustering_solver()(g, second);
  BOOST_TEST(k1 == k2);
  BOOST_TEST(first == second, boost::test_tools::per_element());
  BOOST_TEST(is_normalized(first, k1));

  // The shared-adjacency default solver is exactly the generic sequence.
  Labels generic;
  FS::Solver_sequence<FS::Greedy_additive_edge_contraction, FS::Kernighan_lin_with_joins>()(g, generic);
  BOOST_TEST(generic == first, boost::test_tools::per_element());

  // Any initial label values; the output is normalised whatever they were.
  Labels start(g.number_of_nodes());
  for(std::size_t i = 0; i < start.size(); ++i)
    start[i] = 1000000007u * (i % 5);
  const std::size_t k = FS::Kernighan_lin_with_joins()(g, start);
  BOOST_TEST(is_normalized(start, k));
}

BOOST_AUTO_TEST_CASE(archetype_in_solver_sequence)
{
  // Solver_sequence uses nothing but the concept's operator().
  std::mt19937 rng(11);
  const FS::Correlation_clustering_graph g = grid_graph(20, 20, 0., rng);
  Labels from_archetype;
  const std::size_t k =
    FS::Solver_sequence<Singleton_archetype, FS::Kernighan_lin_with_joins>()(g, from_archetype);
  Labels from_singletons;
  BOOST_TEST(FS::Kernighan_lin_with_joins()(g, from_singletons) == k);
  BOOST_TEST(from_archetype == from_singletons, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()
