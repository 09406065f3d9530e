// graphs/point_kd_tree.h against a brute force over all points in rationals: the nearest
// eligible point by exact squared distance, ties to the smaller index, with and without
// pruned boxes, on random points, grids full of ties, collinear points, clusters packed
// below the floating-point margin, and coordinates near 2^-1000 (where the tree declares
// itself unusable); plus the work limit.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include <CGAL/Gmpq.h>

#include "graphs/point_kd_tree.h"
#include "tests/support/point_generators.h"

namespace curvebench::graphs {
namespace {

using Index = Point_kd_tree::Index;

CGAL::Gmpq squared_distance(const Point& a, const Point& b) {
  const CGAL::Gmpq dx = CGAL::Gmpq(a.x()) - CGAL::Gmpq(b.x()), dy = CGAL::Gmpq(a.y()) - CGAL::Gmpq(b.y());
  return dx * dx + dy * dy;
}

template <class Eligible>
Index brute_force_nearest(const std::vector<Point>& points, Index center, Eligible eligible) {
  Index best = Point_kd_tree::none;
  CGAL::Gmpq best_distance;
  for (Index s = 0; s < points.size(); ++s) {
    if (s == center || !eligible(s)) continue;
    const CGAL::Gmpq d = squared_distance(points[center], points[s]);
    if (best == Point_kd_tree::none || d < best_distance) best = s, best_distance = d;  // ascending: ties keep the smaller
  }
  return best;
}

// Every point's nearest other point, and its nearest point strictly right of x = cut with
// the boxes wholly at or left of the cut pruned, match the brute force: the first point
// where they do not, or none.
std::optional<Index> first_mismatch(const std::vector<Point>& points, double cut) {
  Point_kd_tree tree(points);
  const auto anywhere = [](Index) { return true; };
  const auto nowhere = [](const Kd_box&) { return false; };
  const auto right = [&](Index s) { return points[s].x() > cut; };
  const auto left_of_cut = [&](const Kd_box& box) { return box.xmax <= cut; };
  for (Index rank = 0; rank < points.size(); ++rank) {
    const Index center = tree.leaf_order()[rank];
    if (tree.nearest(rank, anywhere, nowhere) != brute_force_nearest(points, center, anywhere) ||
        tree.nearest(rank, right, left_of_cut) != brute_force_nearest(points, center, right))
      return center;
  }
  return std::nullopt;
}

RC_GTEST_PROP(PointKdTree, MatchesTheBruteForceOnDegenerateInput, ()) {
  const std::vector<Point> points = *testing::point_sets(60);
  RC_PRE(Point_kd_tree::usable(points));
  const double cut = points.empty() ? 0 : points[*rc::gen::inRange<std::size_t>(0, points.size())].x();
  RC_ASSERT(!first_mismatch(points, cut));
}

RC_GTEST_PROP(PointKdTree, MatchesTheBruteForceOnClusteredInput, ()) {
  const std::vector<Point> points = *testing::clustered_points();
  RC_ASSERT(!first_mismatch(points, points.empty() ? 0 : points[0].x()));
}

// A cluster whose squared distances underflow (spacing 2^-600) beside a point at distance
// 1: the tree is usable, but inside the cluster only the exact ranking separates points.
TEST(PointKdTree, RanksPointsPackedBelowTheMarginExactly) {
  std::vector<Point> points{{1, 0}};
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) points.emplace_back(std::ldexp(i + 0.25 * j, -600), std::ldexp(j + 0.1 * i, -600));
  ASSERT_TRUE(Point_kd_tree::usable(points));
  EXPECT_EQ(first_mismatch(points, std::ldexp(3.0, -600)), std::nullopt);
}

TEST(PointKdTree, DeclaresExtremeCoordinatesUnusable) {
  EXPECT_TRUE(Point_kd_tree::usable(std::vector<Point>{{0, 0}, {1, 1}}));
  EXPECT_FALSE(Point_kd_tree::usable(std::vector<Point>{{0, 0}, {std::ldexp(1.0, 401), 1}}));
  EXPECT_FALSE(Point_kd_tree::usable(std::vector<Point>{{0, 0}, {std::ldexp(1.0, -401), 0}}));
}

TEST(PointKdTree, GivesUpBeyondItsWorkLimit) {
  std::vector<Point> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(std::cos(i), std::sin(i * 1.5));
  Point_kd_tree tree(points);
  const auto anywhere = [](Index) { return true; };
  const auto nowhere = [](const Kd_box&) { return false; };
  EXPECT_TRUE(tree.nearest(0, anywhere, nowhere).has_value());
  tree.set_work_limit(0);
  EXPECT_FALSE(tree.nearest(0, anywhere, nowhere).has_value());
}

TEST(PointKdTree, HandlesNoAndOnePoint) {
  const std::vector<Point> one{{2, 3}};
  Point_kd_tree tree(one);
  EXPECT_EQ(tree.nearest(0, [](Index) { return true; }, [](const Kd_box&) { return false; }), Point_kd_tree::none);
  EXPECT_TRUE(Point_kd_tree(std::vector<Point>{}).leaf_order().empty());
}

}  // namespace
}  // namespace curvebench::graphs
