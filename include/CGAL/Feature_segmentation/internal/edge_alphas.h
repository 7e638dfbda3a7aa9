// SPDX-License-Identifier: GPL-3.0-or-later
// The per-edge parameters alpha_e of an edit state, shared between states without
// copies. A global alpha edit moves the alpha_e of every feature edge by the same
// amount; stored so, it would rewrite one double per edge. Here a feature edge stores
// its alpha_e at the base alpha (that of the construction) and reads the stored value
// plus (alpha - base); another edge reads its stored value. So a global edit changes
// nothing stored (the state only holds a new alpha), and a global edit back to an
// earlier alpha gives back every alpha_e to the last bit. A value written at another
// alpha than the base is stored as value - (alpha - base): it reads back to within
// rounding (exactly at the base alpha).
//
// The values are kept in chunks of 4096 edges. Copies share everything (one
// shared_ptr). A write copies the table of chunk pointers (one pointer per 4096 edges)
// the first time a copy writes, and a chunk the first time it writes into it. Tables
// and chunks shared with another copy are never written, so published states stay
// immutable.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_EDGE_ALPHAS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_EDGE_ALPHAS_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

class Edge_alphas
{
public:
  static constexpr std::size_t chunk_bits = 12;
  static constexpr std::size_t chunk_size = std::size_t(1) << chunk_bits;

  Edge_alphas() : m_table(std::make_shared<Table>()) {}

  // `values[e]` is the alpha_e of edge e at the global alpha `base`.
  Edge_alphas(const std::vector<double>& values, double base)
    : m_table(std::make_shared<Table>()), m_size(values.size()), m_base(base)
  {
    m_table->reserve((m_size + chunk_size - 1) / chunk_size);
    for(std::size_t b = 0; b < m_size; b += chunk_size)
      m_table->push_back(std::make_shared<Chunk>(values.begin() + b, values.begin() + (std::min)(m_size, b + chunk_size)));
  }

  std::size_t size() const { return m_size; }
  double base() const { return m_base; }

  // The alpha_e of edge `e` when the global alpha is `alpha`; `feature` tells whether
  // `e` is a feature edge (whose alpha_e follows the global alpha).
  double operator()(std::size_t e, bool feature, double alpha) const
  {
    CGAL_precondition(e < m_size);
    const double v = (*(*m_table)[e >> chunk_bits])[e & (chunk_size - 1)];
    return (feature && alpha != m_base) ? v + (alpha - m_base) : v;
  }

  // Sets the alpha_e of edge `e`, a feature edge or not (after the write), to `value`
  // at the global alpha `alpha`.
  void set(std::size_t e, double value, bool feature, double alpha)
  {
    CGAL_precondition(e < m_size);
    if(m_table.use_count() > 1) m_table = std::make_shared<Table>(*m_table);
    std::shared_ptr<Chunk>& c = (*m_table)[e >> chunk_bits];
    if(c.use_count() > 1) c = std::make_shared<Chunk>(*c);
    (*c)[e & (chunk_size - 1)] = (feature && alpha != m_base) ? value - (alpha - m_base) : value;
  }

  // Calls part(pointer, bytes) for the table; if it returns true (a part not seen
  // before), for every chunk too. Two copies with the same table have the same chunks.
  template <typename Part>
  void for_each_part(Part part) const
  {
    if(!part(static_cast<const void*>(m_table.get()), m_table->capacity() * sizeof(std::shared_ptr<Chunk>)))
      return;
    for(const std::shared_ptr<Chunk>& c : *m_table)
      part(static_cast<const void*>(c.get()), c->capacity() * sizeof(double));
  }

private:
  typedef std::vector<double> Chunk;
  typedef std::vector<std::shared_ptr<Chunk> > Table;

  std::shared_ptr<Table> m_table;
  std::size_t m_size = 0;
  double m_base = 0;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_EDGE_ALPHAS_H
