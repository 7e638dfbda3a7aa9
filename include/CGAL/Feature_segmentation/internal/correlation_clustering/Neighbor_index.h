// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small open-addressing hash map from node index to position, used by edge contraction
// to find in constant time whether a high-degree cluster is adjacent to a given node.
// Without it, merging two large clusters costs the size of the larger neighbourhood, which
// makes contraction quadratic on graphs whose weights are mostly positive (large smooth
// patches of a mesh). Linear probing with backward-shift deletion needs no tombstones, so
// the table never degrades however many erase/insert cycles it sees.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_NEIGHBOR_INDEX_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_NEIGHBOR_INDEX_H

#include <CGAL/assertions.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Simple_adjacency.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Neighbor_index
{
public:
  static Cc_index not_found() { return Cc_index(-1); }

  // Empties the table and sizes it for `expected` keys.
  void reset(std::size_t expected)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * expected)
      capacity *= 2;
    m_keys.assign(capacity, not_found());
    m_values.resize(capacity);
    m_size = 0;
  }

  Cc_index find(Cc_index key) const
  {
    for(std::size_t s = slot(key);; s = (s + 1) & mask())
    {
      if(m_keys[s] == key)
        return m_values[s];
      if(m_keys[s] == not_found())
        return not_found();
    }
  }

  // Inserts `key` or overwrites its value.
  void assign(Cc_index key, Cc_index value)
  {
    if(2 * (m_size + 1) > m_keys.size())
      grow();
    std::size_t s = slot(key);
    while(m_keys[s] != not_found() && m_keys[s] != key)
      s = (s + 1) & mask();
    if(m_keys[s] == not_found())
    {
      m_keys[s] = key;
      ++m_size;
    }
    m_values[s] = value;
  }

  void erase(Cc_index key)
  {
    std::size_t s = slot(key);
    while(m_keys[s] != key)
    {
      CGAL_assertion(m_keys[s] != not_found());
      s = (s + 1) & mask();
    }
    // Backward shift: pull later entries of the probe run into the hole when their home
    // slot does not lie cyclically in (hole, current].
    std::size_t hole = s;
    for(std::size_t next = (hole + 1) & mask(); m_keys[next] != not_found(); next = (next + 1) & mask())
    {
      const std::size_t home = slot(m_keys[next]);
      const bool stays = (hole < next) ? (hole < home && home <= next)
                                       : (hole < home || home <= next);
      if(!stays)
      {
        m_keys[hole] = m_keys[next];
        m_values[hole] = m_values[next];
        hole = next;
      }
    }
    m_keys[hole] = not_found();
    --m_size;
  }

  void release()
  {
    std::vector<Cc_index>().swap(m_keys);
    std::vector<Cc_index>().swap(m_values);
    m_size = 0;
  }

private:
  std::size_t mask() const { return m_keys.size() - 1; }

  // Fibonacci hashing: node indices of a mesh are clustered, so the key must be mixed.
  std::size_t slot(Cc_index key) const
  {
    return std::size_t((std::uint64_t(key) * 0x9E3779B97F4A7C15ull) >> 32) & mask();
  }

  void grow()
  {
    std::vector<Cc_index> keys, values;
    keys.swap(m_keys);
    values.swap(m_values);
    m_keys.assign(2 * keys.size(), not_found());
    m_values.resize(2 * keys.size());
    m_size = 0;
    for(std::size_t s = 0; s < keys.size(); ++s)
      if(keys[s] != not_found())
        assign(keys[s], values[s]);
  }

  std::vector<Cc_index> m_keys;
  std::vector<Cc_index> m_values;
  std::size_t m_size = 0;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_NEIGHBOR_INDEX_H
