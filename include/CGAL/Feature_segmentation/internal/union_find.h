// SPDX-License-Identifier: GPL-3.0-or-later
// Disjoint sets of the indices 0 .. n-1 (union-find with path halving), whose root is
// always the smallest index of its set: the same roots whatever the order of the unions.
// Used for the faces' components (face_components.h) and the corners' sectors of the
// crease cut (crease_cut.h).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_UNION_FIND_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_UNION_FIND_H

#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Smallest_root_union_find
{
public:
  explicit Smallest_root_union_find(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::size_t(0)); }

  std::size_t find(std::size_t x)
  {
    while(m_parent[x] != x) { m_parent[x] = m_parent[m_parent[x]]; x = m_parent[x]; }
    return x;
  }
  void unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a < b) m_parent[b] = a;
    else if(b < a) m_parent[a] = b;
  }
  // The root of every index.
  std::vector<std::size_t> roots()
  {
    for(std::size_t x = 0; x < m_parent.size(); ++x) m_parent[x] = find(x);
    return m_parent;
  }

private:
  std::vector<std::size_t> m_parent;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_UNION_FIND_H
