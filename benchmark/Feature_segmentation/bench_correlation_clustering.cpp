// SPDX-License-Identifier: GPL-3.0-or-later
//
// Timing and cut cost of the correlation clustering solvers on 4-connected grid graphs
// with i.i.d. weights uniform in [-1, 1): the standard synthetic workload for these
// solvers (half of the edges attract, half repel, so GAEC leaves tens of thousands of
// clusters for KLj to refine). Prints a table and writes CSV for the manual.
//
// --bias b shifts all weights by b: with b = 0.5, one cluster covers most of the grid,
// the workload of a mesh with large smooth patches.
//
// Usage: bench_correlation_clustering [--sizes 500x400,1000x1000] [--seeds 1,2]
//          [--bias 0] [--repeat 3] [--singletons] [--csv bench_correlation_clustering.csv]

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Greedy_additive_edge_contraction.h>
#include <CGAL/Feature_segmentation/Kernighan_lin_with_joins.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.h"

namespace FS = CGAL::Feature_segmentation;

namespace {

using fs_bench::cpu_name;
using fs_bench::fastest;
using fs_bench::refine_to_faces;
using fs_bench::seconds_since;

struct Options
{
  std::vector<std::pair<std::size_t, std::size_t> > sizes{{500, 400}, {1000, 1000}};
  std::vector<unsigned> seeds{1};
  std::size_t repeat = 3;
  double bias = 0.;
  bool singletons = false;
  std::string csv = "bench_correlation_clustering.csv";
};

struct Row
{
  std::string grid;
  std::size_t nodes, edges;
  unsigned seed;
  std::string solver;
  double min_seconds, median_seconds, objective;
  std::size_t clusters;
};

std::vector<std::string> split(const std::string& s, char separator)
{
  std::vector<std::string> parts;
  std::stringstream stream(s);
  std::string part;
  while(std::getline(stream, part, separator))
    parts.push_back(part);
  return parts;
}

bool parse_options(int argc, char** argv, Options& options)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if(arg == "--sizes" && has_value)
    {
      options.sizes.clear();
      for(const std::string& size : split(argv[++i], ','))
      {
        const std::vector<std::string> wh = split(size, 'x');
        if(wh.size() != 2 || std::atol(wh[0].c_str()) <= 0 || std::atol(wh[1].c_str()) <= 0)
          return false;
        options.sizes.emplace_back(std::size_t(std::atol(wh[0].c_str())),
                                   std::size_t(std::atol(wh[1].c_str())));
      }
    }
    else if(arg == "--seeds" && has_value)
    {
      options.seeds.clear();
      for(const std::string& seed : split(argv[++i], ','))
        options.seeds.push_back(unsigned(std::strtoul(seed.c_str(), nullptr, 10)));
    }
    else if(arg == "--repeat" && has_value)
      options.repeat = std::max<std::size_t>(1, std::size_t(std::atol(argv[++i])));
    else if(arg == "--bias" && has_value)
      options.bias = std::atof(argv[++i]);
    else if(arg == "--csv" && has_value)
      options.csv = argv[++i];
    else if(arg == "--singletons")
      options.singletons = true;
    else
      return false;
  }
  return !options.sizes.empty() && !options.seeds.empty();
}

// Weights from the raw 32-bit Mersenne Twister output, so that every platform builds the
// same graph (std::uniform_real_distribution is implementation-defined).
FS::Correlation_clustering_graph grid_graph(std::size_t width, std::size_t height, unsigned seed,
                                            double bias)
{
  std::mt19937 rng(seed);
  auto weight = [&rng, bias]() { return bias - 1. + 2. * (double(rng()) / 4294967296.0); };
  FS::Correlation_clustering_graph g(width * height);
  g.reserve_edges(2 * width * height);
  for(std::size_t y = 0; y < height; ++y)
    for(std::size_t x = 0; x < width; ++x)
    {
      const std::size_t i = y * width + x;
      if(x + 1 < width)
        g.add_edge(i, i + 1, weight());
      if(y + 1 < height)
        g.add_edge(i, i + width, weight());
    }
  return g;
}


