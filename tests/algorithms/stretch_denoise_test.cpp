// StretchDenoise (algorithms/stretch_denoise.h) against independent oracles: the closed
// form |‖p - c‖ - r| of a circle, the RMS distance (geometry/metrics/curve_distance.h) to the
// true curve of Fourier curves and font glyphs with lfs noise (survey, "Robustness to
// Noise": epsilon = 0.3, delta = 0.1 and 1/3), HNN-Crust's edges on the same input, and
// laws for every input: the output points are FitConnect's representatives with its
// edges, each within its noise cut-off of its input point, the cut-off at most
// max_cutoff times the local spacing of those edges, finite points, and exact covariance
// under scaling by powers of two.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "algorithms/fit_connect.h"
#include "algorithms/hnn_crust.h"
#include "algorithms/registry.h"
#include "algorithms/stretch_denoise.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/metrics/curve_distance.h"
#include "geometry/curves/glyph_curves.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/metrics/nearest_segment_index.h"
#include "geometry/point_set.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/sampling_noise.h"
#include "geometry/sampling/seeded_random.h"
#include "tests/support/edge_sets.h"
#include "tests/support/point_generators.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;

// std::hypot: no overflow or underflow at 1e300 or 1e-300.
double distance(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

bool valid_edge_list(const Edges& edges, std::size_t n) {
  for (const auto& [i, j] : edges)
    if (!(i < j && j < n)) return false;
  return std::is_sorted(edges.begin(), edges.end()) && std::adjacent_find(edges.begin(), edges.end()) == edges.end();
}

bool finite(const std::vector<Point>& points) {
  return std::all_of(points.begin(), points.end(),
                     [](const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); });
}

// The mean length of each point's edges (0 for none), from the edges alone.
std::vector<double> local_spacing(std::span<const Point> points, const Edges& edges) {
  std::vector<double> sum(points.size(), 0.0);
  std::vector<int> count(points.size(), 0);
  for (const auto& [i, j] : edges) {
    const double length = distance(points[i], points[j]);
    sum[i] += length, sum[j] += length;
    ++count[i], ++count[j];
  }
  for (std::size_t i = 0; i < points.size(); ++i) sum[i] = count[i] > 0 ? sum[i] / count[i] : 0;
  return sum;
}

// The laws every call obeys, whatever the input: checked with RC_ASSERT or EXPECT.
template <class Check>
void check_laws(std::span<const Point> points, const Stretch_denoise_options& options, Check check) {
  const Stretch_denoise_result result = stretch_denoise(points, options);
  const Reconstruction& r = result.reconstruction;
  const std::size_t m = r.points.size();
  check(result.cutoff.size() == m && result.source.size() == m, "one cut-off and one source per output point");
  check(valid_edge_list(r.edges, m), "edges canonical and in range");
  check(finite(r.points), "finite output points");
  check(std::is_sorted(result.source.begin(), result.source.end()), "output points in input order");
  for (const std::size_t s : result.source) check(s < points.size(), "a source in range");
  if (!(result.source.size() == m && std::all_of(result.source.begin(), result.source.end(), [&](std::size_t s) { return s < points.size(); })))
    return;
  // The edges are FitConnect's connectivity on the distinct points, named by first
  // occurrences, and the output points are its representatives.
  const geometry::PointSet distinct(std::vector<Point>(points.begin(), points.end()));
  const Fitted_connectivity connectivity = fit_connect_connectivity(distinct.points(), {.max_neighbors = options.max_neighbors});
  std::vector<std::size_t> representatives;
  for (const auto v : connectivity.representatives) representatives.push_back(distinct.input_index(v));
  check(representatives == result.source, "the output points are FitConnect's representatives");
  Edges expected;
  for (const auto& [a, b] : connectivity.edges) {
    const auto at = [&](std::size_t v) {
      return static_cast<std::size_t>(std::lower_bound(connectivity.representatives.begin(), connectivity.representatives.end(), v) -
                                      connectivity.representatives.begin());
    };
    expected.emplace_back(at(a), at(b));
  }
  check(r.edges == geometry::canonical_edges(expected), "edges are FitConnect's");
  std::vector<Point> sources;
  for (const std::size_t s : result.source) sources.push_back(points[s]);
  const std::vector<double> spacing = local_spacing(sources, r.edges);
  // Points go through coordinates local to their chain and back: a rounding of the
  // chain's size, which for a point near the origin is not a rounding of its own size.
  double size = 0;
  for (const Point& p : points) size = std::max({size, std::abs(p.x()), std::abs(p.y())});
  for (std::size_t k = 0; k < m; ++k) {
    const double moved = distance(sources[k], r.points[k]);
    const double bound = std::max(result.cutoff[k], 0.0) * (1 + 1e-9) + 1e-12 * size;
    check(result.cutoff[k] >= 0, "cut-off not negative");
    check(moved <= bound, "moved within the cut-off");
    check(result.cutoff[k] <= options.max_cutoff * spacing[k] * (1 + 1e-9),
          "cut-off at most max_cutoff times the local spacing");
  }
}

