#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>

#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/corner_curve.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/sampling_noise.h"
#include "geometry/sampling/seeded_random.h"
#include "tests/support/even_in_range.h"

namespace curvebench::geometry {
namespace {

double distance(const Point& p, const Point& q) { return std::sqrt(CGAL::squared_distance(p, q)); }
double radius(const Point& p) { return std::hypot(p.x(), p.y()); }

// The bits of every coordinate: "the same seed gives the same bytes".
std::vector<std::uint64_t> bits(const Sample& sample) {
  std::vector<std::uint64_t> all;
  for (const Point& p : sample.points) all.insert(all.end(), {std::bit_cast<std::uint64_t>(p.x()), std::bit_cast<std::uint64_t>(p.y())});
  return all;
}

// Chain edges along each component, closing edges for closed ones, and per-point data
// of the right sizes: the shape every sampler promises.
void expect_ground_truth(const Sample& sample, const Curve& curve) {
  ASSERT_EQ(sample.lfs.size(), sample.size());
  ASSERT_EQ(sample.locations.size(), sample.size());
  ASSERT_EQ(sample.labels.size(), sample.size());
  std::size_t first = 0, edge = 0;
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    std::size_t last = first;
    while (last < sample.size() && sample.locations[last].component == c) ++last;
    for (std::size_t i = first; i < last; ++i) {
      EXPECT_LT(distance(sample.points[i], curve.components[c].point(sample.locations[i].parameter)), 1e-12);
      if (i + 1 < last) {
        ASSERT_LT(edge, sample.edges.size());
        EXPECT_EQ(sample.edges[edge++], Edge(i, i + 1));
        EXPECT_LT(sample.locations[i].parameter, sample.locations[i + 1].parameter);
      }
    }
    if (curve.components[c].closed() && last - first >= 3) {
      EXPECT_EQ(sample.edges.at(edge++), Edge(last - 1, first));
    }
    first = last;
  }
  EXPECT_EQ(first, sample.size());
  EXPECT_EQ(edge, sample.edges.size());
}

TEST(SeededRandom, MapsTheStandardMersenneTwisterTo53Bits) {
  // The C++ standard fixes the 10000th output of a default-seeded std::mt19937_64.
  Seeded_random random(5489);
  for (int i = 1; i < 10000; ++i) random.uniform();
  EXPECT_EQ(random.uniform(), static_cast<double>(9981545732273789042ull >> 11) * 0x1.0p-53);
}

TEST(EpsilonSampling, StepsAlongACircleByChordsOfEpsilonTimesTheRadius) {
  const double r = 2;
  const Local_feature_size lfs(circle(r));
  for (const double epsilon : {0.1, 0.3, 0.5, 0.9}) {
    const Sample sample = epsilon_sampling(lfs, epsilon, default_minimum_lfs(lfs));
    expect_ground_truth(sample, lfs.curve());
    // The walk's steps: chord epsilon r, i.e. angle 2 asin(epsilon / 2); the last edge closes.
    const double step = 2 * std::asin(epsilon / 2);
    EXPECT_EQ(sample.size(), static_cast<std::size_t>(std::floor(2 * std::numbers::pi / step)) + 1);
    for (std::size_t e = 0; e + 1 < sample.edges.size(); ++e)
      EXPECT_NEAR(distance(sample.points[sample.edges[e].first], sample.points[sample.edges[e].second]), epsilon * r, 1e-9);
    EXPECT_LE(distance(sample.points[sample.edges.back().first], sample.points[sample.edges.back().second]), epsilon * r);
    for (const double l : sample.lfs) EXPECT_NEAR(l, r, 1e-9);
    EXPECT_TRUE(sample.floored.empty());
  }
}

TEST(RhoSampling, StepsAlongACircleByHalfChordsOfRhoTimesTheRadius) {
  const Local_feature_size lfs(circle(3));
  for (const double rho : {0.2, 0.45, 0.9}) {  // not 0.5: 2 pi is then exactly 6 steps, a tie
    const Sample sample = rho_sampling(lfs, rho, default_minimum_lfs(lfs));
    expect_ground_truth(sample, lfs.curve());
    EXPECT_EQ(sample.size(), static_cast<std::size_t>(std::floor(std::numbers::pi / std::asin(rho))) + 1);
    for (std::size_t e = 0; e + 1 < sample.edges.size(); ++e)
      EXPECT_NEAR(distance(sample.points[sample.edges[e].first], sample.points[sample.edges[e].second]) / 2, rho * 3, 1e-9);
  }
}

TEST(EpsilonSampling, PutsASampleOnTheCornerAndReportsWhereTheFloorWasHit) {
  const Local_feature_size lfs(sharp_corner_curve(30));
  const double floor = default_minimum_lfs(lfs);
  for (const auto& sampler : {epsilon_sampling, safe_epsilon_sampling, rho_sampling}) {
    const Sample sample = sampler(lfs, 0.4, floor);
    expect_ground_truth(sample, lfs.curve());
    EXPECT_EQ(sample.locations[0], (Curve_location{0, 0.0}));  // the apex
    EXPECT_EQ(sample.lfs[0], 0);
    EXPECT_EQ(sample.minimum_lfs, floor);
    ASSERT_FALSE(sample.floored.empty());
    EXPECT_EQ(sample.floored[0], 0u);
    for (std::size_t i = 0; i < sample.size(); ++i)
      EXPECT_EQ(std::find(sample.floored.begin(), sample.floored.end(), i) != sample.floored.end(), sample.lfs[i] < floor);
  }
}

// The crossing convention: one shared sample per crossing, of degree 4 in the ground truth,
// where the Lissajous figure's closed form puts 2ab - a - b crossings.
TEST(CrossingSamples, AddOneSharedPointOfDegreeFourPerCrossing) {
  for (const auto& [a, b] : {std::pair{1, 2}, {2, 3}}) {
    const Local_feature_size lfs(lissajous_curve(a, b, 1));
    const Sample plain = safe_epsilon_sampling(lfs, 0.3, default_minimum_lfs(lfs));
    const Sample crossed = with_crossing_samples(lfs, plain);
    const std::size_t crossings = static_cast<std::size_t>(lissajous_crossings(a, b));
    ASSERT_EQ(crossed.size(), plain.size() + crossings);
    ASSERT_EQ(crossed.edges.size(), plain.edges.size() + 2 * crossings);  // each splits an edge on both branches
    std::vector<int> degree(crossed.size());
    for (const Edge& e : crossed.edges) ++degree[e.first], ++degree[e.second];
    std::size_t fours = 0;
    for (std::size_t i = 0; i < crossed.size(); ++i) {
      ASSERT_TRUE(degree[i] == 2 || degree[i] == 4) << i;
      if (degree[i] != 4) continue;
      ++fours;
      EXPECT_EQ(crossed.lfs[i], 0);
      // On the curve at both of its branches: two parameters of the one component give it.
      const Curve_component& component = lfs.curve().components[0];
      EXPECT_LT(distance(crossed.points[i], component.point(crossed.locations[i].parameter)), 1e-9);
    }
    EXPECT_EQ(fours, crossings);
    // Every other point is one of the sampler's, unchanged.
    for (const Point& p : plain.points) EXPECT_NE(std::find(crossed.points.begin(), crossed.points.end(), p), crossed.points.end());
  }
  const Local_feature_size circle_lfs(circle(1));  // no crossing: the sample as it was
  const Sample circle_sample = safe_epsilon_sampling(circle_lfs, 0.3, default_minimum_lfs(circle_lfs));
  EXPECT_EQ(with_crossing_samples(circle_lfs, circle_sample).points, circle_sample.points);
}

TEST(EpsilonSampling, OfAStraightSegmentIsItsEnds) {
  Curve segment{"segment", {}};
  segment.components.emplace_back(
      std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Line_segment>(Point(0, 0), Point(3, 4))}, false);
  const Local_feature_size lfs(segment);
  const Sample sample = epsilon_sampling(lfs, 0.3, 0.01);
  ASSERT_EQ(sample.size(), 2u);
  EXPECT_EQ(sample.points[1], Point(3, 4));
  EXPECT_EQ(sample.edges, (std::vector<Edge>{{0, 1}}));
}

