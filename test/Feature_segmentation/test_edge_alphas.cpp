// The per-edge alpha_e of the edit states (internal/edge_alphas.h): a global alpha
// moves the feature edges' values without writing them, a value written reads back
// (exactly at the base alpha), and copies share every chunk they do not write.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/edge_alphas.h>

#include <cstddef>
#include <set>
#include <vector>

namespace FSI = CGAL::Feature_segmentation::internal;

namespace {

// 10,000 edges: three chunks (4096, 4096, 1808); every third edge is a feature edge
// with alpha_e = alpha = 0.6, the others 0 but for edge 7 (0.25, a user's value).
const std::size_t n = 10000;
bool feature(std::size_t e) { return e % 3 == 0; }
std::vector<double> initial()
{
  std::vector<double> v(n, 0.);
  for(std::size_t e = 0; e < n; e += 3) v[e] = 0.6;
  v[7] = 0.25;
  return v;
}

// The parts of `a` and `b` (pointers), each once.
std::set<const void*> parts(const FSI::Edge_alphas& a, const FSI::Edge_alphas& b)
{
  std::set<const void*> seen;
  auto add = [&](const void* p, std::size_t) { return seen.insert(p).second; };
  a.for_each_part(add);
  b.for_each_part(add);
  return seen;
}

} // namespace

BOOST_AUTO_TEST_SUITE(edge_alphas)

BOOST_AUTO_TEST_CASE(values_follow_the_global_alpha_on_feature_edges)
{
  const std::vector<double> v = initial();
  const FSI::Edge_alphas a(v, 0.6);
  BOOST_TEST(a.size() == n);
  BOOST_TEST(a.base() == 0.6);
  for(std::size_t e = 0; e < n; ++e)
  {
    // at the base alpha, the values read back exactly
    BOOST_TEST(a(e, feature(e), 0.6) == v[e]);
    // at another alpha, a feature edge moves by the difference, another edge stays
    BOOST_TEST(a(e, feature(e), 1.1) == (feature(e) ? 0.6 + (1.1 - 0.6) : v[e]));
  }
  BOOST_TEST(a(7, false, 1.1) == 0.25);
}

BOOST_AUTO_TEST_CASE(a_write_copies_one_chunk)
{
  const std::vector<double> v = initial();
  const FSI::Edge_alphas a(v, 0.6);
  FSI::Edge_alphas b = a;
  // a copy shares the table: one table and three chunks for the two
  BOOST_TEST(parts(a, b).size() == 4u);
  // at the base alpha, edge 5000 (chunk 1) becomes a feature edge with alpha_e 2
  b.set(5000, 2.0, true, 0.6);
  BOOST_TEST(b(5000, true, 0.6) == 2.0);
  BOOST_TEST(b(5000, true, 1.1) == 2.0 + (1.1 - 0.6));
  // b has its own table and its own chunk 1, and shares chunks 0 and 2:
  // two tables, the three chunks of a, the new chunk 1
  BOOST_TEST(parts(a, b).size() == 6u);
  // written at alpha 1.1: stored at the base alpha, so it moves with alpha too
  b.set(4098, 0.75, true, 1.1);
  BOOST_TEST(b(4098, true, 1.1) == (0.75 - (1.1 - 0.6)) + (1.1 - 0.6));
  BOOST_TEST(b(4098, true, 0.6) == 0.75 - (1.1 - 0.6));
  // a non-feature edge keeps the value written, at any alpha
  b.set(4097, 0.5, false, 1.1);
  BOOST_TEST(b(4097, false, 0.6) == 0.5);
  // a second and third write into the same chunk copy nothing more
  BOOST_TEST(parts(a, b).size() == 6u);
  // every other edge reads what `a` reads, and `a` is unchanged
  for(std::size_t e = 0; e < n; ++e)
  {
    BOOST_TEST(a(e, feature(e), 0.6) == v[e]);
    if(e != 5000 && e != 4098 && e != 4097) BOOST_TEST(b(e, feature(e), 1.1) == a(e, feature(e), 1.1));
  }
  // a write into chunk 2 copies that chunk only (b's table is its own already)
  b.set(9999, 1.0, true, 0.6);
  BOOST_TEST(parts(a, b).size() == 7u);
}

BOOST_AUTO_TEST_CASE(an_empty_array)
{
  const FSI::Edge_alphas a(std::vector<double>(), 0.6);
  BOOST_TEST(a.size() == 0u);
  std::size_t bytes = 0, count = 0;
  a.for_each_part([&](const void*, std::size_t b) { bytes += b; ++count; return true; });
  BOOST_TEST(count == 1u); // the table, empty
  BOOST_TEST(bytes == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
