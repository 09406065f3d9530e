// FitConnect (algorithms/fit_connect.h) against independent oracles: a noisy circle
// (closed-form distance | |p - c| - r |, and one cycle in angular order), noise-free
// Fourier curves (the kept points in the curve's own order), lfs-noisy ones (RMS distance
// to a dense polyline of the true curve, against the noisy input), degenerate input
// (never a crash, always a valid manifold), and the law that scaling by a power of two
// commutes with the whole output. The authors' data: noisy_conformance_test.cpp.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "algorithms/fit_connect.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/metrics/curve_distance.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/sampling_noise.h"
#include "geometry/sampling/seeded_random.h"
#include "tests/support/edge_sets.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;

// Indices in range, i < j, sorted, unique, at most two edges per point, every output
// point on an edge (the output is the representative points only).
void expect_valid(const Reconstruction& r) {
  std::vector<int> degree(r.points.size(), 0);
  for (std::size_t e = 0; e < r.edges.size(); ++e) {
    const auto [i, j] = r.edges[e];
    ASSERT_LT(i, j);
    ASSERT_LT(j, r.points.size());
    if (e > 0) {
      ASSERT_LT(r.edges[e - 1], r.edges[e]);
    }
    ++degree[i], ++degree[j];
  }
  for (std::size_t p = 0; p < degree.size(); ++p) {
    EXPECT_LE(degree[p], 2) << "point " << p;
    EXPECT_GE(degree[p], 1) << "point " << p;
  }
  for (const Point& p : r.points) EXPECT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
}

// The edges on input indices, for output points at their input positions (blend off).
Edges on_input(const Reconstruction& r, std::span<const Point> input) {
  Edges result;
  const auto index = [&](const Point& p) {
    return static_cast<std::size_t>(std::find(input.begin(), input.end(), p) - input.begin());
  };
  for (const auto& [i, j] : r.edges) {
    const std::size_t a = index(r.points[i]), b = index(r.points[j]);
    EXPECT_LT(std::max(a, b), input.size()) << "an output point that is no input point";
    result.emplace_back(std::min(a, b), std::max(a, b));
  }
  return testing::canonical(result);
}

// One cycle through every output point.
bool one_cycle(const Reconstruction& r) {
  if (r.points.size() < 3 || r.edges.size() != r.points.size()) return false;
  std::vector<std::vector<std::size_t>> adjacent(r.points.size());
  for (const auto& [i, j] : r.edges) adjacent[i].push_back(j), adjacent[j].push_back(i);
  std::size_t previous = 0, current = 0, steps = 0;
  do {
    if (adjacent[current].size() != 2) return false;
    const std::size_t next = adjacent[current][0] != previous || steps == 0 ? adjacent[current][0] : adjacent[current][1];
    previous = current, current = next, ++steps;
  } while (current != 0 && steps <= r.points.size());
  return current == 0 && steps == r.points.size();
}

const Fit_connect_options at_input{.blend = false};

TEST(FitConnect, TinyInputs) {
  EXPECT_TRUE(fit_connect_reconstruction({}).edges.empty());
  const std::vector<Point> one{{1, 2}};
  const Reconstruction r1 = fit_connect_reconstruction(one);
  EXPECT_TRUE(r1.edges.empty());
  EXPECT_EQ(r1.points, one);
  const std::vector<Point> two{{0, 0}, {1, 0}};
  EXPECT_EQ(fit_connect_reconstruction(two).edges, (Edges{{0, 1}}));
  const std::vector<Point> three{{0, 0}, {1, 0}, {2, 0.1}};
  expect_valid(fit_connect_reconstruction(three));
}

TEST(FitConnect, RejectsDuplicatesNonFiniteAndBadOptions) {
  const std::vector<Point> duplicate{{0, 0}, {1, 0}, {0, 0}};
  EXPECT_THROW(fit_connect_reconstruction(duplicate), std::invalid_argument);
  const std::vector<Point> nan{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}};
  EXPECT_THROW(fit_connect_reconstruction(nan), std::invalid_argument);
  const std::vector<Point> inf{{0, 0}, {std::numeric_limits<double>::infinity(), 0}};
  EXPECT_THROW(fit_connect_reconstruction(inf), std::invalid_argument);
  const std::vector<Point> fine{{0, 0}, {1, 0}};
  EXPECT_THROW(fit_connect_reconstruction(fine, {.max_neighbors = 1}), std::invalid_argument);
  EXPECT_THROW(fit_connect_reconstruction(fine, {.sharp_angle = 200}), std::invalid_argument);
}

