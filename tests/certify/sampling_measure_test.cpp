#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>

#include "certify/sampling_measure.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/corner_curve.h"
#include "geometry/sampling/sampling.h"
#include "tests/support/closed_form_lfs.h"
#include "tests/support/even_in_range.h"

namespace curvebench::certify {
namespace {

using namespace geometry;

constexpr double pi = std::numbers::pi;

// Brute force: the ratio at `count` points evenly spread in each piece's parameter, each
// point against every sample, with lfs from a closed form. Independent of curve_search.h,
// Nearest_point_index and Medial_axis.
template <class Closed_form_lfs>
double brute_force_epsilon(const Curve& curve, const std::vector<Point>& samples, double minimum_lfs, int count,
                           Closed_form_lfs lfs) {
  double worst = 0;
  for (const Curve_component& component : curve.components)
    for (int i = 0; i <= count; ++i) {
      const Point p = component.point(static_cast<double>(component.piece_count()) * i / count);
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point& s : samples) nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(p, s)));
      worst = std::max(worst, relative_distance(nearest, lfs(p), minimum_lfs));
    }
  return worst;
}

TEST(MeasureEpsilon, OfKEvenPointsOnACircleIsTwoSinPiOver2kAtTheArcMiddles) {
  const Local_feature_size lfs(circle(1.5));
  for (const std::size_t k : {3u, 5u, 8u, 20u, 100u}) {
    const Sample sample = uniform_sampling(lfs, k);
    const Epsilon_measure measured = measure_epsilon(lfs, sample.points, 0);
    EXPECT_NEAR(measured.epsilon, 2 * std::sin(pi / (2 * k)), 1e-7 * measured.epsilon) << k;
    const double between = measured.where.parameter * k;  // sample j sits at j / k
    EXPECT_NEAR(between - std::floor(between), 0.5, 1e-4) << k;
  }
}

TEST(MeasureEpsilon, AgreesWithABruteForceOnAnEllipse) {
  const double a = 2, b = 0.7;
  const Local_feature_size lfs(ellipse(a, b));
  for (const std::size_t n : {12u, 40u, 150u}) {
    const Sample sample = uniform_sampling(lfs, n);
    const double truth = brute_force_epsilon(lfs.curve(), sample.points, 0, 100000,
                                             [&](const Point& p) { return testing::ellipse_lfs(a, b, p); });
    EXPECT_NEAR(measure_epsilon(lfs, sample.points, 0).epsilon, truth, 1e-3 * truth) << n;
  }
}

TEST(MeasureEpsilon, IsInfiniteNearAnUnsampledCornerWithoutAFloor) {
  const Local_feature_size lfs(sharp_corner_curve(40));
  const Sample sample = random_sampling(lfs, 50, 1);  // no sample at the apex
  EXPECT_EQ(measure_epsilon(lfs, sample.points, 0).epsilon, std::numeric_limits<double>::infinity());
  EXPECT_LT(measure_epsilon(lfs, sample.points, 0.01).epsilon, std::numeric_limits<double>::infinity());
}

TEST(MeasureRho, OfKEvenPointsOnACircleIsSinPiOverK) {
  const Local_feature_size lfs(circle(0.8));
  for (const std::size_t k : {3u, 7u, 50u}) {
    const Rho_measure measured = measure_rho(lfs, uniform_sampling(lfs, k), 0);
    EXPECT_NEAR(measured.rho, std::sin(pi / k), 1e-9) << k;
    EXPECT_NEAR(measured.reach, 0.8, 1e-9);
  }
}

TEST(MeasureRho, IsTheWorstHalfChordOverTheReachOfItsInterval) {
  // On the corner curve, the edge from the apex has reach 0: infinite without a floor.
  const Local_feature_size lfs(sharp_corner_curve(60));
  const Sample sample = epsilon_sampling(lfs, 0.3, 0.05);
  const Rho_measure unfloored = measure_rho(lfs, sample, 0);
  EXPECT_EQ(unfloored.rho, std::numeric_limits<double>::infinity());
  const Rho_measure floored = measure_rho(lfs, sample, 0.05);
  ASSERT_LT(floored.rho, std::numeric_limits<double>::infinity());
  // Brute force on the worst edge: its half chord over the least closed-form lfs along it.
  const auto [i, j] = floored.edge;
  const Curve_component& component = lfs.curve().components[0];
  double s1 = sample.locations[j].parameter;
  if (s1 <= sample.locations[i].parameter) s1 += 3;
  double reach = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 20000; ++k) {
    const double s = sample.locations[i].parameter + (s1 - sample.locations[i].parameter) * k / 20000;
    reach = std::min(reach, std::max(testing::sharp_corner_lfs(60, component.point(s)), 0.05));
  }
  EXPECT_NEAR(floored.reach, reach, 1e-3 * reach);
  EXPECT_NEAR(floored.rho, std::sqrt(CGAL::squared_distance(sample.points[i], sample.points[j])) / 2 / reach, 2e-3 * floored.rho);
}