TEST(EpsilonSampling, RejectsANonPositiveTargetOrFloor) {
  const Local_feature_size lfs(circle(1));
  EXPECT_THROW(epsilon_sampling(lfs, 0, 0.01), std::invalid_argument);
  EXPECT_THROW(safe_epsilon_sampling(lfs, 0.3, 0), std::invalid_argument);
  EXPECT_THROW(rho_sampling(lfs, -1, 0.01), std::invalid_argument);
}

Curve two_circles() {
  Curve curve = circle(1);
  curve.components.push_back(Curve_component(
      {std::make_shared<Circular_arc>(Point(5, 0), 2, 0, 2 * std::numbers::pi)}, true));
  return curve;
}

TEST(UniformSampling, SharesPointsByLengthAtEqualSteps) {
  const Local_feature_size lfs(two_circles());
  // 9 points: 1 each, then 7 by length (1 : 2): 2.33 and 4.67, the larger remainder first.
  const Sample sample = uniform_sampling(lfs, 9);
  expect_ground_truth(sample, lfs.curve());
  ASSERT_EQ(sample.size(), 9u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(distance(sample.points[i], Point(std::cos(2 * std::numbers::pi * i / 3), std::sin(2 * std::numbers::pi * i / 3))), 0, 1e-9);
  for (std::size_t i = 3; i < 9; ++i) {
    const double angle = 2 * std::numbers::pi * (i - 3) / 6;
    EXPECT_NEAR(distance(sample.points[i], Point(5 + 2 * std::cos(angle), 2 * std::sin(angle))), 0, 1e-9);
  }
  EXPECT_THROW(uniform_sampling(lfs, 1), std::invalid_argument);
}

TEST(UniformSampling, OfAnOpenCurveIncludesBothEnds) {
  Curve arc{"arc", {}};
  arc.components.emplace_back(std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Circular_arc>(Point(0, 0), 1, 0, std::numbers::pi)}, false);
  const Local_feature_size lfs(arc);
  const Sample sample = uniform_sampling(lfs, 5);
  expect_ground_truth(sample, arc);
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_NEAR(distance(sample.points[i], Point(std::cos(std::numbers::pi * i / 4), std::sin(std::numbers::pi * i / 4))), 0, 1e-9);
  EXPECT_EQ(uniform_sampling_with_spacing(lfs, std::numbers::pi / 4 + 1e-9).size(), 5u);
}