void expect_laws(std::span<const Point> points, const Stretch_denoise_options& options = {}) {
  check_laws(points, options, [](bool ok, const char* what) { EXPECT_TRUE(ok) << what; });
}

// ------------------------------------------------------------ the circle, closed form

TEST(StretchDenoise, MovesANoisyCircleCloserToTheCircleAndKeepsOneCycleInAngularOrder) {
  const Point center(3, -2);
  const double radius = 5;
  for (const std::size_t n : {60u, 400u, 3000u}) {
    const double spacing = 2 * std::numbers::pi * radius / static_cast<double>(n);
    geometry::Seeded_random random(n);
    std::vector<Point> noisy;
    for (std::size_t i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
      const double r = radius + random.uniform(-0.3, 0.3) * spacing;
      noisy.emplace_back(center.x() + r * std::cos(angle), center.y() + r * std::sin(angle));
    }
    const auto rms_off_circle = [&](const std::vector<Point>& points) {
      double sum = 0;
      for (const Point& p : points) sum += std::pow(distance(p, center) - radius, 2);
      return std::sqrt(sum / static_cast<double>(points.size()));
    };
    const Reconstruction r = stretch_denoise_reconstruction(noisy);
    EXPECT_EQ(r.edges, testing::cycle_edges(n)) << n;
    const double before = rms_off_circle(noisy), after = rms_off_circle(r.points);
    EXPECT_LT(after, 0.7 * before) << n << " points: " << before << " -> " << after;
    // Still in angular order: each point turns the same way around the centre.
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_EQ(CGAL::orientation(center, r.points[i], r.points[(i + 1) % n]), CGAL::LEFT_TURN) << i;
    expect_laws(noisy);
  }
}

// A 150-degree arc. (A half circle closes: its ends see each other across the centre, on
// opposite sides of their fits, and overlap; the survey leaves StretchDenoise out of its
// open-curve experiment as "not designed for open curves".)
TEST(StretchDenoise, MovesANoisyOpenArcCloserAndKeepsItAPath) {
  const Point center(-1, 4);
  const double radius = 2, span = 150 * std::numbers::pi / 180;
  geometry::Seeded_random random(5);
  std::vector<Point> noisy;
  const std::size_t n = 200;
  const double spacing = span * radius / (n - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = span * static_cast<double>(i) / (n - 1);
    const double r = radius + random.uniform(-0.3, 0.3) * spacing;
    noisy.emplace_back(center.x() + r * std::cos(angle), center.y() + r * std::sin(angle));
  }
  const Stretch_denoise_result result = stretch_denoise(noisy);
  const Reconstruction& r = result.reconstruction;
  ASSERT_GE(r.points.size(), 3u);
  // The output keeps input order, which is the arc's: a path through them in that order.
  EXPECT_EQ(r.edges, testing::path_edges(r.points.size()));
  double before = 0, after = 0;
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    before += std::pow(distance(noisy[result.source[k]], center) - radius, 2);
    after += std::pow(distance(r.points[k], center) - radius, 2);
  }
  EXPECT_LT(after, 0.5 * before);
}

// ------------------------------------------------------------ curves with lfs noise

