// SPDX-License-Identifier: GPL-3.0-or-later
//
// The work behind Kernighan_lin_with_joins: cluster bookkeeping (labels, and member lists
// as intrusive linked lists over node arrays, so that moves are O(1) and nothing is
// allocated per cluster), the Kernighan-Lin move sequence between two clusters, and the
// rounds that revisit only the clusters changed in the previous round.
//
// The pairs of a round may be improved by TBB's threads with the labels of one thread:
// improving a pair {a, b} moves nodes between a and b only, and reads of any other node
// only whether its cluster is a or b, which a pair of two other clusters never changes.
// So two pairs without a common cluster commute, and running every pair after the
// earlier pairs that share a cluster with it (a task graph: each pair waits for at most
// two) gives the serial result. The labels are then read and written as relaxed atomics
// (a node of another pair's clusters may be read while that pair moves it).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_KERNIGHAN_LIN_WITH_JOINS_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_KERNIGHAN_LIN_WITH_JOINS_IMPL_H

#include <CGAL/assertions.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Lazy_max_heap.h>
#include <CGAL/Feature_segmentation/internal/correlation_clustering/Simple_adjacency.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for_each.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Kernighan_lin_with_joins_impl
{
public:
  // `parallel`: the pairs of a round improved by TBB's threads (the same result).
  Kernighan_lin_with_joins_impl(std::size_t number_of_iterations, double epsilon,
                                std::size_t moves_without_improvement, bool parallel = false)
    : m_number_of_iterations(number_of_iterations), m_epsilon(epsilon),
      m_moves_without_improvement((std::max)(std::size_t(1), moves_without_improvement)), m_parallel(parallel)
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
    m_main.heap.reset(n);

    // Every cluster counts as changed before the first round.
    m_changed_next.assign(n, 1);
    split_into_connected_components();

    for(std::size_t round = 0; round < m_number_of_iterations; ++round)
    {
      const std::size_t k = m_head.size();
      m_changed_next.assign(k, 0);
      collect_pairs();

      // pair i runs sequence m_sequence + 2 (i + 1)
      double improvement = improve_pairs();
      m_sequence += 2 * (m_pairs.size() + 1);

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

  // a move of a sequence: the node and the cluster it left
  struct Move
  {
    Cc_index node;
    Cc_index from;
  };

  // What a move sequence works with: one per thread.
  struct Scratch
  {
    Lazy_max_heap heap;
    std::vector<Cc_index> candidates, open;
    std::vector<Move> moves; // the moves of the current sequence
    double prefix_gain = 0.; // and the gain of their best prefix
    std::size_t sequence = 0;
    bool ready = false;      // heap sized
  };

  // The labels, as relaxed atomics where the pairs run on threads (file comment).
#if defined(__GNUC__) || defined(__clang__)
  Cc_index label(Cc_index x) const { return __atomic_load_n(&m_label[x], __ATOMIC_RELAXED); }
  void set_label(Cc_index x, Cc_index l) { __atomic_store_n(&m_label[x], l, __ATOMIC_RELAXED); }
  static constexpr bool can_run_pairs_in_parallel = true;
#else
  Cc_index label(Cc_index x) const { return m_label[x]; }
  void set_label(Cc_index x, Cc_index l) { m_label[x] = l; }
  static constexpr bool can_run_pairs_in_parallel = false;
#endif

  // Pair i of m_pairs with sequence number m_sequence + 2 (i + 1); its gain (or 0).
  double improve_pair_at(std::size_t i, Scratch& sc)
  {
    const Cc_index a = m_pairs[i].first, b = m_pairs[i].second;
    if(m_size[a] == 0 || m_size[b] == 0)
      return 0.;
    const double gain = improve_pair(a, b, sc, m_sequence + 2 * (i + 1));
    if(gain > 0.)
      m_changed_next[a] = m_changed_next[b] = 1;
    return gain;
  }

  // Every pair of the round, in order or by TBB's threads in an order that gives the
  // same labels (file comment); returns the sum of the gains, added in pair order.
  double improve_pairs()
  {
    const std::size_t np = m_pairs.size();
    std::vector<double> gain(np, 0.);
#ifdef CGAL_LINKED_WITH_TBB
    if(can_run_pairs_in_parallel && m_parallel && np >= 64)
    {
      // the next pair of each of a pair's two clusters, and the earlier pairs it waits for
      const std::size_t none = std::size_t(-1);
      std::vector<std::size_t> last(m_head.size(), none), next(2 * np, none);
      std::unique_ptr<std::atomic<int>[]> waits(new std::atomic<int>[np]);
      std::vector<std::size_t> ready;
      for(std::size_t i = 0; i < np; ++i)
      {
        int w = 0;
        for(const Cc_index c : { m_pairs[i].first, m_pairs[i].second })
        {
          const std::size_t j = last[c];
          if(j != none)
          {
            next[2 * j + (m_pairs[j].first == c ? 0 : 1)] = i;
            ++w;
          }
          last[c] = i;
        }
        waits[i].store(w, std::memory_order_relaxed);
        if(w == 0) ready.push_back(i);
      }
      const std::size_t n = m_label.size();
      tbb::enumerable_thread_specific<Scratch> scratch;
      tbb::parallel_for_each(ready.begin(), ready.end(), [&](std::size_t i, tbb::feeder<std::size_t>& feeder) {
        Scratch& sc = scratch.local();
        if(!sc.ready)
        {
          sc.heap.reset(n);
          sc.ready = true;
        }
        gain[i] = improve_pair_at(i, sc);
        for(int side = 0; side < 2; ++side)
        {
          const std::size_t j = next[2 * i + side];
          if(j != none && waits[j].fetch_sub(1, std::memory_order_acq_rel) == 1)
            feeder.add(j);
        }
      });
    }
    else
#endif
      for(std::size_t i = 0; i < np; ++i)
        gain[i] = improve_pair_at(i, m_main);
    double improvement = 0.;
    for(double g : gain)
      if(g > 0.)
        improvement += g;
    return improvement;
  }

  // Decrease of the cut cost if x moves from its cluster to the other one of {a, b}.
  double move_gain(Cc_index x, Cc_index a, Cc_index b) const
  {
    const Cc_index from = label(x);
    const Cc_index to = from == a ? b : a;
    double gain = 0.;
    for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
    {
      const Cc_index l = label(m_adj->neighbors[j]);
      if(l == to)
        gain += m_adj->weights[j];
      else if(l == from)
        gain -= m_adj->weights[j];
    }
    return gain;
  }

  // Best of: a Kernighan-Lin sequence of moves between a and b, and joining a and b.
  // Applies it if it improves by more than epsilon; returns the applied gain (or 0).
  double improve_pair(Cc_index a, Cc_index b, Scratch& sc, std::size_t sequence)
  {
    const Cc_index small = m_size[a] <= m_size[b] ? a : b;
    const Cc_index large = small == a ? b : a;
    begin_sequence(sc, sequence);
    double join_gain = 0.;
    for(Cc_index x = m_head[small]; x != none(); x = m_next[x])
      for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
      {
        const Cc_index y = m_adj->neighbors[j];
        if(label(y) != large)
          continue;
        join_gain += m_adj->weights[j];
        add_candidate(x, sc);
        add_candidate(y, sc);
      }
    if(sc.candidates.empty())
      return 0.;

    const std::size_t kept = run_sequence(a, b, sc);
    const double sequence_gain = sc.prefix_gain;
    if(join_gain > sequence_gain && join_gain > m_epsilon)
    {
      undo_moves(0, sc);
      // Splice the list of the small cluster in front of the list of the large one.
      Cc_index last = m_head[small];
      set_label(last, large);
      while(m_next[last] != none())
      {
        last = m_next[last];
        set_label(last, large);
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
      commit_moves(sc);
      return sequence_gain;
    }
    undo_moves(0, sc);
    return 0.;
  }

  // Kernighan-Lin moves from cluster a to a new, empty cluster.
  double split(Cc_index a)
  {
    const Cc_index b = Cc_index(m_head.size());
    m_head.push_back(none());
    m_size.push_back(0);
    m_sequence += 2;
    begin_sequence(m_main, m_sequence);
    for(Cc_index x = m_head[a]; x != none(); x = m_next[x])
      add_candidate(x, m_main);

    const std::size_t kept = run_sequence(a, b, m_main);
    if(kept > 0 && m_main.prefix_gain > m_epsilon)
    {
      commit_moves(m_main);
      return m_main.prefix_gain;
    }
    undo_moves(0, m_main);
    m_head.pop_back();
    m_size.pop_back();
    return 0.;
  }

  // One stamp per node and sequence: 2s means "candidate in sequence s", 2s+1 means
  // "moved in sequence s". One array instead of two saves a cache miss per neighbour.
  void begin_sequence(Scratch& sc, std::size_t sequence) const
  {
    sc.sequence = sequence;
    sc.candidates.clear();
  }

  bool is_candidate(Cc_index x, const Scratch& sc) const { return m_stamp[x] >= sc.sequence; }
  bool is_locked(Cc_index x, const Scratch& sc) const { return m_stamp[x] == sc.sequence + 1; }

  void add_candidate(Cc_index x, Scratch& sc)
  {
    if(!is_candidate(x, sc))
    {
      m_stamp[x] = sc.sequence;
      sc.candidates.push_back(x);
    }
  }

  // Moves greedily the candidate of largest gain (possibly negative) to the other
  // cluster, each node at most once, neighbours of moved nodes becoming candidates; then
  // undoes the moves after the best prefix. Returns the length of that prefix and stores
  // its gain in m_prefix_gain. Only labels change here; member lists are updated by
  // commit_moves() once the caller decides to keep the moves, which makes rejected
  // sequences (the vast majority) cheap.
  std::size_t run_sequence(Cc_index a, Cc_index b, Scratch& sc)
  {
    sc.moves.clear();
    // Most sequences involve a few dozen nodes; for them, a linear scan of the open
    // candidates finds the best move faster than a heap. Long sequences switch to the
    // heap for good as soon as the open candidates outgrow the threshold.
    sc.open.clear();
    bool use_heap = false;
    for(Cc_index x : sc.candidates)
    {
      m_gain[x] = move_gain(x, a, b);
      sc.open.push_back(x);
    }
    if(sc.open.size() > linear_scan_threshold())
      switch_to_heap(use_heap, sc);

    double total = 0.;
    sc.prefix_gain = 0.;
    std::size_t best_length = 0;
    for(;;)
    {
      Cc_index x;
      if(use_heap)
      {
        Lazy_max_heap::Entry top;
        if(!sc.heap.pop(top))
          break;
        x = top.item;
      }
      else
      {
        if(sc.open.empty())
          break;
        std::size_t best = 0;
        for(std::size_t i = 1; i < sc.open.size(); ++i)
        {
          const double gi = m_gain[sc.open[i]], gb = m_gain[sc.open[best]];
          if(gi > gb || (gi == gb && sc.open[i] < sc.open[best]))
            best = i;
        }
        x = sc.open[best];
        sc.open[best] = sc.open.back();
        sc.open.pop_back();
      }

      const Cc_index from = label(x);
      const Cc_index to = from == a ? b : a;
      total += m_gain[x];
      set_label(x, to);
      m_stamp[x] = sc.sequence + 1;
      sc.moves.push_back(Move{x, from});
      if(total > sc.prefix_gain)
      {
        sc.prefix_gain = total;
        best_length = sc.moves.size();
      }
      // Without this bound, a large cluster would be swept entirely for each of its
      // neighbours, which is quadratic when one cluster covers most of the graph.
      if(sc.moves.size() - best_length >= m_moves_without_improvement)
        break;

      for(std::size_t j = m_adj->begin(x); j < m_adj->end(x); ++j)
      {
        const Cc_index y = m_adj->neighbors[j];
        const Cc_index l = label(y);
        if((l != a && l != b) || is_locked(y, sc))
          continue;
        if(!is_candidate(y, sc))
        {
          m_stamp[y] = sc.sequence;
          m_gain[y] = move_gain(y, a, b);
          if(!use_heap)
            sc.open.push_back(y);
        }
        else
        {
          // The edge x-y switched between cut and uncut, for y on either side.
          const double w = 2. * m_adj->weights[j];
          m_gain[y] += (l == from) ? w : -w;
        }
        if(use_heap)
          sc.heap.update(y, m_gain[y]);
      }
      if(!use_heap && sc.open.size() > linear_scan_threshold())
        switch_to_heap(use_heap, sc);
    }
    undo_moves(best_length, sc);
    return best_length;
  }

  void switch_to_heap(bool& use_heap, Scratch& sc)
  {
    sc.heap.clear();
    for(Cc_index x : sc.open)
      sc.heap.update(x, m_gain[x]);
    sc.open.clear();
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

  void undo_moves(std::size_t length, Scratch& sc)
  {
    for(std::size_t i = length; i < sc.moves.size(); ++i)
      set_label(sc.moves[i].node, sc.moves[i].from);
    sc.moves.resize(length);
  }

  // Brings the member lists up to date with the labels after the kept moves.
  void commit_moves(Scratch& sc)
  {
    for(const Move& move : sc.moves)
    {
      unlink(move.node, move.from);
      push_front(move.node, label(move.node));
    }
    sc.moves.clear();
  }

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
  // the sequence numbers used so far (pairs and splits): a node's stamp below the
  // current sequence's is from an earlier one
  std::size_t m_sequence = 0;
  Scratch m_main; // of the calling thread
  bool m_parallel = false;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CORRELATION_CLUSTERING_KERNIGHAN_LIN_WITH_JOINS_IMPL_H
