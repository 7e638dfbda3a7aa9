// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the correlation clustering solvers on plain weighted graphs: instances whose
// solution is known by construction, the local optimality that each solver guarantees,
// and the interface contract (normalised, deterministic labels; parallel edges summed;
// Solver_sequence with an archetype of the concept). The references (enumeration, naive
// GAEC) are in test_correlation_clustering.cpp.

#include "correlation_clustering_graphs.h"

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Greedy_additive_edge_contraction.h>
#include <CGAL/Feature_segmentation/Kernighan_lin_with_joins.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>

#include <boost/test/unit_test.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

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

using fs_cc_test::Labels;
using fs_cc_test::grid_graph;

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

BOOST_AUTO_TEST_SUITE(correlation_clustering_solvers)

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

#ifdef CGAL_LINKED_WITH_TBB
// Kernighan-Lin with its rounds' pairs on TBB's threads gives the labels of one thread,
// at 1, 2 and 8 threads: on grids of 4,800 nodes (hundreds of pairs per round, enough
// for the threads) with every bias, from GAEC's partition and from singletons.
BOOST_AUTO_TEST_CASE(parallel_kernighan_lin_equals_the_serial_one)
{
  std::mt19937 rng(20261127u);
  for(int instance = 0; instance < 5; ++instance)
  {
    const FS::Correlation_clustering_graph g = grid_graph(80, 60, 0.25 * instance - 0.5, rng);
    for(bool from_gaec : {true, false})
    {
      Labels start;
      if(from_gaec) FS::Greedy_additive_edge_contraction()(g, start);
      FS::Kernighan_lin_with_joins serial;
      Labels expected = start;
      serial(g, expected);
      FS::Kernighan_lin_with_joins parallel;
      parallel.set_parallel(true);
      for(int threads : {1, 2, 8})
      {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        Labels labels = start;
        parallel(g, labels);
        BOOST_TEST((labels == expected), "instance " << instance << (from_gaec ? " from GAEC, " : " from singletons, ")
                                                     << threads << " threads");
      }
      FS::Default_correlation_clustering_solver both;
      both.second().set_parallel(true);
      Labels labels;
      both(g, labels);
      Labels reference;
      FS::Default_correlation_clustering_solver()(g, reference);
      BOOST_TEST((labels == reference), "instance " << instance << ", the default solver");
    }
  }
}
#endif

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