struct Noisy_case {
  double hnn_rms, denoised_rms;             // curve_distance RMS to the true curve
  double input_points_rms, output_points_rms;  // RMS distance of the points to it
};

Noisy_case run_noisy_case(const geometry::Curve& curve, double delta, std::uint64_t seed) {
  const geometry::Local_feature_size lfs(curve);
  const geometry::Sample truth = geometry::uniform_sampling(lfs, 20000);
  const geometry::Sample clean = geometry::safe_epsilon_sampling(lfs, 0.3, geometry::default_minimum_lfs(lfs));
  const geometry::Sample noisy = geometry::with_lfs_noise(lfs, clean, delta, seed);
  const Reconstruction hnn{hnn_crust_reconstruction(noisy.points), {}};
  const Reconstruction denoised = stretch_denoise_reconstruction(noisy.points);
  const geometry::Polyline_view original{truth.points, truth.edges};
  const double spacing = geometry::default_distance_spacing(original);
  const geometry::Nearest_segment_index nearest(truth.points, truth.edges);
  const auto points_rms = [&](const std::vector<Point>& points) {
    double sum = 0;
    for (const Point& p : points) sum += nearest.nearest(p)->squared_distance;
    return std::sqrt(sum / static_cast<double>(points.size()));
  };
  return {geometry::curve_distance(original, {noisy.points, hnn.edges}, spacing).rms,
          geometry::curve_distance(original, {denoised.points, denoised.edges}, spacing).rms,
          points_rms(noisy.points), points_rms(denoised.points)};
}

// Glyphs: dense samples (their features are small against the em square). Every case
// improves on HNN-Crust. Not 'g' and '8': there FitConnect's pass joins contours at
// epsilon 0.3 (denoised RMS 1.3 to 4 times HNN-Crust's), a weakness of the published
// connectivity on sparse samples that the survey also reports.
TEST(StretchDenoise, BeatsHnnCrustAndTheNoisyInputOnGlyphsWithLfsNoise) {
  for (const char32_t c : {U'S', U'a', U'O'})
    for (const double delta : {0.1, 1.0 / 3}) {
      const Noisy_case result = run_noisy_case(geometry::glyph_curve(geometry::default_glyph_font, c), delta, 42);
      EXPECT_LT(result.denoised_rms, 0.8 * result.hnn_rms) << char(c) << " delta " << delta;
      EXPECT_LT(result.output_points_rms, 0.8 * result.input_points_rms) << char(c) << " delta " << delta;
    }
}

// Random Fourier curves at epsilon = 0.3 have only about 20 samples per component. At
// delta = 1/3 every case improves; at delta = 0.1 the sparse sampling lets the angle
// minimisation flatten curvature changes about as much as it removes noise (a case
// reaches ratio 1.07), so only the mean over the cases is asserted there (measured 0.90).
TEST(StretchDenoise, BeatsHnnCrustOnFourierCurvesWithLfsNoise) {
  std::vector<geometry::Curve> curves;
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) curves.push_back(geometry::random_fourier_curve(seed));
  std::vector<testing::Sampled_case> owners;  // own the pieces the side-by-side curves read
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    owners.push_back(testing::sampled_fourier_curves(seed, 2, 8, 0.3));
    curves.push_back(owners.back().curve);
  }
  for (const double delta : {0.1, 1.0 / 3}) {
    double hnn = 0, denoised = 0, input = 0, output = 0;
    for (const geometry::Curve& curve : curves) {
      const Noisy_case result = run_noisy_case(curve, delta, 42);
      hnn += result.hnn_rms, denoised += result.denoised_rms;
      input += result.input_points_rms, output += result.output_points_rms;
      if (delta > 0.3) {
        EXPECT_LT(result.denoised_rms, 0.9 * result.hnn_rms) << curve.name;
        EXPECT_LT(result.output_points_rms, 0.9 * result.input_points_rms) << curve.name;
      }
    }
    EXPECT_LT(denoised, (delta > 0.3 ? 0.8 : 0.95) * hnn) << "delta " << delta;
    EXPECT_LT(output, (delta > 0.3 ? 0.8 : 0.95) * input) << "delta " << delta;
  }
}