TEST(FitConnect, CollinearPointsGiveThePath) {
  std::vector<Point> points;
  for (int i = 0; i < 40; ++i) points.emplace_back((i * 7) % 40, 0);  // shuffled order
  const Reconstruction r = fit_connect_reconstruction(points, at_input);
  expect_valid(r);
  EXPECT_EQ(r.points.size(), points.size());
  Edges expected;
  for (int x = 0; x + 1 < 40; ++x) {
    std::size_t a = 0, b = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (points[i].x() == x) a = i;
      if (points[i].x() == x + 1) b = i;
    }
    expected.emplace_back(std::min(a, b), std::max(a, b));
  }
  EXPECT_EQ(on_input(r, points), testing::canonical(expected));
  // Blended, collinear points are fitted by their line and stay on it.
  for (const Point& p : fit_connect_reconstruction(points).points) EXPECT_EQ(p.y(), 0);

  // The same run at x = 2^1000 with spacing 2^-40: differences that no power of two brings
  // near 1 without overflowing the coordinates, so the filters take them unscaled.
  std::vector<Point> far;
  for (const Point& p : points) far.emplace_back(0x1p+1000, std::ldexp(p.x(), -40));
  const Reconstruction r_far = fit_connect_reconstruction(far, at_input);
  expect_valid(r_far);
  EXPECT_EQ(on_input(r_far, far), testing::canonical(expected));
}

TEST(FitConnect, CocircularPointsGiveTheCycle) {
  for (const std::size_t k : {4u, 5u, 12u, 64u}) {
    const auto points = testing::regular_polygon(k, 3.0);
    const Reconstruction r = fit_connect_reconstruction(points, at_input);
    expect_valid(r);
    EXPECT_EQ(on_input(r, points), testing::cycle_edges(k)) << k << "-gon";
  }
}

TEST(FitConnect, ExtremeScalesDoNotBreakDecisions) {
  const auto base = testing::regular_polygon(24, 1.0);
  const Reconstruction reference = fit_connect_reconstruction(base);
  for (const double scale : {0x1p-1000, 1e-300, 1e300, 0x1p+1000}) {
    std::vector<Point> points;
    for (const Point& p : base) points.emplace_back(p.x() * scale, p.y() * scale);
    const Reconstruction r = fit_connect_reconstruction(points);
    expect_valid(r);
    EXPECT_EQ(r.edges, reference.edges) << "scale " << scale;
  }
  // Mixed magnitudes: coordinates at 1e300 and 1e-300 in one set.
  const std::vector<Point> mixed{{0, 0}, {1e-300, 0}, {1e300, 1e-300}, {-1e300, 1}, {2e-300, 3e-300}, {5, 1e300}};
  const Reconstruction r = fit_connect_reconstruction(mixed);
  for (const auto& [i, j] : r.edges) EXPECT_LT(j, r.points.size());
}

// A noisy circle (300 points, spacing 0.042, radius 2): each point at a jittered angle and
// a radius off by uniform noise in [-noise, noise].
std::vector<Point> noisy_circle(double noise, const Point& center, double radius) {
  geometry::Seeded_random random(11);
  std::vector<Point> points;
  const int n = 300;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (i + random.uniform(-0.3, 0.3)) / n;
    const double r = radius + random.uniform(-noise, noise);
    points.emplace_back(center.x() + r * std::cos(t), center.y() + r * std::sin(t));
  }
  return points;
}

// Mean | |p - c| - r | over the input points and over the output points.
std::pair<double, double> circle_errors(const std::vector<Point>& points, const Reconstruction& result,
                                        const Point& center, double radius) {
  const auto mean_off = [&](std::span<const Point> set) {
    double sum = 0;
    for (const Point& p : set) sum += std::abs(std::hypot(p.x() - center.x(), p.y() - center.y()) - radius);
    return sum / set.size();
  };
  return {mean_off(points), mean_off(result.points)};
}

