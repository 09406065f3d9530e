#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <unistd.h>

#include "certify/ambiguity_search.h"
#include "certify/sampling_measure.h"
#include "geometry/curves/curve_name.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::certify {
namespace {

using geometry::Vector;
constexpr double pi = std::numbers::pi;

double norm(const Vector& v) { return std::sqrt(v.squared_length()); }

// n points around an ellipse-like loop, radius and angle jittered by the generator, so
// consecutive points are distinct; and positive knot intervals.
rc::Gen<std::pair<std::vector<Point>, std::vector<double>>> spline_input() {
  return rc::gen::mapcat(rc::gen::inRange<std::size_t>(3, 14), [](std::size_t n) {
    return rc::gen::map(rc::gen::container<std::vector<std::pair<int, int>>>(n, rc::gen::pair(rc::gen::inRange(0, 1000),
                                                                                              rc::gen::inRange(1, 1000))),
                        [n](const std::vector<std::pair<int, int>>& draws) {
                          std::vector<Point> points;
                          std::vector<double> h;
                          for (std::size_t i = 0; i < n; ++i) {
                            const double angle = 2 * pi * (static_cast<double>(i) + 0.4 * draws[i].first / 1000.0) / n;
                            const double radius = 1 + 0.5 * draws[i].first / 1000.0;
                            points.emplace_back(2 * radius * std::cos(angle), radius * std::sin(angle));
                            h.push_back(0.05 + draws[i].second / 250.0);
                          }
                          return std::pair(points, h);
                        });
  });
}

// Closed form at every joint: the Bézier end points are the data (interpolation, and the
// last segment ends at the first point: closed), and with derivatives taken per unit of
// the spline parameter, B'(1) 3 (c3 - c2) / h_{i-1} and B''(1) = 6 (c1 - 2 c2 + c3) / h_{i-1}²
// of the incoming segment equal 3 (c1 - c0) / h_i and 6 (c0 - 2 c1 + c2) / h_i² of the
// outgoing one.
RC_GTEST_PROP(ClosedSpline, InterpolatesIsClosedAndC2AtEveryJoint, ()) {
  const auto [q, h] = *spline_input();
  const std::size_t n = q.size();
  const auto controls = closed_spline_controls(q, h);
  RC_ASSERT(controls.size() == n);
  double size = 0;
  for (const Point& p : q) size = std::max(size, norm(p - CGAL::ORIGIN));
  for (std::size_t i = 0; i < n; ++i) {
    const auto& in = controls[(i + n - 1) % n];
    const auto& out = controls[i];
    RC_ASSERT(out[0] == q[i]);
    RC_ASSERT(in[3] == q[i]);
    const double h_in = h[(i + n - 1) % n], h_out = h[i];
    const Vector d_in = 3 * (in[3] - in[2]) / h_in, d_out = 3 * (out[1] - out[0]) / h_out;
    const Vector dd_in = 6 * ((in[1] - CGAL::ORIGIN) - 2 * (in[2] - CGAL::ORIGIN) + (in[3] - CGAL::ORIGIN)) / (h_in * h_in);
    const Vector dd_out =
        6 * ((out[0] - CGAL::ORIGIN) - 2 * (out[1] - CGAL::ORIGIN) + (out[2] - CGAL::ORIGIN)) / (h_out * h_out);
    RC_ASSERT(norm(d_in - d_out) <= 1e-9 * (norm(d_in) + size));
    RC_ASSERT(norm(dd_in - dd_out) <= 1e-8 * (norm(dd_in) + size));
  }
}

TEST(ClosedSpline, IsACurveWithoutCornersThroughItsPoints) {
  const std::vector<Point> q{{0, 0}, {2, -0.5}, {3, 1}, {1.5, 2.5}, {-0.5, 1.5}};
  const geometry::Curve curve = closed_spline_curve(q, centripetal_knot_intervals(q));
  ASSERT_EQ(curve.components.size(), 1u);
  const auto& component = curve.components[0];
  EXPECT_TRUE(component.closed());
  EXPECT_TRUE(component.corners().empty());  // the unit tangent turns by < 1e-6 at joins
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_EQ(component.point(static_cast<double>(i)), q[i]);
}

TEST(ClosedSpline, RejectsBadInput) {
  const std::vector<Point> three{{0, 0}, {1, 0}, {0, 1}}, repeated{{0, 0}, {0, 0}, {1, 0}, {0, 1}};
  EXPECT_THROW(closed_spline_controls(std::span(three).first(2), std::vector<double>{1, 1}), std::invalid_argument);
  EXPECT_THROW(closed_spline_controls(three, std::vector<double>{1, 0, 1}), std::invalid_argument);
  EXPECT_THROW(closed_spline_controls(three, std::vector<double>{1, 1}), std::invalid_argument);
  EXPECT_THROW(closed_spline_controls(repeated, std::vector<double>{1, 1, 1, 1}), std::invalid_argument);
  EXPECT_NO_THROW(closed_spline_controls(three, std::vector<double>{1, 2, 3}));
}

// Sampling a spline curve: measured epsilon of a dense sampling is small, of a sparse one
// large, and adding points never raises it (the nearest sample only gets nearer).
const geometry::Local_feature_size& spline_lfs() {
  static const geometry::Local_feature_size lfs = [] {
    const std::vector<Point> q{{0, 0}, {2, -0.5}, {3, 1}, {1.5, 2.5}, {-0.5, 1.5}};
    return geometry::Local_feature_size(closed_spline_curve(q, centripetal_knot_intervals(q)));
  }();
  return lfs;
}

TEST(SplineSampling, DenseIsSmallSparseIsLarge) {
  const auto& lfs = spline_lfs();
  const double dense = measure_epsilon(lfs, geometry::uniform_sampling(lfs, 400).points, 0).epsilon;
  const double sparse = measure_epsilon(lfs, geometry::uniform_sampling(lfs, 5).points, 0).epsilon;
  EXPECT_LT(dense, 0.05);
  EXPECT_GT(sparse, 0.5);
}

RC_GTEST_PROP(SplineSampling, EpsilonIsMonotoneUnderAddingPoints, ()) {
  const auto& lfs = spline_lfs();
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
  const auto size = *rc::gen::inRange<std::size_t>(2, 40);
  const auto extra = *rc::gen::inRange<std::size_t>(1, 40);
  const std::vector<Point> all = geometry::random_sampling(lfs, size + extra, seed).points;
  const std::vector<Point> fewer(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(size));
  const double e_all = measure_epsilon(lfs, all, 0).epsilon, e_fewer = measure_epsilon(lfs, fewer, 0).epsilon;
  RC_ASSERT(e_all <= e_fewer * (1 + 1e-7));
}

TEST(MeasureAmbiguity, RejectsEqualPolygonsAndCrossingCurves) {
  Ambiguity_case c;
  c.points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 3}};
  c.orders = {std::vector<std::size_t>{0, 1, 2, 4, 3}, std::vector<std::size_t>{1, 2, 4, 3, 0}};  // same cycle
  EXPECT_FALSE(measure_ambiguity(c).valid);
  c.orders[1] = {0, 2, 1, 3, 4};  // a bow tie: its spline crosses itself
  EXPECT_FALSE(measure_ambiguity(c).valid);
  EXPECT_EQ(measure_ambiguity(c).max_epsilon(), INFINITY);
}