TEST(StretchDenoise, NoiseFreeDenseInputBarelyMoves) {
  for (const std::uint64_t seed : {3u, 11u}) {
    const geometry::Local_feature_size lfs(geometry::random_fourier_curve(seed));
    const geometry::Sample sample = geometry::uniform_sampling(lfs, 2000);
    const Stretch_denoise_result result = stretch_denoise(sample.points);
    EXPECT_EQ(result.reconstruction.edges, testing::canonical(sample.edges));
    const std::vector<double> spacing = local_spacing(sample.points, result.reconstruction.edges);
    double largest = 0;
    for (std::size_t i = 0; i < sample.size(); ++i)
      largest = std::max(largest, distance(sample.points[i], result.reconstruction.points[i]) / spacing[i]);
    EXPECT_LT(largest, 0.01) << "seed " << seed;
  }
  // A regular polygon is already balanced with equal turning angles: it does not move.
  const std::vector<Point> polygon = testing::regular_polygon(50, 2, 0.3, {1, 1});
  const Reconstruction r = stretch_denoise_reconstruction(polygon);
  for (std::size_t i = 0; i < polygon.size(); ++i) EXPECT_LT(distance(polygon[i], r.points[i]), 1e-9) << i;
}

// ------------------------------------------------------------ laws, all inputs

rc::Gen<Stretch_denoise_options> options() {
  return rc::gen::exec([] {
    Stretch_denoise_options o;
    o.window = *rc::gen::inRange(1, 6);
    o.cutoff_scale = *rc::gen::inRange(0, 31) / 10.0;
    o.max_cutoff = *rc::gen::inRange(0, 21) / 10.0;
    o.balance = *rc::gen::element(0.0, 1.0, 3.0, 100.0);
    o.balance_window = *rc::gen::inRange(0, 4);
    o.fidelity = *rc::gen::element(0.0, 0.01, 0.1, 10.0);
    o.iterations = *rc::gen::inRange(0, 60);
    return o;
  });
}

RC_GTEST_PROP(StretchDenoise, EveryPointStaysWithinItsCutOffOnDegenerateInput, ()) {
  const std::vector<Point> points = *testing::point_sets(40);
  check_laws(points, *options(), [](bool ok, const char* what) {
    if (!ok) RC_FAIL(what);
  });
}

RC_GTEST_PROP(StretchDenoise, EveryPointStaysWithinItsCutOffOnNoisyCurves, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 20);
  const double delta = *rc::gen::inRange(0, 60) / 100.0;
  const testing::Sampled_case sampled = testing::sampled_fourier_curves(seed, *rc::gen::inRange(1, 3), 5, 0.3);
  const geometry::Local_feature_size lfs(sampled.curve);
  const geometry::Sample noisy = geometry::with_lfs_noise(lfs, sampled.sample, delta, seed);
  check_laws(noisy.points, *options(), [](bool ok, const char* what) {
    if (!ok) RC_FAIL(what);
  });
}

RC_GTEST_PROP(StretchDenoise, ScalingByAPowerOfTwoScalesTheOutputExactly, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 20);
  const int exponent = *rc::gen::element(-1000, -500, -3, 7, 900);
  const testing::Sampled_case sampled = testing::sampled_fourier_curves(seed, 1, 4, 0.3);
  const geometry::Sample noisy =
      geometry::with_lfs_noise(geometry::Local_feature_size(sampled.curve), sampled.sample, 0.3, seed);
  std::vector<Point> scaled;
  for (const Point& p : noisy.points) scaled.emplace_back(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent));
  const Reconstruction a = stretch_denoise_reconstruction(noisy.points), b = stretch_denoise_reconstruction(scaled);
  RC_ASSERT(a.edges == b.edges);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    RC_ASSERT(std::ldexp(a.points[i].x(), exponent) == b.points[i].x());
    RC_ASSERT(std::ldexp(a.points[i].y(), exponent) == b.points[i].y());
  }
}

// ------------------------------------------------------------ degenerate input