TEST(UniformSampling, WithSpacingTakesTheFewestEqualSteps) {
  const Local_feature_size lfs(circle(1));
  EXPECT_EQ(uniform_sampling_with_spacing(lfs, 1).size(), 7u);  // ceil(2 pi)
  EXPECT_THROW(uniform_sampling_with_spacing(lfs, 0), std::invalid_argument);
}

TEST(RandomSampling, IsUniformInArcLengthAndReproducible) {
  const Local_feature_size lfs(two_circles());
  const Sample sample = random_sampling(lfs, 3000, 42);
  expect_ground_truth(sample, lfs.curve());
  EXPECT_EQ(bits(sample), bits(random_sampling(lfs, 3000, 42)));
  EXPECT_NE(bits(sample), bits(random_sampling(lfs, 3000, 43)));
  // The second circle has 2/3 of the length; binomial standard deviation ~ 26 points.
  const auto on_second = std::count_if(sample.locations.begin(), sample.locations.end(),
                                       [](const Curve_location& l) { return l.component == 1; });
  EXPECT_NEAR(static_cast<double>(on_second), 2000, 130);
}

TEST(UniformNoise, MovesEachCurvePointAtMostDeltaDiagonals) {
  const Local_feature_size lfs(circle(1));
  const Sample clean = uniform_sampling(lfs, 400);
  const Sample noisy = with_uniform_noise(clean, 0.01, 7);
  const double diagonal = 2 * std::sqrt(2.0);  // the curve points' bounding box: [-1, 1]²
  double largest = 0;
  for (std::size_t i = 0; i < clean.size(); ++i) largest = std::max(largest, distance(clean.points[i], noisy.points[i]));
  EXPECT_LE(largest, 0.01 * diagonal * (1 + 1e-9));
  EXPECT_GT(largest, 0.009 * diagonal);  // 400 uniform draws: the largest is near the top
  EXPECT_EQ(noisy.edges, clean.edges);
  EXPECT_EQ(noisy.lfs, clean.lfs);
  EXPECT_EQ(bits(noisy), bits(with_uniform_noise(clean, 0.01, 7)));
  EXPECT_THROW(with_uniform_noise(clean, -1, 7), std::invalid_argument);
}