TEST(MeasureUniformity, IsTheLargestRatioOfAdjacentEdgeLengths) {
  const std::vector<Point> points{{0, 0}, {1, 0}, {3, 0}, {4, 0}, {4, 0.5}};
  const std::vector<Edge> edges{{0, 1}, {1, 2}, {2, 3}, {3, 4}};
  const Uniformity_measure measured = measure_uniformity(points, edges);
  EXPECT_EQ(measured.uniformity, 2);
  EXPECT_EQ(measured.point, 1u);
  const std::vector<Point> repeated{{0, 0}, {0, 0}, {1, 0}};
  EXPECT_EQ(measure_uniformity(repeated, std::span<const Edge>(edges).first(2)).uniformity, std::numeric_limits<double>::infinity());
  const Local_feature_size lfs(circle(1));
  EXPECT_NEAR(measure_sampling(lfs, uniform_sampling(lfs, 17)).uniformity.uniformity, 1, 1e-12);
}

// The survey's walk steps by chords of epsilon lfs, so on a circle the middle of a step
// is only 2 sin(asin(epsilon / 2) / 2) ~ epsilon / 2 from its samples.
TEST(EpsilonSampling, OfACircleMeasuresAboutHalfItsEpsilon) {
  const Local_feature_size lfs(circle(1));
  for (const double epsilon : {0.1, 0.5, 0.9}) {
    const Sample sample = epsilon_sampling(lfs, epsilon, default_minimum_lfs(lfs));
    EXPECT_NEAR(measure_sampling(lfs, sample).epsilon.epsilon, 2 * std::sin(std::asin(epsilon / 2) / 2), 1e-7);
  }
}

// Curves to sample, each with its lfs estimate built once, and a closed-form lfs where
// there is one (for a brute-force second opinion).
struct Family_curve {
  std::shared_ptr<const Local_feature_size> lfs;
  std::function<double(const Point&)> closed_form;  // empty if none
};

const Family_curve& family_curve(int family, int index) {
  static std::map<std::pair<int, int>, Family_curve> cache;
  auto [it, inserted] = cache.try_emplace({family, index});
  if (inserted) {
    switch (family) {
      case 0: {
        const double r = 0.5 + index;
        it->second = {std::make_shared<Local_feature_size>(circle(r)), [r](const Point&) { return r; }};
        break;
      }
      case 1: {
        const double a = 1, b = 1.0 / (1.5 + index);
        it->second = {std::make_shared<Local_feature_size>(ellipse(a, b)),
                      [a, b](const Point& p) { return testing::ellipse_lfs(a, b, p); }};
        break;
      }
      case 2:
        it->second = {std::make_shared<Local_feature_size>(random_fourier_curve(index)), {}};
        break;
      default: {
        const double angle = 10.0 * (index + 1);
        it->second = {std::make_shared<Local_feature_size>(sharp_corner_curve(angle)),
                      [angle](const Point& p) { return testing::sharp_corner_lfs(angle, p); }};
      }
    }
  }
  return it->second;
}

RC_GTEST_PROP(SafeEpsilonSampling, MeasuresAtMostItsTarget, ()) {
  const int family = *testing::even_in_range(0, 4);
  const int index = *testing::even_in_range(0, 6);
  const double epsilon = *testing::even_in_range(50, 901) / 1000.0;
  const Family_curve& curve = family_curve(family, index);
  const Local_feature_size& lfs = *curve.lfs;
  const Sample sample = safe_epsilon_sampling(lfs, epsilon, default_minimum_lfs(lfs));
  RC_TAG(family);
  const double measured = measure_sampling(lfs, sample).epsilon.epsilon;
  RC_ASSERT(measured <= epsilon);
  RC_ASSERT(measured > 0.8 * epsilon);  // and not needlessly dense
  if (curve.closed_form) {
    // With the true lfs, up to the estimate's 1e-3 and the brute force's grid.
    const double truth = brute_force_epsilon(lfs.curve(), sample.points, sample.minimum_lfs, 4000, curve.closed_form);
    RC_ASSERT(truth <= epsilon * 1.01);
  }
}