// One cycle through the output points in the order of their angles around the centre.
void expect_cycle_in_angular_order(const Reconstruction& result, const Point& center) {
  ASSERT_TRUE(one_cycle(result));
  std::vector<std::size_t> by_angle(result.points.size());
  for (std::size_t i = 0; i < by_angle.size(); ++i) by_angle[i] = i;
  const auto angle = [&](std::size_t i) {
    return std::atan2(result.points[i].y() - center.y(), result.points[i].x() - center.x());
  };
  std::sort(by_angle.begin(), by_angle.end(), [&](std::size_t a, std::size_t b) { return angle(a) < angle(b); });
  Edges cycle;
  for (std::size_t i = 0; i < by_angle.size(); ++i) cycle.emplace_back(by_angle[i], by_angle[(i + 1) % by_angle.size()]);
  EXPECT_EQ(result.edges, testing::canonical(cycle));
}

// Noise up to the spacing (+-0.04 against 0.042) and beyond it (+-0.06): one cycle of
// representative points, closer to the circle than the input, and in angular order up to
// the spacing (beyond it, neighbouring representatives may swap: measured once at 0.06).
TEST(FitConnect, ThinsANoisyCircleToOneCycle) {
  const double radius = 2.0;
  const Point center(0.5, -0.25);
  for (const double noise : {0.04, 0.06}) {
    SCOPED_TRACE(noise);
    const std::vector<Point> points = noisy_circle(noise, center, radius);
    const Reconstruction result = fit_connect_reconstruction(points);
    expect_valid(result);
    if (noise <= 0.04)
      expect_cycle_in_angular_order(result, center);
    else
      EXPECT_TRUE(one_cycle(result));
    const auto [input_error, output_error] = circle_errors(points, result, center, radius);
    std::cout << "circle, noise " << noise << ": " << result.points.size() << " of " << points.size()
              << " points kept; mean | |p-c| - r |: input " << input_error << ", output " << output_error << '\n';
    EXPECT_LT(output_error, input_error);
  }
}

struct Curve_case {
  geometry::Sample truth_polyline;  // dense, noise-free: the reference curve
  geometry::Sample sample;          // epsilon-sampled, then noisy
};

Curve_case fourier_case(std::uint64_t seed, double epsilon, double delta) {
  const geometry::Local_feature_size lfs(geometry::random_fourier_curve(seed, {.harmonics = 4, .amplitude = 0.3}));
  Curve_case c;
  c.truth_polyline = geometry::uniform_sampling(lfs, 4000);
  c.sample = geometry::safe_epsilon_sampling(lfs, epsilon, geometry::default_minimum_lfs(lfs));
  if (delta > 0) c.sample = geometry::with_lfs_noise(lfs, c.sample, delta, seed + 1);
  return c;
}

double rms(const geometry::Sample& truth, std::span<const Point> points, std::span<const Edge> edges) {
  const geometry::Polyline_view original{truth.points, truth.edges};
  return geometry::curve_distance(original, {points, edges}, geometry::default_distance_spacing(original)).rms;
}

// Noise-free samples: one cycle through the kept points in the curve's own order (the
// sampler's), every kept point an input point (blend off), and, blended, about as near the
// true curve as the input polygon. On these sparse samples (16 to 21 points) FitConnect
// drops a point now and then as redundant, as the authors' does (the survey: it degrades
// on sparse sampling): measured RMS 1.42 times the input's on seed 2, so the bound is 1.5.
TEST(FitConnect, NoiseFreeFourierCurvesGiveTheCurveInItsOrder) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(seed);
    const Curve_case c = fourier_case(seed, 0.3, 0);
    const Reconstruction r = fit_connect_reconstruction(c.sample.points, at_input);
    expect_valid(r);
    ASSERT_TRUE(one_cycle(r));
    const Edges edges = on_input(r, c.sample.points);
    std::vector<std::size_t> kept;
    for (const auto& [i, j] : edges) kept.push_back(i), kept.push_back(j);
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    Edges in_order;  // the sampler numbers the points along the curve
    for (std::size_t i = 0; i < kept.size(); ++i) in_order.emplace_back(kept[i], kept[(i + 1) % kept.size()]);
    EXPECT_EQ(edges, testing::canonical(in_order));
    const Reconstruction blended = fit_connect_reconstruction(c.sample.points);
    const double ours = rms(c.truth_polyline, blended.points, blended.edges);
    const double input = rms(c.truth_polyline, c.sample.points, c.sample.edges);
    std::cout << "noise-free seed " << seed << ": " << kept.size() << " of " << c.sample.size() << " points kept, RMS "
              << ours << " against the input's " << input << '\n';
    EXPECT_LT(ours, 1.5 * input);
  }
}

