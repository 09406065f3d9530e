// The runner's calls behind the verbs that the command line and the Python module share:
// sample_curve (`sample`), located_sample and measure_report_json (`measure`),
// evaluation_report_json (`evaluate`), each against a closed form.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bench/runner/curve_sampling.h"
#include "bench/runner/evaluation_report.h"
#include "bench/runner/sampling_report.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/sampling/sampling_noise.h"

namespace curvebench::bench {
namespace {

using geometry::Edge;
using geometry::Point;

const geometry::Local_feature_size& unit_circle() {
  static const geometry::Local_feature_size lfs(geometry::make_curve("circle:r=1"));
  return lfs;
}

TEST(SampleCurve, UniformOnACircleIsARegularPolygonWithItsCycle) {
  const geometry::Sample s = sample_curve(unit_circle(), {.uniform = 8});
  ASSERT_EQ(s.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_NEAR(std::hypot(s.points[k].x(), s.points[k].y()), 1, 1e-12);
    const Point& next = s.points[(k + 1) % 8];
    EXPECT_NEAR(std::hypot(next.x() - s.points[k].x(), next.y() - s.points[k].y()), 2 * std::sin(std::numbers::pi / 8),
                1e-12);  // the side of the regular octagon
  }
  std::vector<Edge> cycle;
  for (std::size_t k = 0; k < 8; ++k) cycle.emplace_back(std::min(k, (k + 1) % 8), std::max(k, (k + 1) % 8));
  EXPECT_EQ(geometry::canonical_edges(s.edges), geometry::canonical_edges(cycle));
}

TEST(SampleCurve, TakesExactlyOneSampler) {
  EXPECT_THROW(sample_curve(unit_circle(), {}), std::invalid_argument);
  EXPECT_THROW(sample_curve(unit_circle(), {.epsilon = 0.3, .uniform = 10}), std::invalid_argument);
}

// The command line's seeds, which `curvebench sample` has always drawn from: uniform noise
// from seed + 1, outliers from seed + 3.
TEST(SampleCurve, PerturbationsDrawFromTheirOwnStreamsOfTheSeed) {
  const geometry::Sample s = sample_curve(unit_circle(), {.uniform = 20, .uniform_noise = 0.01, .outliers = 10, .seed = 5});
  const geometry::Sample by_hand = geometry::with_outliers(
      geometry::with_uniform_noise(sample_curve(unit_circle(), {.uniform = 20}), 0.01, 6), 10, 8);
  EXPECT_EQ(s.points, by_hand.points);
  EXPECT_EQ(s.size(), 22u);
}

// On the unit circle lfs is 1 everywhere, so n points at equal steps have
// epsilon = 2 sin(pi / 2n) (the arc's middle to its ends), rho = sin(pi / n) (half a chord
// over the reach) and uniformity 1.
TEST(MeasureReport, AUniformCircleSamplingMeasuresItsClosedForms) {
  constexpr int n = 12;
  const double pi = std::numbers::pi;
  std::vector<Point> points;
  std::vector<Edge> edges;
  for (int k = 0; k < n; ++k) {
    // Backwards round the circle, and the edges as pairs (i, j), i < j: located_sample
    // must orient them along the curve itself.
    points.emplace_back(std::cos(-2 * pi * k / n), std::sin(-2 * pi * k / n));
    edges.emplace_back(k, (k + 1) % n);
  }
  geometry::Sample s = located_sample(unit_circle(), points, geometry::canonical_edges(edges));
  s.minimum_lfs = 0;
  const nlohmann::json report = nlohmann::json::parse(measure_report_json(unit_circle(), s, "by hand"));
  EXPECT_NEAR(report["epsilon"].get<double>(), 2 * std::sin(pi / (2 * n)), 1e-3 * 2 * std::sin(pi / (2 * n)));
  EXPECT_NEAR(report["rho"].get<double>(), std::sin(pi / n), 1e-3 * std::sin(pi / n));
  EXPECT_NEAR(report["uniformity"].get<double>(), 1, 1e-9);
  EXPECT_EQ(report["points"], n);
  EXPECT_EQ(report["edges"], "by hand");
  EXPECT_THROW(located_sample(unit_circle(), points, {{0, n}}), std::invalid_argument);
}

TEST(EvaluationReport, ScoresASquareAgainstItsCycle) {
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Edge> cycle{{0, 1}, {1, 2}, {2, 3}, {0, 3}};
  const nlohmann::json exact = nlohmann::json::parse(evaluation_report_json(square, cycle, cycle, ""));
  EXPECT_TRUE(exact["exact"].get<bool>());
  EXPECT_EQ(exact["hausdorff"].get<double>(), 0);
  EXPECT_EQ(exact["closed_components"], 1);
  EXPECT_EQ(exact["distances_to"], "ground truth");
  // One side missing, given as (j, i): an open path of three edges, not exact.
  const std::vector<Edge> path{{1, 0}, {2, 1}, {3, 2}};
  const nlohmann::json open = nlohmann::json::parse(evaluation_report_json(square, path, cycle, ""));
  EXPECT_FALSE(open["exact"].get<bool>());
  EXPECT_EQ(open["edges"], 3);
  EXPECT_EQ(open["open_components"], 1);
  EXPECT_TRUE(open["manifold"].get<bool>());
  const std::vector<Edge> beyond{{0, 4}};
  EXPECT_THROW(evaluation_report_json(square, beyond, cycle, ""), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench::bench
