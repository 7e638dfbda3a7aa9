// SPDX-License-Identifier: GPL-3.0-or-later
//
// Random weighted graphs shared by the tests of the correlation clustering solvers
// (test_correlation_clustering.cpp, test_correlation_clustering_solvers.cpp).
#ifndef FS_TEST_CORRELATION_CLUSTERING_GRAPHS_H
#define FS_TEST_CORRELATION_CLUSTERING_GRAPHS_H

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>

#include <cstddef>
#include <random>
#include <vector>

namespace fs_cc_test {

namespace FS = CGAL::Feature_segmentation;

typedef std::vector<std::size_t> Labels;

// Uniform in [lo, hi) from the raw 32-bit output, identical on every platform (the
// distributions of <random> are implementation-defined).
inline double uniform(std::mt19937& rng, double lo, double hi)
{
  return lo + (hi - lo) * (double(rng()) / 4294967296.0);
}

// Each pair of nodes is an edge with probability `density`, weight uniform in [-1, 1).
inline FS::Correlation_clustering_graph random_graph(std::size_t n, double density,
                                                     std::mt19937& rng)
{
  FS::Correlation_clustering_graph g(n);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      if(uniform(rng, 0., 1.) < density)
        g.add_edge(i, j, uniform(rng, -1., 1.));
  return g;
}

inline FS::Correlation_clustering_graph grid_graph(std::size_t width, std::size_t height, double bias,
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

} // namespace fs_cc_test

#endif // FS_TEST_CORRELATION_CLUSTERING_GRAPHS_H