// Runs `solve` on a fresh copy of `initial` `repeat` times; returns the timings sorted
// and leaves the labels of the last run in `labels`.
std::vector<double> time_solver(const std::function<std::size_t(std::vector<std::size_t>&)>& solve,
                                const std::vector<std::size_t>& initial, std::size_t repeat,
                                std::vector<std::size_t>& labels, std::size_t& clusters)
{
  std::vector<double> seconds;
  for(std::size_t r = 0; r < repeat; ++r)
  {
    labels = initial;
    const auto start = std::chrono::steady_clock::now();
    clusters = solve(labels);
    const auto stop = std::chrono::steady_clock::now();
    seconds.push_back(std::chrono::duration<double>(stop - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds;
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  if(!parse_options(argc, argv, options))
  {
    std::cerr << "usage: " << argv[0]
              << " [--sizes WxH[,WxH...]] [--seeds S[,S...]] [--bias B] [--repeat R] [--singletons]"
                 " [--csv FILE]\n";
    return 1;
  }

  const std::string cpu = cpu_name();
  std::cout << "CPU: " << cpu << "\n"
            << "Weights: uniform in [" << options.bias - 1. << ", " << options.bias + 1.
            << ").\nTimes: wall clock of one thread, min and median of " << options.repeat
            << " runs; objective = cut cost (Eq. 1), lower is better.\n"
            << "KLj (from GAEC) times the second stage alone, starting from GAEC's labels.\n\n";

  std::vector<Row> rows;
  char line[256];
  std::snprintf(line, sizeof(line), "%-10s %9s %9s %5s  %-18s %9s %9s %15s %9s\n", "grid",
                "nodes", "edges", "seed", "solver", "min s", "median s", "objective",
                "clusters");
  std::cout << line;

  for(const auto& size : options.sizes)
    for(unsigned seed : options.seeds)
    {
      const FS::Correlation_clustering_graph g = grid_graph(size.first, size.second, seed, options.bias);
      const std::string grid = std::to_string(size.first) + "x" + std::to_string(size.second);

      std::vector<std::size_t> gaec_labels, labels;
      std::size_t clusters = 0;
      auto record = [&](const std::string& solver, const std::vector<double>& seconds) {
        Row row{grid, g.number_of_nodes(), g.number_of_edges(), seed, solver, seconds.front(),
                seconds[seconds.size() / 2], FS::cut_cost(g, labels), clusters};
        std::snprintf(line, sizeof(line), "%-10s %9zu %9zu %5u  %-18s %9.3f %9.3f %15.3f %9zu\n",
                      row.grid.c_str(), row.nodes, row.edges, row.seed, row.solver.c_str(),
                      row.min_seconds, row.median_seconds, row.objective, row.clusters);
        std::cout << line << std::flush;
        rows.push_back(row);
      };

      const FS::Greedy_additive_edge_contraction gaec;
      const FS::Kernighan_lin_with_joins klj;
      const FS::Default_correlation_clustering_solver both;
      const std::vector<std::size_t> none;

      record("GAEC", time_solver([&](std::vector<std::size_t>& l) { return gaec(g, l); },
                                 none, options.repeat, labels, clusters));
      gaec_labels = labels;
      record("KLj (from GAEC)", time_solver([&](std::vector<std::size_t>& l) { return klj(g, l); },
                                            gaec_labels, options.repeat, labels, clusters));
      record("GAEC+KLj", time_solver([&](std::vector<std::size_t>& l) { return both(g, l); },
                                     none, options.repeat, labels, clusters));
      if(options.singletons)
        record("KLj (singletons)",
               time_solver([&](std::vector<std::size_t>& l) { return klj(g, l); }, none,
                           options.repeat, labels, clusters));
    }

  std::ofstream csv(options.csv);
  if(!csv)
  {
    std::cerr << "error: cannot write " << options.csv << "\n";
    return 1;
  }
  csv << "grid,bias,nodes,edges,seed,solver,min_seconds,median_seconds,objective,clusters,cpu\n";
  csv.precision(10);
  for(const Row& row : rows)
    csv << row.grid << ',' << options.bias << ',' << row.nodes << ',' << row.edges << ',' << row.seed << ','
        << row.solver << ',' << row.min_seconds << ',' << row.median_seconds << ','
        << row.objective << ',' << row.clusters << ",\"" << cpu << "\"\n";
  csv.close();
  fs_bench::write_provenance(options.csv, argc, argv);
  std::cout << "\nwrote " << options.csv << "\n";
  return 0;
}
