// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the correlation clustering graph and of the solvers against references on
// plain weighted graphs: the cut cost and the label normalisation by hand, the graph's
// construction, GAEC against a naive dense implementation of its definition, and exact
// optima of small graphs by exhaustive enumeration. The solvers' guarantees and interface
// contract are in test_correlation_clustering_solvers.cpp.

#include "correlation_clustering_graphs.h"

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

using fs_cc_test::Labels;
using fs_cc_test::uniform;
using fs_cc_test::random_graph;
using fs_cc_test::grid_graph;

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

BOOST_AUTO_TEST_SUITE_END()
