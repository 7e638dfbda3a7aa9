// SPDX-License-Identifier: GPL-3.0-or-later
// An element id stored in 32 bits where a mesh's topology is copied into arrays (half
// the memory of std::size_t). It reads and writes as a std::size_t, and keeps "none"
// (std::size_t(-1), a border's missing face) as "none". For element ids only (never
// for the user's patch ids, which may be any std::size_t): the arrays that hold it check
// their mesh's size with check_compact_index_range().

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_COMPACT_INDEX_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_COMPACT_INDEX_H

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Compact_index
{
public:
  static constexpr std::uint32_t none = UINT32_MAX;

  Compact_index(std::size_t i = 0) : m_i(i == std::size_t(-1) ? none : std::uint32_t(i)) {}
  operator std::size_t() const { return m_i == none ? std::size_t(-1) : std::size_t(m_i); }

private:
  std::uint32_t m_i;
};

static_assert(sizeof(Compact_index) == 4, "a compact index takes 32 bits");

// The two vertex ids of every edge of a graph.
typedef std::vector<std::pair<Compact_index, Compact_index> > Edge_vertex_list;

// Throws std::length_error if ids up to `largest` (excluded) do not fit a Compact_index.
inline void check_compact_index_range(std::size_t largest)
{
  if(largest >= std::size_t(Compact_index::none))
    throw std::length_error("the mesh has more than 4,294,967,294 elements of a kind: "
                            "the segmentation stores element ids in 32 bits");
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_COMPACT_INDEX_H
