// The outlier pre-filter (algorithms/outlier_filter.h): against a brute force of its rule
// in rationals (all pairwise distances, sorted); against circles with outliers whose
// answer is known (every outlier far from the curve dropped, every sample kept, also for
// non-uniform samplings and open curves); through the registry as NAME+outlier-filter.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "algorithms/outlier_filter.h"
#include "algorithms/registry.h"
#include "tests/support/edge_sets.h"
#include "tests/support/point_generators.h"

namespace curvebench::algorithms {
namespace {

using Q = CGAL::Gmpq;

Q squared_distance(const Point& a, const Point& b) {
  const Q dx = Q(a.x()) - Q(b.x()), dy = Q(a.y()) - Q(b.y());
  return dx * dx + dy * dy;
}

std::vector<std::size_t> brute_force_inliers(const std::vector<Point>& points, std::size_t k, double factor) {
  const std::size_t n = points.size();
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), 0);
  if (n <= k) return all;
  std::vector<Q> r2(n);
  for (std::size_t p = 0; p < n; ++p) {
    std::vector<Q> distances;
    for (std::size_t q = 0; q < n; ++q)
      if (q != p) distances.push_back(squared_distance(points[p], points[q]));
    std::sort(distances.begin(), distances.end());
    r2[p] = distances[k - 1];
  }
  std::vector<Q> sorted = r2;
  std::sort(sorted.begin(), sorted.end());
  const Q median = sorted[(n - 1) / 2];
  std::vector<std::size_t> kept;
  for (std::size_t p = 0; p < n; ++p)
    if (!(r2[p] > Q(factor) * Q(factor) * median)) kept.push_back(p);
  return kept;
}

std::vector<Point> circle(std::size_t n, double radius = 1, double warp = 0) {
  std::vector<Point> points;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / static_cast<double>(n);
    const double t = 2 * std::numbers::pi * (u + warp * std::sin(2 * std::numbers::pi * u) / (2 * std::numbers::pi));
    points.emplace_back(radius * std::cos(t), radius * std::sin(t));
  }
  return points;
}

// Points at least `clearance` from the unit circle, uniform in its bounding box as the
// survey's outliers are (geometry/sampling/sampling_noise.h); nearer ones are noise, not outliers.
std::vector<Point> far_outliers(std::size_t count, double clearance, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> anywhere(-1, 1);
  std::vector<Point> points;
  while (points.size() < count) {
    const Point p(anywhere(random), anywhere(random));
    if (std::abs(std::hypot(p.x(), p.y()) - 1) > clearance) points.push_back(p);
  }
  return points;
}

RC_GTEST_PROP(OutlierFilter, EqualsTheBruteForceOfItsRule, ()) {
  const auto points = *testing::point_sets(30);
  const std::size_t k = *rc::gen::inRange<std::size_t>(1, 5);
  const double factor = *rc::gen::element(1.0, 1.5, 2.0, 3.0, 10.0);
  RC_ASSERT(inlier_indices(points, {.neighbors = k, .factor = factor}) == brute_force_inliers(points, k, factor));
}

TEST(OutlierFilter, DropsFarOutliersAndKeepsEverySample) {
  for (const double warp : {0.0, 0.3}) {  // uniform, and spacing varying 2:1 along the circle
    auto points = circle(400, 1, warp);
    const auto outliers = far_outliers(40, 0.2, 3);  // 10%
    points.insert(points.end(), outliers.begin(), outliers.end());
    std::vector<std::size_t> samples(400);
    std::iota(samples.begin(), samples.end(), 0);
    const auto kept = inlier_indices(points);
    EXPECT_TRUE(std::includes(kept.begin(), kept.end(), samples.begin(), samples.end())) << "warp " << warp;
    // A clump of more than k outliers within factor * R of each other reads as dense:
    // with these 40, one clump of 5 (seed 3); every other outlier must go.
    EXPECT_LE(kept.size(), samples.size() + 1) << "warp " << warp << ": " << ::testing::PrintToString(kept);
  }
}

TEST(OutlierFilter, KeepsTheEndsOfAnOpenCurve) {
  std::vector<Point> arc;
  for (int i = 0; i <= 100; ++i) arc.emplace_back(i * 0.01, std::sin(i * 0.03));
  EXPECT_EQ(inlier_indices(arc).size(), arc.size());
}

TEST(OutlierFilter, KeepsSmallInputAndChecksItsOptions) {
  const std::vector<Point> three{{0, 0}, {1, 0}, {1e300, 0}};
  EXPECT_EQ(inlier_indices(three, {.neighbors = 3}).size(), 3u) << "at most k points: nothing to compare with";
  EXPECT_THROW(inlier_indices(three, {.neighbors = 0}), std::invalid_argument);
  EXPECT_THROW(inlier_indices(three, {.factor = 0.5}), std::invalid_argument);
  EXPECT_THROW(inlier_indices(std::vector<Point>{{0, 0}, {0, 0}, {1, 1}, {2, 2}, {3, 5}, {7, 1}}, {.neighbors = 1}),
               std::invalid_argument);
}

TEST(OutlierFilter, LetsAnInterpolatingAlgorithmReconstructACircleAmongOutliers) {
  const Algorithm* plain = find_algorithm("nn-crust");
  const Algorithm* filtered = find_algorithm("nn-crust+outlier-filter");
  ASSERT_NE(filtered, nullptr);
  EXPECT_EQ(find_algorithm("nn-crust+outlier-filter"), filtered) << "built once";
  EXPECT_EQ(find_algorithm("no-such+outlier-filter"), nullptr);
  EXPECT_EQ(find_algorithm("nn-crust+outlier-filter+outlier-filter"), nullptr) << "one filter is enough";
  EXPECT_EQ(filtered->title, "NN-Crust + outlier filter");
  EXPECT_EQ(filtered->name, "nn-crust+outlier-filter");
  EXPECT_EQ(filtered->capabilities.outliers, Support::yes);

  auto points = circle(300);
  const auto outliers = far_outliers(30, 0.2, 9);
  points.insert(points.end(), outliers.begin(), outliers.end());
  const Reconstruction result = reconstruct(*filtered, points);
  ASSERT_EQ(result.points.size(), 300u);
  EXPECT_TRUE(std::equal(result.points.begin(), result.points.end(), points.begin()));
  EXPECT_EQ(result.edges, testing::cycle_edges(300));
  EXPECT_NE(reconstruct(*plain, points).edges, testing::cycle_edges(300)) << "the outliers do hurt without it";
  EXPECT_THROW(reconstruct(*filtered, points, {{"outlier_factor", 0.5}}), std::invalid_argument);
  EXPECT_NO_THROW(reconstruct(*filtered, points, {{"outlier_neighbors", 8}, {"outlier_factor", 2}}));
}

}  // namespace
}  // namespace curvebench::algorithms
