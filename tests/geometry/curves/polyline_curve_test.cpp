#include "geometry/curves/polyline_curve.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

TEST(PolylineCurve, CyclesAreClosedComponentsAndChainsOpenOnes) {
  // A unit square (edges in any order and direction), an open chain, an isolated point.
  const GroundTruth truth{{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1), Point(5, 5), Point(6, 5), Point(6, 7), Point(9, 9)},
                          {{2, 1}, {4, 5}, {0, 3}, {6, 5}, {1, 0}, {3, 2}}};
  const Curve curve = polyline_curve(truth, "two");
  EXPECT_EQ(curve.name, "two");
  ASSERT_EQ(curve.components.size(), 2u);
  const auto& chain = curve.components[0];
  EXPECT_FALSE(chain.closed());
  EXPECT_EQ(chain.piece_count(), 2u);
  EXPECT_EQ(chain.point(0), Point(5, 5));
  EXPECT_EQ(chain.point(2), Point(6, 7));
  EXPECT_DOUBLE_EQ(chain.length(), 3);
  const auto& square = curve.components[1];
  EXPECT_TRUE(square.closed());
  EXPECT_EQ(square.piece_count(), 4u);
  EXPECT_DOUBLE_EQ(square.length(), 4);
  EXPECT_EQ(square.corners().size(), 4u);
  EXPECT_EQ(square.point(0), Point(0, 0));
  EXPECT_EQ(square.point(1), Point(1, 0));  // towards the lower-indexed neighbour
}

TEST(PolylineCurve, EveryEdgeBecomesOnePieceOfTheSameLength) {
  EXPECT_TRUE(rc::check("a random polygon and path, shuffled", [] {
    const int n = *rc::gen::inRange(3, 30), m = *rc::gen::inRange(2, 30);
    std::vector<Point> points;
    for (int i = 0; i < n + m; ++i) points.emplace_back(i, (i * 7919) % 101);  // distinct points
    std::vector<Edge> edges;
    for (int i = 0; i < n; ++i) edges.emplace_back(i, (i + 1) % n);
    for (int i = n; i + 1 < n + m; ++i) edges.emplace_back(i + 1, i);
    std::vector<Edge> shuffled = edges;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(*rc::gen::arbitrary<unsigned>()));
    const Curve curve = polyline_curve({points, shuffled});
    RC_ASSERT(curve.components.size() == 2u);
    std::size_t pieces = 0;
    for (const auto& c : curve.components) pieces += c.piece_count();
    RC_ASSERT(pieces == edges.size());
    double total = 0;
    for (const auto& [i, j] : edges) total += std::sqrt(CGAL::squared_distance(points[i], points[j]));
    RC_ASSERT(std::abs(curve.length() - total) <= 1e-12 * total);
    RC_ASSERT(testing::valid_curve(curve));
  }));
}

TEST(PolylineCurve, DropsEdgesBetweenCoincidentPoints) {
  const Curve curve = polyline_curve({{Point(0, 0), Point(0, 0), Point(1, 0), Point(3, 3), Point(3, 3)}, {{0, 1}, {1, 2}, {3, 4}}});
  ASSERT_EQ(curve.components.size(), 1u);
  EXPECT_EQ(curve.components[0].piece_count(), 1u);
}

TEST(PolylineCurve, RejectsBranchesRepeatsLoopsAndBadIndices) {
  const std::vector<Point> points{Point(0, 0), Point(1, 0), Point(0, 1), Point(1, 1)};
  for (const auto& edges : std::vector<std::vector<Edge>>{{{0, 1}, {0, 2}, {0, 3}}, {{0, 1}, {1, 0}}, {{2, 2}}, {{0, 4}}}) {
    EXPECT_THROW(polyline_curve({points, edges}), std::invalid_argument);
  }
}

}  // namespace
}  // namespace curvebench::geometry