// HNN-Crust's hypothesis on purpose: the measured rho at most the target, with no two
// samples at one point. On the sharp-corner family the floor sets the reach near the apex:
// measured with it.
RC_GTEST_PROP(SafeRhoSampling, MeasuresAtMostItsTarget, ()) {
  const int family = *testing::even_in_range(0, 4);
  const int index = *testing::even_in_range(0, 6);
  const double rho = *testing::even_in_range(50, 951) / 1000.0;
  const Local_feature_size& lfs = *family_curve(family, index).lfs;
  const Sample sample = safe_rho_sampling(lfs, rho, default_minimum_lfs(lfs));
  RC_TAG(family);
  RC_ASSERT(measure_rho(lfs, sample, sample.minimum_lfs).rho <= rho);
  // A zero chord: a greedy cover tried on 2026-12-05 left slivers of 1e-15, and HNN-Crust
  // then "failed" on 24 of 10,000 rounded stars.
  RC_ASSERT(std::isfinite(measure_uniformity(sample.points, sample.edges).uniformity));
}

// And near the target, which is what certifying at 0.95 of a bound needs, though not on
// every curve: where a curve gets a handful of samples, the walk's last step can leave
// every interval well below it (a circle of radius 2.5 at rho 0.945: 0.66 of it). Over a
// fixed grid of the families, curves and targets: the median measured rho is at least 0.99
// of the target, the 10th percentile at least 0.95 (measured: all 120 at 0.999 or above).
TEST(SafeRhoSampling, MeasuresNearItsTargetOnMostCurves) {
  std::vector<double> ratios;
  for (int family = 0; family <= 4; ++family)
    for (int index = 0; index <= 6; index += 2)
      for (const double rho : {0.1, 0.3, 0.5, 0.7, 0.855, 0.9}) {
        const Local_feature_size& lfs = *family_curve(family, index).lfs;
        const Sample sample = safe_rho_sampling(lfs, rho, default_minimum_lfs(lfs));
        ratios.push_back(measure_rho(lfs, sample, sample.minimum_lfs).rho / rho);
      }
  std::ranges::sort(ratios);
  std::cout << ratios.size() << " samplings, measured rho / target: least " << ratios.front() << ", 10th percentile "
            << ratios[ratios.size() / 10] << ", median " << ratios[ratios.size() / 2] << '\n';
  EXPECT_GE(ratios[ratios.size() / 2], 0.99);
  EXPECT_GE(ratios[ratios.size() / 10], 0.95);
  EXPECT_LE(ratios.back(), 1.0);
}

// Connect2D's two hypotheses at once: epsilon at most the target, and near it, and every
// point's longer chord below the uniformity bound times its shorter one.
RC_GTEST_PROP(GradedEpsilonSampling, MeetsEpsilonAndUniformity, ()) {
  const int family = *testing::even_in_range(0, 3);  // smooth curves: the corner family's floor makes chords of any ratio
  const int index = *testing::even_in_range(0, 6);
  const double epsilon = *testing::even_in_range(50, 500) / 1000.0;
  const double uniformity = 1 + *testing::even_in_range(50, 1000) / 1000.0;
  const Local_feature_size& lfs = *family_curve(family, index).lfs;
  const Sample graded = graded_epsilon_sampling(lfs, epsilon, uniformity, default_minimum_lfs(lfs));
  RC_TAG(family);
  const Sampling_measure measured = measure_sampling(lfs, graded);
  RC_ASSERT(measured.uniformity.uniformity < uniformity);
  RC_ASSERT(measured.epsilon.epsilon <= epsilon);
  RC_ASSERT(measured.epsilon.epsilon > 0.8 * epsilon);  // a circle of few points: N and N + 1 differ that much
}

}  // namespace
}  // namespace curvebench::certify
