// SPDX-License-Identifier: GPL-3.0-or-later
// The states of the editing engine and their history. A state is immutable once made:
// an edit makes a new one that shares with its predecessor every part the edit leaves
// alone (copy on write), and the history is the list of states with a cursor. Undo and
// redo move the cursor; a new edit drops the states after it. What the history keeps is
// bounded by the memory of the parts that the current state does not use, not by a
// number of edits.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_EDIT_HISTORY_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_EDIT_HISTORY_H

#include <CGAL/Feature_segmentation/internal/edge_alphas.h>
#include <CGAL/Feature_segmentation/internal/edge_weights_impl.h>
#include <CGAL/Feature_segmentation/internal/oversegmentation_impl.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <memory>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The oversegmentation and the graph G' it induces (a sketch redoes them), with the
// oversegments in the order of their first vertex (the order patch ids follow).
struct Reduction
{
  Oversegmentation os;
  Reduced_graph rg;
  std::vector<std::size_t> segments_in_vertex_order;
  std::vector<std::size_t> segment_size; // vertices per segment

  // Sets segments_in_vertex_order and segment_size from os (every vertex in a segment).
  void order_segments()
  {
    std::vector<char> seen(os.number_of_segments, 0);
    segments_in_vertex_order.clear();
    segments_in_vertex_order.reserve(os.number_of_segments);
    segment_size.assign(os.number_of_segments, 0);
    for(std::size_t s : os.vertex_segment)
    {
      CGAL_assertion(s < os.number_of_segments);
      ++segment_size[s];
      if(!seen[s]) { seen[s] = 1; segments_in_vertex_order.push_back(s); }
    }
    CGAL_postcondition(segments_in_vertex_order.size() == os.number_of_segments);
  }

  std::size_t memory() const
  {
    return (os.vertex_segment.capacity() + segments_in_vertex_order.capacity() + segment_size.capacity()) *
             sizeof(std::size_t) +
           rg.edges.capacity() * sizeof(std::pair<std::size_t, std::size_t>) +
           (rg.cross_begin.capacity() + rg.cross.capacity()) * sizeof(std::size_t);
  }
};

// One state of the segmentation: every part is shared, read-only, with the states
// before and after it that have the same part. The patches are kept per oversegment, so
// an edit that re-solves G' writes nothing per vertex; a vertex's patch is that of its
// oversegment.
struct Edit_state
{
  double alpha = 0;
  Edge_alphas alpha_e;                                            // per edge and crease tie
  std::shared_ptr<const std::vector<std::size_t> > group;         // per oversegment: its merge group
  std::shared_ptr<const std::vector<std::size_t> > segment_patch; // per oversegment: its patch
  std::size_t number_of_patches = 0;
  std::shared_ptr<const Reduction> reduction;
  std::shared_ptr<const Feature_terms> features;

  // The alpha_e and the weight of edge (or crease tie) `e`.
  double alpha_of(std::size_t e) const { return alpha_e(e, features->is_feature_edge[e] != 0, alpha); }
  double weight(std::size_t e) const { return features->weight(e, alpha_of(e)); }

  // The patch of working vertex `v`, and of every working vertex.
  std::size_t vertex_patch(std::size_t v) const { return (*segment_patch)[reduction->os.vertex_segment[v]]; }
  std::vector<std::size_t> vertex_patches() const
  {
    const std::vector<std::size_t>& seg = reduction->os.vertex_segment;
    std::vector<std::size_t> labels(seg.size());
    for(std::size_t v = 0; v < seg.size(); ++v) labels[v] = (*segment_patch)[seg[v]];
    return labels;
  }

  // Calls f(pointer, bytes) for every part; f returns whether the part is new to it (a
  // part made of parts reports those only when it is new itself).
  template <typename F>
  void for_each_part(F f) const
  {
    alpha_e.for_each_part(f);
    f(group.get(), group->capacity() * sizeof(std::size_t));
    f(segment_patch.get(), segment_patch->capacity() * sizeof(std::size_t));
    f(reduction.get(), reduction->memory());
    f(features.get(), features->memory());
  }
};

class Edit_history
{
public:
  typedef std::shared_ptr<const Edit_state> State_ptr;

  Edit_history() = default;
  explicit Edit_history(State_ptr first) : m_states{ std::move(first) } {}

  const Edit_state& current() const { return *m_states[m_current]; }
  std::size_t number_of_undoable_edits() const { return m_current; }
  std::size_t number_of_redoable_edits() const { return m_states.size() - 1 - m_current; }
  std::size_t number_of_recorded_edits() const { return m_recorded; }
  std::size_t memory_limit() const { return m_limit; }

  // A new edit: its state becomes the current one; the states that undo had left behind
  // the cursor are dropped (a new branch of history), then the oldest ones while the
  // history holds more than the limit.
  void push(State_ptr s)
  {
    m_states.resize(m_current + 1);
    m_states.push_back(std::move(s));
    ++m_current;
    ++m_recorded;
    trim();
  }
  bool undo()
  {
    if(m_current == 0) return false;
    --m_current;
    return true;
  }
  bool redo()
  {
    if(m_current + 1 == m_states.size()) return false;
    ++m_current;
    return true;
  }
  void set_memory_limit(std::size_t bytes)
  {
    m_limit = bytes;
    trim();
  }

  // The bytes that the history keeps besides the current state: the parts of the other
  // states that the current one does not share, each counted once.
  std::size_t memory() const
  {
    std::unordered_set<const void*> seen;
    current().for_each_part([&](const void* p, std::size_t) { return seen.insert(p).second; });
    std::size_t bytes = 0;
    for(const State_ptr& s : m_states)
      s->for_each_part([&](const void* p, std::size_t b) {
        const bool is_new = seen.insert(p).second;
        if(is_new) bytes += b;
        return is_new;
      });
    return bytes;
  }

private:
  // Drops the farthest redo states, then the oldest undo states, while over the limit;
  // the state before the current one is always kept, so the last edit can be undone.
  void trim()
  {
    while(memory() > m_limit)
    {
      if(m_current + 1 < m_states.size())
        m_states.pop_back();
      else if(m_current > 1)
      {
        m_states.erase(m_states.begin());
        --m_current;
      }
      else
        break;
    }
  }

  std::vector<State_ptr> m_states;
  std::size_t m_current = 0;
  std::size_t m_recorded = 0;
  std::size_t m_limit = std::size_t(256) << 20;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_EDIT_HISTORY_H
