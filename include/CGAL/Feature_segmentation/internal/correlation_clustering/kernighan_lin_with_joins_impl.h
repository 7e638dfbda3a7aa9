// SPDX-License-Identifier: GPL-3.0-or-later
//
// The work behind Kernighan_lin_with_joins: cluster bookkeeping (labels, and member lists
// as intrusive linked lists over node arrays, so that moves are O(1) and nothing is
// allocated per cluster), the Kernighan-Lin move sequence between two clusters, and the
// rounds that revisit only the clusters changed in the previous round.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_KERNIGHAN_LIN_WITH_JOINS_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_KERNIGHAN_LIN_WITH_JOINS_IMPL_H

#include <CGAL/assertions.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Lazy_max_heap.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Simple_adjacency.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Kernighan_lin_with_joins_impl
{
public:
  Kernighan_lin_with_joins_impl(std::size_t number_of_iterations, double epsilon,
                                std::size_t moves_without_improvement)
    : m_number_of_iterations(number_of_iterations), m_epsilon(epsilon),
      m_moves_without_improvement((std::max)(std::size_t(1), moves_without_improvement))
  {}

  // `labels` holds a partition (any label values smaller than labels.size() + 1 after
  // normalisation by the caller); on exit it holds a partition whose cut cost is not
  // larger, with labels not normalised.
  void run(const Simple_adjacency& adj, std::vector<std::size_t>& labels)
  {
    m_adj = &adj;
    const std::size_t n = adj.number_of_nodes();
    CGAL_precondition(labels.size() == n);
    if(n == 0)
      return;

    m_label.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      m_label[i] = Cc_index(labels[i]);
    const double input_cost = cost();

    m_next.resize(n);
    m_previous.resize(n);
    m_gain.resize(n);
    m_stamp.assign(n, 0);
    m_sequence = 0;
    m_heap.reset(n);

    // Every cluster counts as changed before the first round.
    m_changed_next.assign(n, 1);
    split_into_connected_components();

    for(std::size_t round = 0; round < m_number_of_iterations; ++round)
    {
      const std::size_t k = m_head.size();
      m_changed_next.assign(k, 0);
      collect_pairs();

      double improvement = 0.;
      for(const std::pair<Cc_index, Cc_index>& pair : m_pairs)
      {
        if(m_size[pair.first] == 0 || m_size[pair.second] == 0)
          continue;
        const double gain = improve_pair(pair.first, pair.second);
        if(gain > 0.)
        {
          improvement += gain;
          m_changed_next[pair.first] = m_changed_next[pair.second] = 1;
        }
      }

      // Splitting depends only on the members of one cluster, so it is retried only for
      // clusters whose members changed since the last attempt.
      for(Cc_index a = 0; a < Cc_index(k); ++a)
      {
        if(!(m_changed[a] || m_changed_next[a]) || m_size[a] < 2)
          continue;
        const double gain = split(a);
        if(gain > 0.)
        {
          improvement += gain;
          m_changed_next[a] = 1;
          m_changed_next.push_back(1);
        }
      }

      if(improvement <= m_epsilon)
        break;
      split_into_connected_components();
    }

    // Gains are exact up to rounding; never hand back something worse than the input.
    if(cost() <= input_cost)
      for(std::size_t i = 0; i < n; ++i)
        labels[i] = m_label[i];
  }

private:
  double cost() const
  {
    double c = 0.;
    for(std::size_t i = 0; i < m_label.size(); ++i)
      for(std::size_t k = m_adj->begin(i); k < m_adj->end(i); ++k)
        if(m_label[i] != m_label[m_adj->neighbors[k]])
          c += m_adj->weights[k];
    return c / 2.;
  }

  // Moving nodes can disconnect a cluster; its components are better treated as separate
  // clusters (same cost, more freedom). Also compacts cluster indices, and carries the
  // "changed" flags over from m_changed_next to m_changed.
  void split_into_connected_components()
  {
    const std::size_t n = m_label.size();
    m_new_label.assign(n, none());
    m_changed.clear();
    Cc_index k = 0;
    for(std::size_t s = 0; s < n; ++s)
    {
      if(m_new_label[s] != none())
        continue;
      const Cc_index old_label = m_label[s];
      m_new_label[s] = k;
      m_queue.clear();
      m_queue.push_back(Cc_index(s));
      for(std::size_t head = 0; head < m_queue.size(); ++head)
      {
        const Cc_index x = m_queue[head];
        for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
        {
          const Cc_index y = m_adj->neighbors[j];
          if(m_new_label[y] == none() && m_label[y] == old_label)
          {
            m_new_label[y] = k;
            m_queue.push_back(y);
          }
        }
      }
      m_changed.push_back(m_changed_next[old_label]);
      ++k;
    }
    m_label.swap(m_new_label);

    m_head.assign(k, none());
    m_size.assign(k, 0);
    // Pushing in decreasing order lists the members of each cluster in increasing order.
    for(std::size_t x = n; x-- > 0;)
      push_front(Cc_index(x), m_label[x]);
  }

  // Pairs of adjacent clusters of which at least one changed in the previous round, each
  // pair once, in an order that depends only on the labelling.
  void collect_pairs()
  {
    const std::size_t k = m_head.size();
    m_pairs.clear();
    m_pair_mark.assign(k, Cc_index(-1));
    for(Cc_index a = 0; a < Cc_index(k); ++a)
    {
      if(!m_changed[a])
        continue;
      for(Cc_index x = m_head[a]; x != none(); x = m_next[x])
        for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
        {
          const Cc_index b = m_label[m_adj->neighbors[j]];
          if(b != a && m_pair_mark[b] != a && (!m_changed[b] || a < b))
          {
            m_pair_mark[b] = a;
            m_pairs.emplace_back(a, b);
          }
        }
    }
  }

  // Decrease of the cut cost if x moves from its cluster to the other one of {a, b}.
  double move_gain(Cc_index x, Cc_index a, Cc_index b) const
  {
    const Cc_index from = m_label[x];
    const Cc_index to = from == a ? b : a;
    double gain = 0.;
    for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
    {
      const Cc_index l = m_label[m_adj->neighbors[j]];
      if(l == to)
        gain += m_adj->weights[j];
      else if(l == from)
        gain -= m_adj->weights[j];
    }
    return gain;
  }

  // Best of: a Kernighan-Lin sequence of moves between a and b, and joining a and b.
  // Applies it if it improves by more than epsilon; returns the applied gain (or 0).
  double improve_pair(Cc_index a, Cc_index b)
  {
    const Cc_index small = m_size[a] <= m_size[b] ? a : b;
    const Cc_index large = small == a ? b : a;
    begin_sequence();
    double join_gain = 0.;
    for(Cc_index x = m_head[small]; x != none(); x = m_next[x])
      for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
      {
        const Cc_index y = m_adj->neighbors[j];
        if(m_label[y] != large)
          continue;
        join_gain += m_adj->weights[j];
        add_candidate(x);
        add_candidate(y);
      }
    if(m_candidates.empty())
      return 0.;

    const std::size_t kept = run_sequence(a, b);
    const double sequence_gain = m_prefix_gain;
    if(join_gain > sequence_gain && join_gain > m_epsilon)
    {
      undo_moves(0);
      // Splice the list of the small cluster in front of the list of the large one.
      Cc_index last = m_head[small];
      m_label[last] = large;
      while(m_next[last] != none())
      {
        last = m_next[last];
        m_label[last] = large;
      }
      m_next[last] = m_head[large];
      m_previous[m_head[large]] = last;
      m_head[large] = m_head[small];
      m_head[small] = none();
      m_size[large] += m_size[small];
      m_size[small] = 0;
      return join_gain;
    }
    if(kept > 0 && sequence_gain > m_epsilon)
    {
      commit_moves();
      return sequence_gain;
    }
    undo_moves(0);
    return 0.;
  }

  // Kernighan-Lin moves from cluster a to a new, empty cluster.
  double split(Cc_index a)
  {
    const Cc_index b = Cc_index(m_head.size());
    m_head.push_back(none());
    m_size.push_back(0);
    begin_sequence();
    for(Cc_index x = m_head[a]; x != none(); x = m_next[x])
      add_candidate(x);

    const std::size_t kept = run_sequence(a, b);
    if(kept > 0 && m_prefix_gain > m_epsilon)
    {
      commit_moves();
      return m_prefix_gain;
    }
    undo_moves(0);
    m_head.pop_back();
    m_size.pop_back();
    return 0.;
  }

  // One stamp per node and sequence: 2s means "candidate in sequence s", 2s+1 means
  // "moved in sequence s". One array instead of two saves a cache miss per neighbour.
  void begin_sequence()
  {
    m_sequence += 2;
    m_candidates.clear();
  }

  bool is_candidate(Cc_index x) const { return m_stamp[x] >= m_sequence; }
  bool is_locked(Cc_index x) const { return m_stamp[x] == m_sequence + 1; }

  void add_candidate(Cc_index x)
  {
    if(!is_candidate(x))
    {
      m_stamp[x] = m_sequence;
      m_candidates.push_back(x);
    }
  }

  // Moves greedily the candidate of largest gain (possibly negative) to the other
  // cluster, each node at most once, neighbours of moved nodes becoming candidates; then
  // undoes the moves after the best prefix. Returns the length of that prefix and stores
  // its gain in m_prefix_gain. Only labels change here; member lists are updated by
  // commit_moves() once the caller decides to keep the moves, which makes rejected
  // sequences (the vast majority) cheap.
  std::size_t run_sequence(Cc_index a, Cc_index b)
  {
    m_moves.clear();
    // Most sequences involve a few dozen nodes; for them, a linear scan of the open
    // candidates finds the best move faster than a heap. Long sequences switch to the
    // heap for good as soon as the open candidates outgrow the threshold.
    m_open.clear();
    bool use_heap = false;
    for(Cc_index x : m_candidates)
    {
      m_gain[x] = move_gain(x, a, b);
      m_open.push_back(x);
    }
    if(m_open.size() > linear_scan_threshold())
      switch_to_heap(use_heap);

    double total = 0.;
    m_prefix_gain = 0.;
    std::size_t best_length = 0;
    for(;;)
    {
      Cc_index x;
      if(use_heap)
      {
        Lazy_max_heap::Entry top;
        if(!m_heap.pop(top))
          break;
        x = top.item;
      }
      else
      {
        if(m_open.empty())
          break;
        std::size_t best = 0;
        for(std::size_t i = 1; i < m_open.size(); ++i)
        {
          const double gi = m_gain[m_open[i]], gb = m_gain[m_open[best]];
          if(gi > gb || (gi == gb && m_open[i] < m_open[best]))
            best = i;
        }
        x = m_open[best];
        m_open[best] = m_open.back();
        m_open.pop_back();
      }

      const Cc_index from = m_label[x];
      const Cc_index to = from == a ? b : a;
      total += m_gain[x];
      m_label[x] = to;
      m_stamp[x] = m_sequence + 1;
      m_moves.push_back(Move{x, from});
      if(total > m_prefix_gain)
      {
        m_prefix_gain = total;
        best_length = m_moves.size();
      }
      // Without this bound, a large cluster would be swept entirely for each of its
      // neighbours, which is quadratic when one cluster covers most of the graph.
      if(m_moves.size() - best_length >= m_moves_without_improvement)
        break;

      for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
      {
        const Cc_index y = m_adj->neighbors[j];
        const Cc_index l = m_label[y];
        if((l != a && l != b) || is_locked(y))
          continue;
        if(!is_candidate(y))
        {
          m_stamp[y] = m_sequence;
          m_gain[y] = move_gain(y, a, b);
          if(!use_heap)
            m_open.push_back(y);
        }
        else
        {
          // The edge x-y switched between cut and uncut, for y on either side.
          const double w = 2. * m_adj->weights[j];
          m_gain[y] += (l == from) ? w : -w;
        }
        if(use_heap)
          m_heap.update(y, m_gain[y]);
      }
      if(!use_heap && m_open.size() > linear_scan_threshold())
        switch_to_heap(use_heap);
    }
    undo_moves(best_length);
    return best_length;
  }

  void switch_to_heap(bool& use_heap)
  {
    m_heap.clear();
    for(Cc_index x : m_open)
      m_heap.update(x, m_gain[x]);
    m_open.clear();
    use_heap = true;
  }

  static std::size_t linear_scan_threshold() { return 48; }

  static Cc_index none() { return Cc_index(-1); }

  void push_front(Cc_index x, Cc_index cluster)
  {
    m_previous[x] = none();
    m_next[x] = m_head[cluster];
    if(m_head[cluster] != none())
      m_previous[m_head[cluster]] = x;
    m_head[cluster] = x;
    ++m_size[cluster];
  }

  void unlink(Cc_index x, Cc_index cluster)
  {
    if(m_previous[x] != none())
      m_next[m_previous[x]] = m_next[x];
    else
      m_head[cluster] = m_next[x];
    if(m_next[x] != none())
      m_previous[m_next[x]] = m_previous[x];
    --m_size[cluster];
  }

  void undo_moves(std::size_t length)
  {
    for(std::size_t i = length; i < m_moves.size(); ++i)
      m_label[m_moves[i].node] = m_moves[i].from;
    m_moves.resize(length);
  }

  // Brings the member lists up to date with the labels after the kept moves.
  void commit_moves()
  {
    for(const Move& move : m_moves)
    {
      unlink(move.node, move.from);
      push_front(move.node, m_label[move.node]);
    }
    m_moves.clear();
  }

  // a move of a sequence: the node and the cluster it left
  struct Move
  {
    Cc_index node;
    Cc_index from;
  };

  const Simple_adjacency* m_adj = nullptr;
  std::size_t m_number_of_iterations;
  double m_epsilon;
  std::size_t m_moves_without_improvement;

  std::vector<Cc_index> m_label;
  std::vector<Cc_index> m_new_label;
  std::vector<Cc_index> m_next;     // next member of the same cluster
  std::vector<Cc_index> m_previous; // previous member of the same cluster
  std::vector<Cc_index> m_head;     // first member of each cluster
  std::vector<Cc_index> m_size;     // number of members of each cluster
  std::vector<char> m_changed;
  std::vector<char> m_changed_next;
  std::vector<std::pair<Cc_index, Cc_index> > m_pairs;
  std::vector<Cc_index> m_pair_mark;
  std::vector<Cc_index> m_queue;

  std::vector<double> m_gain;
  std::vector<std::size_t> m_stamp;
  std::size_t m_sequence = 0;
  Lazy_max_heap m_heap;
  std::vector<Cc_index> m_candidates;
  std::vector<Cc_index> m_open;
  // the moves of the current sequence, and their gain so far
  double m_prefix_gain = 0.;
  std::vector<Move> m_moves;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_KERNIGHAN_LIN_WITH_JOINS_IMPL_H