// lfs noise (the survey's "LFS-based Noise" experiment), at epsilon 0.3 and 0.15: one
// closed curve, and on average over 5 curves about as near the true curve as the noisy
// input with its true connectivity (measured: 0.3% to 6% nearer, except at epsilon 0.15,
// delta 0.1, 0.8% farther): the authors' blending moves points little; StretchDenoise is
// the method that denoises.
TEST(FitConnect, LfsNoisyCurvesGiveOneCycleCloserThanTheInput) {
  for (const double epsilon : {0.3, 0.15})
    for (const double delta : {0.1, 1.0 / 3}) {
      double ours_sum = 0, input_sum = 0;
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const Curve_case c = fourier_case(seed, epsilon, delta);
        const Reconstruction r = fit_connect_reconstruction(c.sample.points);
        expect_valid(r);
        EXPECT_TRUE(one_cycle(r)) << "eps " << epsilon << " delta " << delta << " seed " << seed;
        const double ours = rms(c.truth_polyline, r.points, r.edges);
        const double input = rms(c.truth_polyline, c.sample.points, c.sample.edges);
        ours_sum += ours, input_sum += input;
      }
      std::cout << "eps " << epsilon << " delta " << delta << " mean RMS: fit-connect " << ours_sum / 5
                << ", noisy input " << input_sum / 5 << '\n';
      EXPECT_LT(ours_sum, 1.05 * input_sum) << "eps " << epsilon << " delta " << delta;
    }
}

// The blending window only moves points: the edges are the same at every `smoothing`. On
// heavy noise over a sparse sampling (3 to 5 points per neighbourhood) the widened window
// lands closer to the true curve than the point's own neighbourhood (the authors' window).
TEST(FitConnect, WiderSmoothingWindowOnlyMovesPointsAndHelpsOnHeavyNoise) {
  double own_sum = 0, wide_sum = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Curve_case c = fourier_case(seed, 0.3, 0.5);
    const Reconstruction own = fit_connect_reconstruction(c.sample.points, {.smoothing = 0});
    const Reconstruction wide = fit_connect_reconstruction(c.sample.points, {.smoothing = 2});
    EXPECT_EQ(own.edges, wide.edges) << "seed " << seed;
    EXPECT_EQ(own.points.size(), wide.points.size()) << "seed " << seed;
    own_sum += rms(c.truth_polyline, own.points, own.edges);
    wide_sum += rms(c.truth_polyline, wide.points, wide.edges);
  }
  std::cout << "lfs noise 0.5, mean RMS over 10 curves: smoothing 0 " << own_sum / 10 << ", smoothing 2 "
            << wide_sum / 10 << '\n';
  EXPECT_LT(wide_sum, 0.95 * own_sum);
  EXPECT_THROW(fit_connect_reconstruction(std::vector<Point>{{0, 0}, {1, 0}}, {.smoothing = -1}), std::invalid_argument);
  EXPECT_THROW(fit_connect_reconstruction(std::vector<Point>{{0, 0}, {1, 0}}, {.smoothing = 65}), std::invalid_argument);
}

