// SPDX-License-Identifier: GPL-3.0-or-later
// The work behind metrics.h: segments of a mesh extracted as plain double-precision
// geometry (patch boundaries made of mesh edges, boundary curves on the surface,
// feature-line pieces), distance queries against a set of
// segments with CGAL's AABB tree, and the contingency table of two face labellings from
// which the Rand index and the over- and under-segmentation counts are read.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_EVALUATION_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_EVALUATION_IMPL_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Evaluation_kernel;
typedef Evaluation_kernel::Point_3 Evaluation_point;
typedef Evaluation_kernel::Segment_3 Evaluation_segment;

template <typename Point>
Evaluation_point to_evaluation_point(const Point& p)
{
  return Evaluation_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// Distances from points to a fixed set of segments. An empty set is infinitely far.
class Segment_distance
{
  typedef std::vector<Evaluation_segment>::const_iterator Iterator;
  typedef CGAL::AABB_segment_primitive<Evaluation_kernel, Iterator> Primitive;
  typedef CGAL::AABB_traits<Evaluation_kernel, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

public:
  explicit Segment_distance(const std::vector<Evaluation_segment>& segments)
    : m_segments(segments)
  {
    // Degenerate segments carry no length; the tree rejects nothing but they add nothing.
    if(!m_segments.empty())
    {
      m_tree.insert(m_segments.begin(), m_segments.end());
      m_tree.accelerate_distance_queries();
    }
  }

  Segment_distance(const Segment_distance&) = delete; // the tree points into m_segments
  Segment_distance& operator=(const Segment_distance&) = delete;

  bool is_within(const Evaluation_point& p, double tolerance) const
  {
    if(m_segments.empty()) return false;
    return m_tree.squared_distance(p) <= tolerance * tolerance;
  }

private:
  std::vector<Evaluation_segment> m_segments; // owned: the tree points into it
  Tree m_tree;
};

// Length of the pieces of `pieces` whose midpoint lies within `tolerance` of `target`.
inline double matched_length(const std::vector<Evaluation_segment>& pieces, const Segment_distance& target,
                             double tolerance)
{
  double len = 0;
  for(const Evaluation_segment& s : pieces)
    if(target.is_within(CGAL::midpoint(s.source(), s.target()), tolerance))
      len += std::sqrt(s.squared_length());
  return len;
}

inline double total_length(const std::vector<Evaluation_segment>& pieces)
{
  double len = 0;
  for(const Evaluation_segment& s : pieces) len += std::sqrt(s.squared_length());
  return len;
}

// The edges of `tm` between two faces of different patches (border edges excluded).
template <typename TriangleMesh, typename FacePatchMap, typename VertexPointMap>
std::vector<Evaluation_segment> patch_boundary_segments(const TriangleMesh& tm, FacePatchMap face_patch,
                                                        VertexPointMap vpm)
{
  std::vector<Evaluation_segment> result;
  for(auto e : edges(tm))
  {
    if(is_border(e, tm)) continue;
    auto h = halfedge(e, tm);
    if(get(face_patch, face(h, tm)) == get(face_patch, face(opposite(h, tm), tm))) continue;
    result.emplace_back(to_evaluation_point(get(vpm, source(h, tm))), to_evaluation_point(get(vpm, target(h, tm))));
  }
  return result;
}

// The segments of boundary curves (a `Patch_boundaries`: polylines whose points lie on
// the surface, inside triangles and on edges), closing segments of closed curves included.
template <typename PatchBoundaries>
std::vector<Evaluation_segment> boundary_curve_segments(const PatchBoundaries& boundaries)
{
  std::vector<Evaluation_segment> result;
  for(const auto& c : boundaries.curves())
  {
    const std::size_t n = c.points.size();
    const std::size_t m = c.is_closed() ? (n > 1 ? n : 0) : (n > 0 ? n - 1 : 0);
    for(std::size_t i = 0; i < m; ++i)
    {
      const auto &a = c.points[i].point, &b = c.points[(i + 1) % n].point;
      result.emplace_back(Evaluation_point(a[0], a[1], a[2]), Evaluation_point(b[0], b[1], b[2]));
    }
  }
  return result;
}

// Compact ids 0..n-1 of arbitrary integer labels, in order of first appearance.
template <typename Label>
std::vector<std::size_t> compact_labels(const std::vector<Label>& labels, std::size_t& n)
{
  std::unordered_map<Label, std::size_t> ids;
  std::vector<std::size_t> result(labels.size());
  for(std::size_t i = 0; i < labels.size(); ++i)
    result[i] = ids.emplace(labels[i], ids.size()).first->second;
  n = ids.size();
  return result;
}

// The weighted contingency table of two labellings (compact ids), as a sparse map.
struct Contingency_table
{
  std::size_t na = 0, nb = 0;
  std::vector<double> row, column;                  // total weight per label of a, of b
  std::unordered_map<std::size_t, double> cells;    // key a * nb + b
  double total = 0, sum_of_squared_weights = 0;

  Contingency_table(const std::vector<std::size_t>& a, std::size_t na_, const std::vector<std::size_t>& b,
                    std::size_t nb_, const std::vector<double>& w)
    : na(na_), nb(nb_), row(na_, 0.), column(nb_, 0.)
  {
    for(std::size_t i = 0; i < a.size(); ++i)
    {
      row[a[i]] += w[i];
      column[b[i]] += w[i];
      cells[a[i] * nb + b[i]] += w[i];
      total += w[i];
      sum_of_squared_weights += w[i] * w[i];
    }
  }
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_EVALUATION_IMPL_H
