// canonical_edges against its definition: the set of edges {min, max}, in order. Two
// paths decide how it sorts (a counting sort for point indices, std::sort for sparse
// ones), so the properties draw both.
#include <limits>
#include <set>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "geometry/edge.h"

namespace curvebench::geometry {
namespace {

// The oracle: an ordered set of (min, max) pairs.
std::vector<Edge> as_ordered_set(const std::vector<Edge>& edges) {
  std::set<Edge> set;
  for (const auto& [i, j] : edges) set.emplace(std::min(i, j), std::max(i, j));
  return {set.begin(), set.end()};
}

TEST(CanonicalEdges, EmptyStaysEmpty) { EXPECT_TRUE(canonical_edges({}).empty()); }

TEST(CanonicalEdges, AStarFromTheLastPointAndALoop) {
  // Every edge in one counting bucket, reversed, with a repeat; and the self-loop (0, 0).
  std::vector<Edge> star;
  for (std::size_t i = 0; i < 50; ++i) star.emplace_back(50, 49 - i);
  star.emplace_back(3, 50);
  star.emplace_back(0, 0);
  EXPECT_EQ(canonical_edges(star), as_ordered_set(star));
}

RC_GTEST_PROP(CanonicalEdges, IsTheOrderedSetOfMinMaxPairs, ()) {
  // Indices up to about 6 times the number of edges: both sides of the counting sort's
  // bound (largest index / 4 < number of edges).
  const auto count = *rc::gen::inRange<std::size_t>(0, 300);
  const auto largest = *rc::gen::inRange<std::size_t>(0, 6 * count + 10);
  const auto index = rc::gen::inRange<std::size_t>(0, largest + 1);
  const auto edges = *rc::gen::container<std::vector<Edge>>(count, rc::gen::pair(index, index));
  RC_ASSERT(canonical_edges(edges) == as_ordered_set(edges));
}

RC_GTEST_PROP(CanonicalEdges, HugeIndicesSortToo, ()) {
  const auto index = rc::gen::inRange<std::size_t>(std::numeric_limits<std::size_t>::max() - 20,
                                                   std::numeric_limits<std::size_t>::max());
  const auto edges = *rc::gen::container<std::vector<Edge>>(rc::gen::pair(index, rc::gen::arbitrary<std::size_t>()));
  RC_ASSERT(canonical_edges(edges) == as_ordered_set(edges));
}

}  // namespace
}  // namespace curvebench::geometry
