// The clusters grown breadth first (internal/breadth_first_clusters.h), which the
// curvature fits and the crease gap search both walk: on small graphs whose clusters
// can be listed by hand.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/breadth_first_clusters.h>
#include <CGAL/Feature_segmentation/internal/vertex_clusters.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace FSI = CGAL::Feature_segmentation::internal;

namespace {

// A graph as lists of neighbours.
typedef std::vector<std::vector<std::uint32_t> > Graph;

FSI::Breadth_first_clusters grow(const Graph& g, std::size_t size)
{
  FSI::Breadth_first_clusters c;
  c.grow(g.size(), size, [&](std::uint32_t x, const auto& visit) {
    for(std::uint32_t y : g[x]) visit(y);
  });
  return c;
}

} // namespace

BOOST_AUTO_TEST_SUITE(breadth_first_clusters)

// A path 0-1-...-9 in clusters of 4: {0,1,2,3}, {4,5,6,7}, {8,9}.
BOOST_AUTO_TEST_CASE(a_path_in_fours)
{
  Graph g(10);
  for(std::uint32_t i = 0; i + 1 < 10; ++i) { g[i].push_back(i + 1); g[i + 1].push_back(i); }
  const FSI::Breadth_first_clusters c = grow(g, 4);
  BOOST_TEST(c.size() == 3u);
  BOOST_TEST((c.cluster_of == std::vector<std::uint32_t>{ 0, 0, 0, 0, 1, 1, 1, 1, 2, 2 }));
  BOOST_TEST((c.first == std::vector<std::uint32_t>{ 0, 4, 8, 10 }));
  BOOST_TEST(c.seed(0) == 0u);
  BOOST_TEST(c.seed(1) == 4u);
  BOOST_TEST(c.seed(2) == 8u);
}

// A 3x3 grid (node 3r+c), neighbours listed right, down, left, up, in clusters of 4:
// from 0 breadth first 0, 1, 3, then 2 (1's right); from 4: 4, 5, 7, then 8; 6 alone.
// Border sides given as `none` are skipped.
BOOST_AUTO_TEST_CASE(a_grid_breadth_first)
{
  const std::uint32_t none = FSI::Breadth_first_clusters::none;
  Graph g(9);
  for(std::uint32_t r = 0; r < 3; ++r)
    for(std::uint32_t c = 0; c < 3; ++c)
    {
      std::vector<std::uint32_t>& n = g[3 * r + c];
      n.push_back(c + 1 < 3 ? 3 * r + c + 1 : none);
      n.push_back(r + 1 < 3 ? 3 * (r + 1) + c : none);
      n.push_back(c > 0 ? 3 * r + c - 1 : none);
      n.push_back(r > 0 ? 3 * (r - 1) + c : none);
    }
  const FSI::Breadth_first_clusters c = grow(g, 4);
  BOOST_TEST((c.cluster_of == std::vector<std::uint32_t>{ 0, 0, 0, 0, 1, 1, 2, 1, 1 }));
  BOOST_TEST((c.order == std::vector<std::uint32_t>{ 0, 1, 3, 2, 4, 5, 7, 8, 6 }));
  BOOST_TEST(c.size() == 3u);
}

// Vertex_clusters over the same path (CSR): the clusters above, each one's seed, and
// the clusters next to each.
BOOST_AUTO_TEST_CASE(vertex_clusters_of_a_path)
{
  std::vector<std::size_t> begin{ 0 }, adj;
  for(std::size_t i = 0; i < 10; ++i)
  {
    if(i > 0) adj.push_back(i - 1);
    if(i + 1 < 10) adj.push_back(i + 1);
    begin.push_back(adj.size());
  }
  FSI::Vertex_clusters v;
  v.build(begin, adj, 4);
  BOOST_TEST(v.size() == 3u);
  BOOST_TEST((v.representative == std::vector<std::size_t>{ 0, 4, 8 }));
  BOOST_TEST((v.neighbour_begin == std::vector<std::size_t>{ 0, 1, 3, 4 }));
  BOOST_TEST((v.neighbours == std::vector<std::uint32_t>{ 1, 0, 2, 1 }));
}

BOOST_AUTO_TEST_SUITE_END()