TEST(StretchDenoise, TinyDuplicateCollinearCocircularAndExtremeInput) {
  for (std::size_t n = 0; n <= 3; ++n) {
    std::vector<Point> points;
    for (std::size_t i = 0; i < n; ++i) points.emplace_back(double(i), double(i * i));
    expect_laws(points);
    if (n < 3) {
      EXPECT_EQ(stretch_denoise_reconstruction(points).points, points) << "a chain of < 3 points: unmoved";
    }
  }
  // Duplicates: merged into the first occurrence, which alone gets edges.
  std::vector<Point> doubled = testing::regular_polygon(9, 2, 0.1);
  const std::vector<Point> once = doubled;
  doubled.insert(doubled.end(), once.begin(), once.end());
  doubled.push_back(once[4]);
  const Reconstruction d = stretch_denoise_reconstruction(doubled);
  EXPECT_EQ(d.edges, testing::cycle_edges(9));
  expect_laws(doubled);
  expect_laws(std::vector<Point>{{1, 1}, {1, 1}, {1, 1}});
  // Collinear: a straight path has no residual, so nothing moves.
  std::vector<Point> line;
  for (int i = 0; i < 30; ++i) line.emplace_back(3.0 * ((i * 7) % 30), -2.0 * ((i * 7) % 30) + 1);
  const Reconstruction l = stretch_denoise_reconstruction(line);
  for (std::size_t i = 0; i < line.size(); ++i) EXPECT_LT(distance(l.points[i], line[i]), 1e-12) << i;
  expect_laws(line);
  // Cocircular: the exact square, an octagon, many points on a circle.
  expect_laws(std::vector<Point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  expect_laws(testing::regular_polygon(8, 1));
  expect_laws(testing::regular_polygon(500, 1e-3, 0.2));
  // Extreme scales, and a noisy circle at them.
  for (const double scale : {1e-300, 1e300, 0x1.0p-1070, 1.7e308 / 4}) {
    std::vector<Point> points;
    geometry::Seeded_random random(9);
    for (int i = 0; i < 100; ++i) {
      const double angle = 2 * std::numbers::pi * i / 100, r = 1 + random.uniform(-0.02, 0.02);
      points.emplace_back(scale * r * std::cos(angle), scale * r * std::sin(angle));
    }
    points = testing::distinct(points);
    expect_laws(points);
  }
  EXPECT_THROW(stretch_denoise(std::vector<Point>{{0, 0}, {std::nan(""), 1}}), std::invalid_argument);
}

TEST(StretchDenoise, DescribesItselfAsTheSurveysTableDoes) {
  const Algorithm algorithm = stretch_denoise_algorithm();
  EXPECT_EQ(algorithm.name, "stretch-denoise");
  EXPECT_EQ(algorithm.title, "StretchDenoise");
  EXPECT_EQ(algorithm.category, "Noisy Points Fitting");
  EXPECT_EQ(algorithm.capabilities.noise, Support::yes);
  EXPECT_TRUE(algorithm.capabilities.guarantee);
  EXPECT_FALSE(algorithm.condition.epsilon_below.has_value()) << "not certified: FitConnect's pass drops points";
  // Through the registry's reconstruct(): parameters checked, duplicates merged, and the
  // result equal to the direct call's on the distinct points.
  std::vector<Point> points = testing::regular_polygon(40, 3, 0.2);
  geometry::Seeded_random random(3);
  for (Point& p : points) p = Point(p.x() + random.uniform(-0.05, 0.05), p.y() + random.uniform(-0.05, 0.05));
  const Reconstruction direct = stretch_denoise_reconstruction(points);
  const Reconstruction via = reconstruct(algorithm, points);
  EXPECT_EQ(via.edges, direct.edges);
  EXPECT_EQ(via.points, direct.points);
  const Reconstruction tuned = reconstruct(algorithm, points, {{"window", 2}, {"max_cutoff", 0.5}});
  EXPECT_EQ(tuned.points, stretch_denoise_reconstruction(points, {.window = 2, .max_cutoff = 0.5}).points);
  EXPECT_THROW(reconstruct(algorithm, points, {{"window", 0.5}}), std::invalid_argument);
  EXPECT_THROW(reconstruct(algorithm, points, {{"no_such", 1}}), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench::algorithms
