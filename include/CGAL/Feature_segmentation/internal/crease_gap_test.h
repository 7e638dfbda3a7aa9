// SPDX-License-Identifier: GPL-3.0-or-later
// The gap test of the crease candidates (crease_detection.h): a crease of a CAD tessellation
// stands alone, a strong bend of a smooth surface comes with slightly weaker ones.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_TEST_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_TEST_H

#include <CGAL/Feature_segmentation/internal/crease_gap_search.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The gap test's lengths for every edge of `candidates` (by TBB's threads if
// `parallel`, with the same result at any count); `max_levels` and `by_direction` as
// Crease_gap_search's; the search of candidate i ends once `stop_of(i)` holds for its
// lengths so far.
template <typename TriangleMesh, typename StopOf>
std::vector<Gap_lengths> crease_gap_lengths(const Mesh_indexing<TriangleMesh>& idx, Edge_geometry geometry,
                                            const std::vector<double>& angle, const std::vector<double>& band_angle,
                                            double crease_angle, const std::vector<std::size_t>& candidates,
                                            bool parallel, int max_levels, bool by_direction, const StopOf& stop_of)
{
  std::vector<Gap_lengths> out(candidates.size());
  if(candidates.empty()) return out;
  typedef Crease_gap_search<TriangleMesh> Search;
  const Search search(idx, std::move(geometry), angle, band_angle, crease_angle, max_levels, by_direction);
  auto run = [&](std::size_t first, std::size_t last, typename Search::Work_space& ws) {
    for(std::size_t i = first; i < last; ++i) out[i] = search.lengths(candidates[i], i, ws, stop_of(i));
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::enumerable_thread_specific<typename Search::Work_space> spaces;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& b) { run(b.begin(), b.end(), spaces.local()); });
  }
  else
#endif
  {
    (void)parallel;
    typename Search::Work_space ws;
    run(0, candidates.size(), ws);
  }
  return out;
}

// The same, every search to its end.
template <typename TriangleMesh>
std::vector<Gap_lengths> crease_gap_lengths(const Mesh_indexing<TriangleMesh>& idx, Edge_geometry geometry,
                                            const std::vector<double>& angle, const std::vector<double>& band_angle,
                                            double crease_angle, const std::vector<std::size_t>& candidates,
                                            bool parallel = false, int max_levels = 8, bool by_direction = true)
{
  return crease_gap_lengths(idx, std::move(geometry), angle, band_angle, crease_angle, candidates, parallel, max_levels,
                            by_direction, [](std::size_t) { return [](const Gap_lengths&) { return false; }; });
}

// The crease and band edges of the gap test in a bounding volume hierarchy whose nodes
// hold their edges' sums: the crease length, the band length and the band's direction
// tensor (Band_tensor). A ball query (lengths()) adds a node whole when its box lies
// inside the ball, and also each leaf (at most leaf_size edges) that the ball's sphere
// crosses: it bounds the lengths within the ball from above, never below, and its cost
// grows with the ball's surface, not with the edges inside: a noisy fine mesh, a third
// of whose edges are candidates, has thousands of them in every ball.
class Gap_edge_hierarchy
{
public:
  static constexpr std::size_t leaf_size = 8;

  // the edges of `g` that bend by crease_angle or more, or are band edges
  Gap_edge_hierarchy(const Edge_geometry& g, const std::vector<double>& angle, const std::vector<double>& band_angle,
                     double crease_angle)
  {
    std::vector<Item> items;
    for(std::size_t e = 0; e < g.ends.size(); ++e)
    {
      const bool crease = angle[e] >= crease_angle;
      if(!crease && !is_crease_gap_band_edge(angle[e], band_angle[e], crease_angle)) continue;
      items.push_back(Item{ g.ends[e][0], g.ends[e][1], crease });
    }
    if(items.empty()) return;
    m_nodes.reserve(items.size() / 2 + 1); // a leaf holds leaf_size / 2 edges or more
    build(g.points, items, 0, items.size());
  }

