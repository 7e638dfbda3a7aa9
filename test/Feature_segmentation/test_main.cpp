// The Boost.Test entry point of the single test executable; suites live in test_*.cpp.
#define BOOST_TEST_MODULE Feature_segmentation
#include <boost/test/unit_test.hpp>
