// SPDX-License-Identifier: GPL-3.0-or-later
//
// A binary max-heap of (priority, item) pairs with lazy deletion, used by both solvers.
// Updating the priority of an item pushes a new entry and bumps the item's version;
// entries whose version is no longer current are skipped when they reach the top. This
// is cheaper than an indexed heap with decrease-key for the update patterns of edge
// contraction and Kernighan-Lin moves, and it never allocates per update once warm.
// The initial entries are kept apart in one sorted array: most of them are popped
// without ever being updated, and walking a sorted array is much more cache friendly
// than sifting them through a heap of millions of entries.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_LAZY_MAX_HEAP_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_LAZY_MAX_HEAP_H

#include <CGAL/Feature_segmentation/internal/correlation_clustering/Simple_adjacency.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Lazy_max_heap
{
public:
  struct Entry
  {
    double priority;
    Cc_index item;
    Cc_index version;
  };

  // Resets the versions of items 0..n-1 and empties the heap.
  void reset(std::size_t n)
  {
    m_versions.assign(n, 0);
    clear();
  }

  void clear()
  {
    m_entries.clear();
    m_initial.clear();
    m_cursor = 0;
  }

  // Invalidates all entries of `item` already in the heap.
  void invalidate(Cc_index item) { ++m_versions[item]; }

  // Invalidates older entries of `item` and pushes it with `priority`.
  void update(Cc_index item, double priority)
  {
    push_entry(Entry{priority, item, ++m_versions[item]});
  }

  // Adds an initial entry; call sort_initial() once all are added, before any pop or
  // update.
  void append_initial(Cc_index item, double priority)
  {
    m_initial.push_back(Entry{priority, item, m_versions[item]});
  }

  void sort_initial()
  {
    std::sort(m_initial.begin(), m_initial.end(),
              [](const Entry& a, const Entry& b) { return Less()(b, a); });
    m_cursor = 0;
  }

  // Returns false if no current entry is left, otherwise removes the largest current
  // entry and stores it in `top`. Stale entries met on the way are discarded.
  bool pop(Entry& top)
  {
    while(m_cursor < m_initial.size() && is_stale(m_initial[m_cursor]))
      ++m_cursor;
    while(!m_entries.empty() && is_stale(m_entries.front()))
      pop_entry();
    const bool has_initial = m_cursor < m_initial.size();
    if(m_entries.empty() && !has_initial)
      return false;
    if(m_entries.empty() || (has_initial && Less()(m_entries.front(), m_initial[m_cursor])))
    {
      top = m_initial[m_cursor++];
    }
    else
    {
      top = m_entries.front();
      pop_entry();
    }
    return true;
  }

private:
  // Ties go to the smaller item index, which makes the solvers deterministic.
  struct Less
  {
    bool operator()(const Entry& a, const Entry& b) const
    {
      return a.priority < b.priority || (a.priority == b.priority && a.item > b.item);
    }
  };

  bool is_stale(const Entry& entry) const { return entry.version != m_versions[entry.item]; }

  void pop_entry()
  {
    std::pop_heap(m_entries.begin(), m_entries.end(), Less());
    m_entries.pop_back();
  }

  void push_entry(const Entry& entry)
  {
    m_entries.push_back(entry);
    std::push_heap(m_entries.begin(), m_entries.end(), Less());
  }

  std::vector<Entry> m_entries;
  std::vector<Entry> m_initial;
  std::size_t m_cursor = 0;
  std::vector<Cc_index> m_versions;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_LAZY_MAX_HEAP_H