  // At least the lengths within the ball of radius r around c (the length_in_ball() of
  // every edge): of the crease edges, and of the band edges, each times band_weight(d, t)
  // if `by_direction`; more by the edges of the leaves that the sphere crosses, whose
  // lengths count whole.
  Gap_lengths lengths(const Eigen::Vector3d& c, double r, const Eigen::Vector3d& t, bool by_direction,
                      std::vector<std::uint32_t>& stack) const
  {
    Gap_lengths out;
    if(m_nodes.empty()) return out;
    const double r2 = r * r;
    stack.clear();
    stack.push_back(0);
    while(!stack.empty())
    {
      const Node& n = m_nodes[stack.back()];
      stack.pop_back();
      // the squared distances from c to the box and to its farthest corner
      double near2 = 0, far2 = 0;
      for(int k = 0; k < 3; ++k)
      {
        const double below = n.lo[k] - c[k], above = c[k] - n.hi[k];
        const double d = (std::max)({ below, above, 0. });
        near2 += d * d;
        const double f = (std::max)(c[k] - n.lo[k], n.hi[k] - c[k]);
        far2 += f * f;
      }
      if(near2 > r2) continue;
      if(far2 <= r2 || n.left == no_child)
      {
        out.crease += n.crease;
        out.band += by_direction ? n.band.along(t) : n.band.trace();
        continue;
      }
      stack.push_back(n.right);
      stack.push_back(n.left);
    }
    return out;
  }

private:
  struct Item
  {
    std::uint32_t a, b;
    bool crease;
  };
  static constexpr std::uint32_t no_child = std::uint32_t(-1);
  struct Node
  {
    Eigen::Vector3d lo, hi;
    double crease = 0;
    Band_tensor band;
    std::uint32_t left = no_child, right = no_child;
  };

  // the node of items [first, last): split at the median of the midpoints along the
  // box's longest axis (ties by the edges' order: the same tree on every run)
  std::uint32_t build(const std::vector<Eigen::Vector3d>& points, std::vector<Item>& items, std::size_t first,
                      std::size_t last)
  {
    const std::uint32_t id = std::uint32_t(m_nodes.size());
    m_nodes.emplace_back();
    Node n;
    n.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    n.hi = -n.lo;
    for(std::size_t i = first; i < last; ++i)
    {
      const Eigen::Vector3d& a = points[items[i].a];
      const Eigen::Vector3d& b = points[items[i].b];
      n.lo = n.lo.cwiseMin(a).cwiseMin(b);
      n.hi = n.hi.cwiseMax(a).cwiseMax(b);
    }
    if(last - first > leaf_size)
    {
      int axis = 0;
      const Eigen::Vector3d extent = n.hi - n.lo;
      if(extent.y() > extent[axis]) axis = 1;
      if(extent.z() > extent[axis]) axis = 2;
      const std::size_t mid = first + (last - first) / 2;
      std::nth_element(items.begin() + std::ptrdiff_t(first), items.begin() + std::ptrdiff_t(mid),
                       items.begin() + std::ptrdiff_t(last), [&](const Item& x, const Item& y) {
                         const double px = points[x.a][axis] + points[x.b][axis];
                         const double py = points[y.a][axis] + points[y.b][axis];
                         return px < py || (px == py && (x.a < y.a || (x.a == y.a && x.b < y.b)));
                       });
      n.left = build(points, items, first, mid);
      n.right = build(points, items, mid, last);
      const Node& l = m_nodes[n.left];
      const Node& r = m_nodes[n.right];
      n.crease = l.crease + r.crease;
      n.band = l.band;
      n.band.add(r.band);
    }
    else
      for(std::size_t i = first; i < last; ++i)
      {
        const Eigen::Vector3d d = points[items[i].b] - points[items[i].a];
        if(items[i].crease) n.crease += d.norm();
        else n.band.add(d, d.norm());
      }
    m_nodes[id] = n;
    return id;
  }

  std::vector<Node> m_nodes;
};

// Per candidate, at least the lengths its search can find: those of every crease and band
// edge within its ball, reached from the candidate or not, and of the edges near the
// ball's sphere (Gap_edge_hierarchy::lengths()). The searches need only an upper bound
// to end early with the verdict of the whole search. The candidates by TBB's threads if
// `parallel`, each summed in the hierarchy's order: the same at any count.
inline std::vector<Gap_lengths> crease_gap_length_bounds(const Edge_geometry& g, const std::vector<double>& angle,
                                                         const std::vector<double>& band_angle, double crease_angle,
                                                         const std::vector<std::size_t>& candidates,
                                                         bool by_direction = true, bool parallel = false)
{
  std::vector<Gap_lengths> bound(candidates.size());
  if(candidates.empty()) return bound;
  const std::vector<Eigen::Vector3d>& points = g.points;
  const Gap_edge_hierarchy hierarchy(g, angle, band_angle, crease_angle);
  const double r = crease_gap_ball_radius(points, g.ends);
  for_each_range(candidates.size(), parallel, 64, [&](std::size_t first, std::size_t last) {
    std::vector<std::uint32_t> stack;
    for(std::size_t i = first; i < last; ++i)
    {
      const std::size_t c = candidates[i];
      const Eigen::Vector3d m = 0.5 * (points[g.ends[c][0]] + points[g.ends[c][1]]);
      Eigen::Vector3d t = points[g.ends[c][1]] - points[g.ends[c][0]];
      if(t.squaredNorm() > 0) t.normalize();
      bound[i] = hierarchy.lengths(m, r, t, by_direction, stack);
    }
  });
  return bound;
}

