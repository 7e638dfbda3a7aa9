// The small patches of rough meshes (small_patches.h): join_small_patches() on a graph
// of six oversegments whose joins are worked out by hand (the costliest neighbour last,
// a patch that a join leaves small joining again, ties to the smaller id, a patch without
// neighbours staying), and through the class with a solver that cuts out a connected set
// of vertices: three vertices join the rest on a noisy box, not on a clean one, and
// twelve (above small_patch_max_vertices) stay a patch on both.
#include <boost/test/unit_test.hpp>

#include "crease_meshes.h"

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/internal/small_patches.h>

#include <deque>
#include <vector>

BOOST_AUTO_TEST_SUITE(small_patches)

namespace I = FS::internal;

// A reduced graph from (segment, segment, weights of its cross edges) triples; the
// cross edges are numbered in order, their weights listed in `weight`.
struct Graph
{
  I::Reduced_graph rg;
  std::vector<double> weight;

  Graph(std::size_t segments, const std::vector<std::tuple<std::size_t, std::size_t, std::vector<double> > >& edges)
  {
    rg.number_of_nodes = segments;
    rg.cross_begin.push_back(0);
    for(const auto& [a, b, w] : edges)
    {
      rg.edges.push_back({ a, b });
      for(double x : w)
      {
        rg.cross.push_back(weight.size());
        weight.push_back(x);
      }
      rg.cross_begin.push_back(rg.cross.size());
    }
  }

  std::vector<std::size_t> join(std::vector<std::size_t> patch, const std::vector<std::size_t>& size,
                                std::size_t max_vertices = I::small_patch_max_vertices) const
  {
    I::join_small_patches(rg, size, [this](std::size_t e) { return weight[e]; }, max_vertices, patch);
    return patch;
  }
};

BOOST_AUTO_TEST_CASE(small_patches_join_the_cheapest_neighbour)
{
  // Segments 0 and 1 are patch 0 (50 vertices), 2 patch 1 (40), 3 patch 2 (3), 4 patch 3
  // (4), 5 patch 4 (2, no edge). Patch 4 is the smallest but has no neighbour: it stays.
  // Patch 2 borders patch 0 by -0.6 - 0.4 = -1, patch 1 by -0.5 and patch 3 by -0.2: it
  // joins patch 3 (the join that raises the cut cost least), which then holds 7
  // vertices and borders patch 0 by -2 (its own edge) - 1 (patch 2's) = -3 and patch 1
  // by -0.5: it joins patch 1.
  const Graph g(6, { { 0, 1, { 5. } },
                     { 3, 0, { -0.6, -0.4 } },
                     { 3, 2, { -0.5 } },
                     { 4, 3, { -0.2 } },
                     { 4, 1, { -2. } } });
  const std::vector<std::size_t> patch = { 0, 0, 1, 2, 3, 4 }, size = { 30, 20, 40, 3, 4, 2 };
  BOOST_TEST(g.join(patch, size) == std::vector<std::size_t>({ 0, 0, 1, 1, 1, 4 }), boost::test_tools::per_element());
  // with at most 3 vertices, only patch 2 joins (patch 3, then of 7, is not small)
  BOOST_TEST(g.join(patch, size, 3) == std::vector<std::size_t>({ 0, 0, 1, 3, 3, 4 }),
             boost::test_tools::per_element());
  // nothing is small: unchanged
  BOOST_TEST(g.join(patch, size, 1) == patch, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(equal_neighbours_go_to_the_smaller_id)
{
  // patch 1 (one segment of 5 vertices) borders patches 2 and 0 by -1 each: it joins 0;
  // two large patches bordering each other stay apart however they are weighted
  const Graph g(4, { { 1, 2, { -1. } }, { 1, 0, { -0.25, -0.75 } }, { 0, 2, { 3. } }, { 2, 3, { -4. } } });
  BOOST_TEST(g.join({ 0, 1, 2, 3 }, { 20, 5, 20, 20 }) == std::vector<std::size_t>({ 0, 0, 2, 3 }),
             boost::test_tools::per_element());
}

// A solver that puts `count` nodes found breadth-first from node 0 into patch 1 and the
// others into patch 0 (a connected piece, whatever the weights).
struct Cut_out_a_piece
{
  std::size_t count;

  std::size_t operator()(const FS::Correlation_clustering_graph& g, std::vector<std::size_t>& labels) const
  {
    std::vector<std::vector<std::size_t> > next(g.number_of_nodes());
    for(std::size_t e = 0; e < g.number_of_edges(); ++e)
    {
      next[g.source(e)].push_back(g.target(e));
      next[g.target(e)].push_back(g.source(e));
    }
    labels.assign(g.number_of_nodes(), 0);
    std::deque<std::size_t> queue = { 0 };
    labels[0] = 1;
    std::size_t taken = 1;
    while(!queue.empty() && taken < count)
    {
      const std::size_t n = queue.front();
      queue.pop_front();
      for(std::size_t m : next[n])
        if(labels[m] == 0 && taken < count) { labels[m] = 1; ++taken; queue.push_back(m); }
    }
    return FS::normalize_labels(labels);
  }
};

BOOST_AUTO_TEST_CASE(noise_pieces_of_a_few_vertices_join_on_rough_meshes_only)
{
  std::vector<int> side;
  const SM noisy = fs_test::to_mesh<SM>(fs_test::noisy_box(0.015, 12, side));
  const SM clean = fs_test::to_mesh<SM>(fs_test::box(1., 1., 1., 12, side));
  // vertices are the nodes of the solve without the oversegmentation
  const auto patches = [](const SM& m, std::size_t count) {
    const FS::Feature_aligned_segmentation<SM> seg(
      m, FS::parameters::use_oversegmentation(false).solver(Cut_out_a_piece{ count }));
    return seg.number_of_patches();
  };
  BOOST_TEST(patches(noisy, 3) == 1u);
  BOOST_TEST(patches(clean, 3) == 2u);
  BOOST_TEST(patches(noisy, I::small_patch_max_vertices + 2) == 2u);
  BOOST_TEST(patches(clean, I::small_patch_max_vertices + 2) == 2u);
}

BOOST_AUTO_TEST_SUITE_END()