TEST(LfsNoise, MovesAlongTheNormalWithinDeltaLfs) {
  const Local_feature_size lfs(circle(2));
  const Sample clean = uniform_sampling(lfs, 300);
  const Sample noisy = with_lfs_noise(lfs, clean, 0.25, 3);
  double largest = 0;
  for (std::size_t i = 0; i < clean.size(); ++i) {
    const Point p = clean.points[i], q = noisy.points[i];
    EXPECT_NEAR(p.x() * q.y() - p.y() * q.x(), 0, 1e-12);  // on the same ray from the center: the normal
    EXPECT_LE(std::abs(radius(q) - 2), 0.25 * 2 * (1 + 1e-9));
    largest = std::max(largest, std::abs(radius(q) - 2));
  }
  EXPECT_GT(largest, 0.24 * 2);
  EXPECT_EQ(bits(noisy), bits(with_lfs_noise(lfs, clean, 0.25, 3)));
}

TEST(Outliers, AddLabelledPointsInTheBoundingBoxAndNoEdges) {
  const Local_feature_size lfs(circle(1));
  const Sample clean = uniform_sampling(lfs, 50);
  const Sample with = with_outliers(clean, 10, 11);
  ASSERT_EQ(with.size(), 55u);
  EXPECT_EQ(with.edges, clean.edges);
  for (std::size_t i = 50; i < 55; ++i) {
    EXPECT_EQ(with.labels[i], Sample_label::outlier);
    EXPECT_TRUE(std::isnan(with.lfs[i]));
    EXPECT_EQ(with.locations[i].component, Curve_location::no_component);
    EXPECT_LE(std::abs(with.points[i].x()), 1);
    EXPECT_LE(std::abs(with.points[i].y()), 1);
  }
  // Noise after outliers moves the curve points only.
  const Sample noisy = with_uniform_noise(with, 0.05, 1);
  for (std::size_t i = 50; i < 55; ++i) EXPECT_EQ(noisy.points[i], with.points[i]);
  EXPECT_EQ(bits(with), bits(with_outliers(clean, 10, 11)));
}

RC_GTEST_PROP(RandomSampling, SameSeedSameBytes, (std::uint64_t seed)) {
  static const Local_feature_size lfs(random_fourier_curve(5));
  const std::size_t n = *testing::even_in_range(1, 200);
  const Sample once = with_lfs_noise(lfs, random_sampling(lfs, n, seed), 0.3, seed);
  RC_ASSERT(bits(once) == bits(with_lfs_noise(lfs, random_sampling(lfs, n, seed), 0.3, seed)));
}

}  // namespace
}  // namespace curvebench::geometry