// The candidates whose ball holds a band edge (is_crease_gap_band_edge), or may: those
// with a band edge closer to their midpoint than the ball's radius (plus a relative
// 1e-6, far above rounding). The others pass the gap test whatever their ball holds
// (no band length is at most any share of the crease length), so they need no search:
// on a clean CAD tessellation, which has few band edges, few do.
inline std::vector<std::size_t> candidates_near_band_edges(const Edge_geometry& g, const std::vector<double>& angle,
                                                           const std::vector<double>& band_angle,
                                                           double crease_angle,
                                                           const std::vector<std::size_t>& candidates)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Segment_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Iterator> > > Tree;
  const std::vector<Eigen::Vector3d>& points = g.points;
  std::vector<K::Segment_3> band;
  auto point = [&](std::size_t v) { return K::Point_3(points[v].x(), points[v].y(), points[v].z()); };
  for(std::size_t e = 0; e < g.ends.size(); ++e)
    if(is_crease_gap_band_edge(angle[e], band_angle[e], crease_angle))
      band.emplace_back(point(g.ends[e][0]), point(g.ends[e][1]));
  std::vector<std::size_t> near;
  if(band.empty()) return near;
  const double r = crease_gap_ball_radius(points, g.ends) * (1 + 1e-6);
  Tree tree(band.begin(), band.end());
  tree.accelerate_distance_queries();
  for(std::size_t e : candidates)
  {
    const Eigen::Vector3d c = 0.5 * (points[g.ends[e][0]] + points[g.ends[e][1]]);
    if(tree.squared_distance(K::Point_3(c.x(), c.y(), c.z())) < r * r) near.push_back(e);
  }
  return near;
}

// The least number of searched candidates for which the gap test builds the cluster
// hierarchy of Crease_gap_search: the hierarchy costs about as much as 800 searches face
// by face at any resolution (both grow with the faces; fandisk at 828k faces: 0.26 s to
// build, 0.66 ms per search face by face and 0.34 ms with the clusters), and a clean CAD
// tessellation has few candidates near a band edge (fandisk: 64 of 2,288).
constexpr std::size_t crease_gap_hierarchy_least_candidates = 512;

// Drops the candidates (is_crease, from `angle`) that fail the gap test; `raw` are the
// dihedral angles of the unfiltered normals, `raw_roughness` their roughness; a candidate
// bending by `keep_from` degrees or more is kept untested (Crease_gap::strong_angle);
// `by_direction`: the band edges weigh by band_weight() (on a tessellation with large
// planar regions, detect_creases()), else their lengths count whole. Each
// candidate's test reads the angles only, never is_crease, so the candidates are tested
// independently: by TBB's threads if `parallel`, with the same result at any count.
// Only the candidates near a band edge are searched (candidates_near_band_edges()), face
// by face if they are few (crease_gap_hierarchy_least_candidates).
template <typename TriangleMesh, typename VPM>
void keep_creases_with_gap(const Mesh_indexing<TriangleMesh>& idx, VPM vpm, const std::vector<double>& angle,
                           const std::vector<double>& raw, double raw_roughness, double crease_angle,
                           std::vector<char>& is_crease, bool parallel = false, double keep_from = 360.,
                           bool by_direction = true)
{
  std::vector<std::size_t> candidates;
  for(std::size_t e = 0; e < is_crease.size(); ++e)
    if(is_crease[e] && angle[e] < keep_from) candidates.push_back(e);
  const std::vector<double>& band_angle = raw_roughness <= Crease_gap::raw_roughness ? raw : angle;
  Edge_geometry geometry = edge_geometry(idx, vpm);
  const std::vector<std::size_t> searched =
    candidates_near_band_edges(geometry, angle, band_angle, crease_angle, candidates);
  // A search ends once its verdict is sure: the band it found already exceeds the share
  // of all the crease length within the ball, or all the band length within the ball is
  // below the share of the crease it found (the sums only grow; a relative margin of 1e-9
  // covers the order of the additions); the verdict is that of the whole search.
  const std::vector<Gap_lengths> bound =
    crease_gap_length_bounds(geometry, angle, band_angle, crease_angle, searched, by_direction, parallel);
  const double ratio = Crease_gap::ratio, margin = 1 + 1e-9;
  const std::vector<Gap_lengths> lengths =
    crease_gap_lengths(idx, std::move(geometry), angle, band_angle, crease_angle, searched, parallel,
                       searched.size() >= crease_gap_hierarchy_least_candidates ? 8 : 0, by_direction,
                       [&](std::size_t i) {
                         const Gap_lengths b = bound[i];
                         return [b, ratio, margin](const Gap_lengths& s) {
                           return s.band > ratio * b.crease * margin || b.band * margin < ratio * s.crease;
                         };
                       });
  for(std::size_t i = 0; i < searched.size(); ++i)
    if(lengths[i].band > ratio * lengths[i].crease) is_crease[searched[i]] = 0;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_TEST_H