Ambiguity_search_options small_search(std::uint64_t seed) {
  return {.count = 2, .points = 7, .seed = seed, .evaluations = 40};
}

TEST(SearchAmbiguity, IsDeterministicForASeed) {
  const Ambiguity_search_result a = search_ambiguity(small_search(5)), b = search_ambiguity(small_search(5));
  ASSERT_EQ(a.best.points.size(), b.best.points.size());
  for (std::size_t i = 0; i < a.best.points.size(); ++i) EXPECT_EQ(a.best.points[i], b.best.points[i]);
  EXPECT_EQ(a.best.orders, b.best.orders);
  EXPECT_EQ(a.best.log_knot_factors, b.best.log_knot_factors);
  EXPECT_EQ(a.measure.epsilon, b.measure.epsilon);
  EXPECT_EQ(a.start_results, b.start_results);
}

// The mirror search keeps S symmetric under R: x -> -x and C2 = R(C1): every point's
// mirror image is in S, the second order is the first one mirrored, and the two curves,
// each measured from scratch, have the same epsilon up to the lfs estimate's error, while
// their polygons differ.
TEST(SearchAmbiguity, MirrorSearchKeepsTheCaseSymmetric) {
  const Ambiguity_search_options options{.count = 2, .seed = 3, .evaluations = 30, .mirror = true};
  const Ambiguity_search_result found = search_ambiguity(options);
  ASSERT_TRUE(found.measure.valid);
  const Ambiguity_case& c = found.best;
  const auto mirror_of = [&](std::size_t i) {
    const Point image(-c.points[i].x(), c.points[i].y());
    return static_cast<std::size_t>(std::ranges::find(c.points, image) - c.points.begin());
  };
  for (std::size_t k = 0; k < c.orders[0].size(); ++k) EXPECT_EQ(c.orders[1][k], mirror_of(c.orders[0][k])) << k;
  EXPECT_NE(order_edges(c.orders[0]), order_edges(c.orders[1]));
  EXPECT_NEAR(found.measure.epsilon[0], found.measure.epsilon[1], 2 * lfs_relative_error_bound * found.measure.epsilon[0]);
  EXPECT_GE(c.points.size(), 6u);
  EXPECT_LE(c.points.size(), 20u);
}