// Scaling by 2^k is exact in double, every decision is homogeneous, and every output
// construction scales with it: edges identical, points exactly scaled.
RC_GTEST_PROP(FitConnect, ScalingByAPowerOfTwoCommutes, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1000);
  const int k = *rc::gen::inRange(-60, 61);
  const double delta = *rc::gen::element(0.0, 0.1, 0.3);
  const geometry::Local_feature_size lfs(geometry::random_fourier_curve(seed, {.harmonics = 3, .amplitude = 0.3}));
  geometry::Sample sample = geometry::safe_epsilon_sampling(lfs, 0.3, geometry::default_minimum_lfs(lfs));
  if (delta > 0) sample = geometry::with_lfs_noise(lfs, sample, delta, seed);
  const double scale = std::ldexp(1.0, k);
  std::vector<Point> scaled;
  for (const Point& p : sample.points) scaled.emplace_back(p.x() * scale, p.y() * scale);
  const Reconstruction a = fit_connect_reconstruction(sample.points);
  const Reconstruction b = fit_connect_reconstruction(scaled);
  RC_ASSERT(a.edges == b.edges);
  RC_ASSERT(a.points.size() == b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    RC_ASSERT(a.points[i].x() * scale == b.points[i].x());
    RC_ASSERT(a.points[i].y() * scale == b.points[i].y());
  }
}

// The same law at the ends of double, where the filters work on differences scaled by a
// power of two (fit_connect.cpp, filter_exponent): the decisions, i.e. the edges, agree.
// Output points are constructions and may round differently near underflow.
RC_GTEST_PROP(FitConnect, ScalingToTheEndsOfDoubleKeepsTheEdges, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1000);
  const int k = *rc::gen::oneOf(rc::gen::inRange(-960, -900), rc::gen::inRange(900, 1020));
  const double delta = *rc::gen::element(0.0, 0.2);
  const geometry::Local_feature_size lfs(geometry::random_fourier_curve(seed, {.harmonics = 3, .amplitude = 0.3}));
  geometry::Sample sample = geometry::safe_epsilon_sampling(lfs, 0.3, geometry::default_minimum_lfs(lfs));
  if (delta > 0) sample = geometry::with_lfs_noise(lfs, sample, delta, seed);
  std::vector<Point> scaled;
  for (const Point& p : sample.points) scaled.emplace_back(std::ldexp(p.x(), k), std::ldexp(p.y(), k));
  RC_ASSERT(fit_connect_reconstruction(sample.points).edges == fit_connect_reconstruction(scaled).edges);
}

// Random small point sets, including grid points (collinear and cocircular ties): always a
// valid manifold on representative input points, and the same output for the same input.
RC_GTEST_PROP(FitConnect, ArbitraryInputGivesAValidDeterministicResult, ()) {
  const int n = *rc::gen::inRange(0, 40);
  const int grid = *rc::gen::inRange(2, 12);
  std::vector<Point> points;
  for (int i = 0; i < n; ++i) points.emplace_back(*rc::gen::inRange(0, grid), *rc::gen::inRange(0, grid));
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  const Reconstruction r = fit_connect_reconstruction(points, at_input);
  RC_ASSERT(r.points.size() <= points.size());
  std::vector<int> degree(r.points.size(), 0);
  for (std::size_t e = 0; e < r.edges.size(); ++e) {
    RC_ASSERT(r.edges[e].first < r.edges[e].second);
    RC_ASSERT(r.edges[e].second < r.points.size());
    if (e > 0) RC_ASSERT(r.edges[e - 1] < r.edges[e]);
    RC_ASSERT(++degree[r.edges[e].first] <= 2 && ++degree[r.edges[e].second] <= 2);
  }
  for (const Point& p : r.points) RC_ASSERT(std::find(points.begin(), points.end(), p) != points.end());
  RC_ASSERT(fit_connect_reconstruction(points, at_input).edges == r.edges);
}

TEST(FitConnect, AlgorithmDescription) {
  const Algorithm a = fit_connect_algorithm();
  EXPECT_EQ(a.name, "fit-connect");
  EXPECT_EQ(a.capabilities.noise, Support::yes);
  EXPECT_EQ(a.capabilities.sharp, Support::yes);
  ASSERT_EQ(a.parameters.size(), 4u);
  Parameter_values values;
  values.check(a.parameters, a.name);
  const auto points = testing::regular_polygon(10, 1.0);
  EXPECT_EQ(a.reconstruct(points, values).edges, fit_connect_reconstruction(points).edges);
}

}  // namespace
}  // namespace curvebench::algorithms
