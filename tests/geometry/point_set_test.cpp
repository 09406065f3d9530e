#include "geometry/point_set.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace curvebench::geometry {
namespace {

TEST(PointSet, EmptyInputGivesEmptySet) {
  const PointSet set(std::vector<Point>{});
  EXPECT_TRUE(set.empty());
  EXPECT_EQ(set.input_size(), 0u);
  EXPECT_TRUE(set.duplicates().empty());
}

TEST(PointSet, NegativeZeroIsTheSamePointAsZeroAndTheFirstOccurrenceIsKept) {
  const PointSet set({Point(-0.0, 1), Point(2, 3), Point(0.0, 1), Point(-0.0, 1)});
  ASSERT_EQ(set.size(), 2u);
  EXPECT_TRUE(std::signbit(set[0].x())) << "the first occurrence (-0.0) is the one kept";
  EXPECT_EQ(set.kept_index(2), 0u);
  EXPECT_EQ(set.kept_index(3), 0u);
  ASSERT_EQ(set.duplicates().size(), 2u);
  EXPECT_EQ(set.duplicates()[0].input_index, 2u);
  EXPECT_EQ(set.duplicates()[0].first_input_index, 0u);
  EXPECT_EQ(set.duplicates()[1].input_index, 3u);
}

TEST(PointSet, RejectsNanAndInfinity) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(PointSet({Point(0, 0), Point(nan, 0)}), std::invalid_argument);
  EXPECT_THROW(PointSet({Point(0, -inf)}), std::invalid_argument);
}

// Coordinates from a 3 x 3 grid that includes -0.0, so that random inputs are full of
// duplicates, some of which differ only in the sign of zero.
rc::Gen<std::vector<Point>> points_on_a_tiny_grid() {
  const auto coordinate = rc::gen::element(-0.0, 0.0, 1.0, 2.5);
  return rc::gen::container<std::vector<Point>>(rc::gen::construct<Point>(coordinate, coordinate));
}

RC_GTEST_PROP(PointSet, AgreesWithBruteForceDeduplication, ()) {
  const std::vector<Point> input = *points_on_a_tiny_grid();
  const PointSet set(input);

  // Oracle, O(n^2): the first j with the same coordinates (== treats -0.0 as 0.0).
  std::vector<std::size_t> first(input.size());
  std::vector<Point> kept;
  std::vector<Duplicate> duplicates;
  for (std::size_t i = 0; i < input.size(); ++i) {
    first[i] = i;
    for (std::size_t j = 0; j < i; ++j) {
      if (input[j].x() == input[i].x() && input[j].y() == input[i].y()) {
        first[i] = j;
        break;
      }
    }
    if (first[i] == i)
      kept.push_back(input[i]);
    else
      duplicates.push_back({i, first[i]});
  }

  RC_ASSERT(set.input_size() == input.size());
  RC_ASSERT(set.size() == kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) {
    RC_ASSERT(set[k] == kept[k]);
    RC_ASSERT(std::signbit(set[k].x()) ==
              std::signbit(kept[k].x()));  // the first occurrence's bits
    RC_ASSERT(std::signbit(set[k].y()) == std::signbit(kept[k].y()));
  }
  for (std::size_t i = 0; i < input.size(); ++i) {
    RC_ASSERT(set[set.kept_index(i)] == input[i]);
    RC_ASSERT(set.input_index(set.kept_index(i)) == first[i]);
  }
  RC_ASSERT(set.duplicates().size() == duplicates.size());
  for (std::size_t d = 0; d < duplicates.size(); ++d) {
    RC_ASSERT(set.duplicates()[d].input_index == duplicates[d].input_index);
    RC_ASSERT(set.duplicates()[d].first_input_index == duplicates[d].first_input_index);
  }
}

}  // namespace
}  // namespace curvebench::geometry