// Via points come as a second stage of the climb: both curves of the best case have one
// via point between every two consecutive samples, mirror images of each other, and the
// search is as deterministic as without them.
TEST(SearchAmbiguity, ViaPointsFollowTheClimbAndKeepTheMirror) {
  const Ambiguity_search_options options{.count = 2, .seed = 3, .evaluations = 20, .via_points = true, .mirror = true};
  const Ambiguity_search_result found = search_ambiguity(options), again = search_ambiguity(options);
  ASSERT_TRUE(found.measure.valid);
  const Ambiguity_case& c = found.best;
  for (int k = 0; k < 2; ++k) EXPECT_EQ(c.via[k].size(), c.points.size()) << k;
  for (std::size_t e = 0; e < c.via[0].size(); ++e) EXPECT_EQ(c.via[1][e], Point(-c.via[0][e].x(), c.via[0][e].y())) << e;
  EXPECT_EQ(found.start_results, again.start_results);
  EXPECT_EQ(found.evaluations, 2 * (2 * options.evaluations + 2));
}

// Is `edges` one cycle through all n points?
bool hamiltonian_cycle(const std::vector<geometry::Edge>& edges, std::size_t n) {
  if (edges.size() != n) return false;
  std::vector<std::vector<std::size_t>> adjacent(n);
  for (const auto& [i, j] : edges) {
    if (i >= n || j >= n || i == j) return false;
    adjacent[i].push_back(j), adjacent[j].push_back(i);
  }
  for (const auto& a : adjacent)
    if (a.size() != 2) return false;
  std::size_t previous = 0, current = adjacent[0][0], steps = 1;
  while (current != 0) {
    const std::size_t next = adjacent[current][0] == previous ? adjacent[current][1] : adjacent[current][0];
    previous = current, current = next, ++steps;
  }
  return steps == n;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The written case, re-measured from its files alone: points and edge lists through
// point_io / edge_io, each curve as the spec svg:curve_K.svg (what `curvebench measure`
// reads), its lfs at the default density, and measure_epsilon against the points.
TEST(SearchAmbiguity, WrittenCaseReMeasuresFromItsFiles) {
  const Ambiguity_search_result found = search_ambiguity(small_search(11));
  ASSERT_TRUE(found.measure.valid);
  const auto directory = std::filesystem::temp_directory_path() / ("ambiguity_test_" + std::to_string(::getpid()));
  const Ambiguity_files files = write_ambiguity_case(directory, found.best, found.measure, 11);
  const std::vector<Point> points = geometry::read_point_file(files.points).points;
  ASSERT_EQ(points.size(), found.best.points.size());
  const double reported_max = found.measure.max_epsilon();
  std::vector<geometry::Edge> polygons[2];
  for (int k = 0; k < 2; ++k) {
    polygons[k] = geometry::canonical_edges(geometry::read_edges(files.edges[k]));
    EXPECT_TRUE(hamiltonian_cycle(polygons[k], points.size())) << k;
    const geometry::Local_feature_size lfs(geometry::make_curve("svg:" + files.curves[k].string()));
    ASSERT_EQ(lfs.curve().components.size(), 1u);
    EXPECT_TRUE(lfs.curve().components[0].closed());
    EXPECT_TRUE(lfs.sharp_points().empty()) << "curve " << k + 1 << " is not smooth and simple";
    // Each point of S lies on the curve: it is a Bézier end point of the path.
    for (const Point& p : points) {
      double nearest = INFINITY;
      const auto& component = lfs.curve().components[0];
      for (std::size_t s = 0; s < component.piece_count(); ++s)
        nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(p, component.point(static_cast<double>(s)))));
      EXPECT_LE(nearest, 1e-12 * component.length());
    }
    const double epsilon = measure_epsilon(lfs, points, 0).epsilon;
    EXPECT_NEAR(epsilon, found.measure.epsilon[k], 1e-9 * epsilon) << k;
    EXPECT_LE(epsilon, reported_max * (1 + 1e-9)) << k;
  }
  EXPECT_NE(polygons[0], polygons[1]);
  const std::string summary = read_text(files.summary);
  EXPECT_NE(summary.find("\"max_epsilon\": " + geometry::format_number(reported_max)), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"lfs_error_bound\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::file_size(files.picture) > 0);
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace curvebench::certify
