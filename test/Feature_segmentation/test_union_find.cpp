// The disjoint sets of internal/union_find.h, which number the crease cut's sectors and
// the faces' components: roots are the smallest index of each set, whatever the order of
// the unions.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/union_find.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace FSI = CGAL::Feature_segmentation::internal;

BOOST_AUTO_TEST_SUITE(union_find)

// Ten indices, sets {0, 3, 7}, {1, 9}, {2, 4, 5, 8} and {6}: every order of the same
// unions gives the roots 0, 1, 2, 0, 2, 2, 6, 0, 2, 1.
BOOST_AUTO_TEST_CASE(roots_are_the_smallest_index_of_each_set)
{
  std::vector<std::pair<std::size_t, std::size_t> > unions = { { 7, 3 }, { 3, 0 }, { 9, 1 }, { 8, 5 },
                                                               { 4, 8 }, { 2, 5 }, { 5, 4 } };
  const std::vector<std::size_t> expected = { 0, 1, 2, 0, 2, 2, 6, 0, 2, 1 };
  std::sort(unions.begin(), unions.end());
  int orders = 0;
  do
  {
    FSI::Smallest_root_union_find sets(10);
    for(const auto& u : unions) sets.unite(u.first, u.second);
    BOOST_TEST(sets.find(8) == 2u);
    BOOST_TEST(sets.roots() == expected, boost::test_tools::per_element());
    ++orders;
  } while(std::next_permutation(unions.begin(), unions.end()) && orders < 5040);
  BOOST_TEST(orders == 5040); // 7! orders of the seven unions
}

BOOST_AUTO_TEST_SUITE_END()
