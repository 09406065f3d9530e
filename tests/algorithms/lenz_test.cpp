// Lenz (algorithms/lenz.h) against a brute force of its definition over ALL pairs of
// points, in rationals (CGAL::Gmpq): each point's k nearest by sorting every other point,
// the probe cone tested on rationals, the same seed order and trace rule. Plus the cases
// the paper claims (survey, "Feature Size Criteria"): dense smooth closed curves, open
// curves, sharp corners (the survey's corner family), a self-intersecting figure eight
// (sampled at its crossing and between samples); regular polygons whose answer follows
// from the rule; degenerate and extreme input; the registry description.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <numeric>
#include <set>
#include <sstream>

#include "algorithms/lenz.h"
#include "algorithms/registry.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/corner_curve.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "tests/support/edge_sets.h"
#include "tests/support/hand_made_curves.h"
#include "tests/support/point_generators.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

using Q = CGAL::Gmpq;
using Edges = std::vector<Edge>;
using testing::canonical;
using testing::cycle_edges;
using testing::path_edges;
using testing::degrees;

// ---------------------------------------------------------------- rational brute force

Q squared_distance(const Point& a, const Point& b) {
  const Q dx = Q(a.x()) - Q(b.x()), dy = Q(a.y()) - Q(b.y());
  return dx * dx + dy * dy;
}

bool brute_in_cone(const Point& o, const Point& p, const Point& q, double cos_alpha) {
  const Q dx = Q(p.x()) - Q(o.x()), dy = Q(p.y()) - Q(o.y());
  const Q vx = Q(q.x()) - Q(p.x()), vy = Q(q.y()) - Q(p.y());
  const Q along = dx * vx + dy * vy;
  return along > 0 && along * along >= Q(cos_alpha) * Q(cos_alpha) * (dx * dx + dy * dy) * (vx * vx + vy * vy);
}

Edges brute_lenz(const std::vector<Point>& points, double alpha_degrees, std::size_t k) {
  const std::size_t n = points.size();
  const double cos_alpha = std::cos(alpha_degrees * std::numbers::pi / 180);
  std::vector<std::vector<std::size_t>> nearest(n);
  for (std::size_t p = 0; p < n; ++p) {
    std::vector<std::size_t>& ranked = nearest[p];
    std::vector<Q> distance(n);
    for (std::size_t q = 0; q < n; ++q)
      if (q != p) ranked.push_back(q), distance[q] = squared_distance(points[p], points[q]);
    std::sort(ranked.begin(), ranked.end(), [&](std::size_t a, std::size_t b) {
      return distance[a] < distance[b] || (distance[a] == distance[b] && a < b);
    });
    if (ranked.size() > k) ranked.resize(k);
  }
  std::set<Edge> pairs;
  for (std::size_t p = 0; p < n; ++p)
    if (!nearest[p].empty()) pairs.insert({std::min(p, nearest[p][0]), std::max(p, nearest[p][0])});
  std::vector<Edge> seeds(pairs.begin(), pairs.end());
  std::stable_sort(seeds.begin(), seeds.end(), [&](const Edge& a, const Edge& b) {
    return squared_distance(points[a.first], points[a.second]) < squared_distance(points[b.first], points[b.second]);
  });

  std::set<Edge> edges;
  std::vector<bool> used(n, false);
  const auto add = [&](std::size_t a, std::size_t b) {
    used[a] = used[b] = true;
    return edges.insert({std::min(a, b), std::max(a, b)}).second;
  };
  const auto trace = [&](std::size_t o, std::size_t p) {
    for (;;) {
      std::size_t next = n;
      for (const std::size_t q : nearest[p])
        if (brute_in_cone(points[o], points[p], points[q], cos_alpha)) {
          next = q;
          break;
        }
      if (next == n || !add(p, next)) return;
      o = p;
      p = next;
    }
  };
  std::vector<Edge> lone;
  for (const auto& [a, b] : seeds) {
    if (used[a] || used[b]) continue;
    const std::size_t before = edges.size();
    add(a, b);
    trace(a, b);
    trace(b, a);
    if (edges.size() == before + 1) lone.emplace_back(a, b);
  }
  std::vector<Edge> result(edges.begin(), edges.end());
  const auto degree = degrees(result, n);
  for (const Edge& e : lone)
    if (degree[e.first] > 1 && degree[e.second] > 1) edges.erase(e);
  return {edges.begin(), edges.end()};
}

// ---------------------------------------------------------------- the definition

RC_GTEST_PROP(Lenz, MatchesTheDefinitionOverAllPairs, ()) {
  const auto points = *testing::point_sets(40);
  const double alpha = *rc::gen::element(20.0, 40.0, 60.0, 85.0);
  const std::size_t k = *rc::gen::inRange<std::size_t>(1, 12);
  RC_ASSERT(lenz_reconstruction(points, alpha, k) == brute_lenz(points, alpha, k));
}

RC_GTEST_PROP(Lenz, MatchesTheDefinitionOnClusteredInput, ()) {
  const auto points = *testing::clustered_points();
  RC_ASSERT(lenz_reconstruction(points) == brute_lenz(points, 40, 8));
}

RC_GTEST_PROP(Lenz, ScalingByAPowerOfTwoChangesNothing, ()) {
  const auto points = *testing::uniform_points(60);
  const int exponent = *rc::gen::inRange(-900, 900);
  RC_ASSERT(lenz_reconstruction(testing::scaled_by(points, exponent)) == lenz_reconstruction(points));
}

TEST(Lenz, MatchesTheDefinitionOnCurveSamples) {
  for (const std::uint64_t seed : {3u, 11u}) {
    const auto sample = geometry::random_sampling(
        geometry::Local_feature_size(geometry::random_fourier_curve(seed)), 150, seed);
    EXPECT_EQ(lenz_reconstruction(sample.points), brute_lenz(sample.points, 40, 8)) << seed;
  }
}

// ---------------------------------------------------------------- hand cases

// A regular polygon turns by 360/n at each vertex, and each vertex's nearest points ahead
// are its neighbours along it: the probe follows the polygon round iff 360/n <= alpha.
// Otherwise no trace leaves its seed, and the seeds form a matching of polygon sides
// (greedy by rounded-apart lengths, so not necessarily a perfect one).
TEST(Lenz, RegularPolygonsCloseIffTheirTurnFitsTheProbe) {
  for (const std::size_t n : {3u, 4u, 5u, 6u, 7u, 8u, 10u, 12u, 100u}) {
    const auto polygon = testing::regular_polygon(n, 1.0, 0.1);
    const Edges edges = lenz_reconstruction(polygon, 40, 8);
    if (n >= 10) {
      EXPECT_EQ(edges, cycle_edges(n)) << n;
      continue;
    }
    const auto degree = degrees(edges, n);
    EXPECT_TRUE(std::all_of(degree.begin(), degree.end(), [](std::size_t d) { return d <= 1; })) << n;
    EXPECT_FALSE(edges.empty()) << n;
    for (const auto& [i, j] : edges) EXPECT_TRUE(j == i + 1 || (i == 0 && j == n - 1)) << n;
  }
}

TEST(Lenz, TinyCollinearAndInvalidInput) {
  EXPECT_TRUE(lenz_reconstruction(std::vector<Point>{}).empty());
  EXPECT_TRUE(lenz_reconstruction(std::vector<Point>{{1, 2}}).empty());
  EXPECT_EQ(lenz_reconstruction(std::vector<Point>{{0, 0}, {3, 4}}), (Edges{{0, 1}}));
  // Three in a row: one straight trace; a right angle: wider than the probe, one edge.
  EXPECT_EQ(lenz_reconstruction(std::vector<Point>{{0, 0}, {2, 0}, {1, 0}}), (Edges{{0, 2}, {1, 2}}));
  EXPECT_EQ(lenz_reconstruction(std::vector<Point>{{0, 0}, {1, 0}, {0, 2}}), (Edges{{0, 1}}));
  // A shuffled line is the path in order along it for k >= 2 (k = 1 sees only one side).
  const std::vector<Point> line{{3, 3}, {0, 0}, {1, 1}, {-2, -2}, {2, 2}};
  for (const std::size_t k : {2u, 8u})
    EXPECT_EQ(lenz_reconstruction(line, 40, k), (Edges{{0, 4}, {1, 2}, {1, 3}, {2, 4}})) << k;
  EXPECT_THROW(lenz_reconstruction(std::vector<Point>{{0, 0}, {1, 1}, {0, 0}}), std::invalid_argument);
  EXPECT_THROW(lenz_reconstruction(std::vector<Point>{{0, 0}, {NAN, 1}}), std::invalid_argument);
  EXPECT_THROW(lenz_reconstruction(std::vector<Point>{{0, 0}, {INFINITY, 1}}), std::invalid_argument);
  EXPECT_THROW(lenz_reconstruction(line, 0, 8), std::invalid_argument);
  EXPECT_THROW(lenz_reconstruction(line, 90, 8), std::invalid_argument);
  EXPECT_THROW(lenz_reconstruction(line, 40, 0), std::invalid_argument);
}

TEST(Lenz, ExtremeCoordinatesAndGridsDoNotBreakIt) {
  // A circle at 1e300 and 1e-300 (not exactly scaled: products overflow and underflow in
  // double, so the exact stage decides) is still its cycle; a grid, full of ties, is the
  // brute force's answer.
  const auto circle = testing::regular_polygon(40, 1.0, 0.3);
  for (const double scale : {1e300, 1e-300, 1.0}) {
    std::vector<Point> scaled;
    for (const Point& p : circle) scaled.emplace_back(p.x() * scale, p.y() * scale);
    EXPECT_EQ(lenz_reconstruction(scaled), cycle_edges(40)) << scale;
  }
  std::vector<Point> grid;
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 12; ++y) grid.emplace_back(x, y);
  EXPECT_EQ(lenz_reconstruction(grid), brute_lenz(grid, 40, 8));
}

// ---------------------------------------------------------------- the paper's cases

TEST(Lenz, ReconstructsDenseSmoothClosedCurves) {
  for (const std::size_t n : {50u, 200u, 1000u}) {
    const geometry::Sample ellipse =
        geometry::uniform_sampling(geometry::Local_feature_size(geometry::ellipse(2, 1)), n);
    EXPECT_EQ(lenz_reconstruction(ellipse.points), canonical(ellipse.edges)) << n;
  }
  // Random Fourier curves, one component (the survey: Lenz "does not handle multiple curves
  // well"; see below), safe-epsilon-sampled below the paper's claimed 0.4.
  std::ostringstream table;
  for (const double epsilon : {0.1, 0.2, 0.3, 0.35, 0.4, 0.45}) {
    int total = 0, exact = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      const testing::Sampled_case c = testing::sampled_fourier_curves(seed * 7919, 1, 2 + seed % 7, epsilon);
      ++total;
      const bool ok = lenz_reconstruction(c.sample.points) == c.truth;
      exact += ok;
      if (c.measured_epsilon < 0.4) {  // the paper's claim
        EXPECT_TRUE(ok) << c;
      }
    }
    table << "epsilon " << epsilon << ": " << exact << " / " << total << " exact\n";
  }
  std::cout << table.str();
}

TEST(Lenz, SeveralSeparateClosedCurves) {
  // Components far apart against their spacing: each is traced from its own seed, and a
  // closed curve has no end whose probe could reach across to another.
  std::ostringstream table;
  int total = 0, exact = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const testing::Sampled_case c = testing::sampled_fourier_curves(seed * 104729, 2 + seed % 2, 2 + seed % 5, 0.2);
    ++total;
    exact += lenz_reconstruction(c.sample.points) == c.truth;
  }
  std::cout << "two or three components at epsilon 0.2: " << exact << " / " << total << " exact\n";
  EXPECT_EQ(exact, total);
}

TEST(Lenz, ReconstructsAnOpenArc) {
  // The probe at either end sees only points behind it: both traces stop there.
  std::vector<Point> points;
  for (int i = 0; i <= 200; ++i) points.emplace_back(i * 0.03, 0.4 * std::sin(i * 0.03));
  EXPECT_EQ(lenz_reconstruction(points), path_edges(201));
}

// The survey's sharp-corner family sampled uniformly with a sample at the apex
// (geometry::uniform_sampling starts at s = 0, the corner). The tangent turns by 180° minus
// the opening angle there; a turn wider than alpha empties the probe at the apex, so the
// trace stops and a later trace along the other side joins it.
TEST(Lenz, ReconstructsSharpCorners) {
  std::ostringstream table;
  table << "angle  per circle 10 16 20 32\n";
  for (int angle = 10; angle <= 170; angle += 10) {
    std::string row;
    for (const int per_circle : {10, 16, 20, 32}) {
      const geometry::Curve curve = geometry::sharp_corner_curve(angle);
      const geometry::Local_feature_size lfs(curve);
      const double length = curve.components.front().length();
      const auto n = static_cast<std::size_t>(std::ceil(length / (2 * std::numbers::pi / per_circle)));
      const geometry::Sample sample = geometry::uniform_sampling(lfs, n);
      ASSERT_TRUE(std::abs(sample.points.front().y()) < 1e-12);  // the apex is sampled
      const bool ok = lenz_reconstruction(sample.points) == canonical(sample.edges);
      EXPECT_TRUE(ok) << "angle " << angle << ", " << per_circle << " per circle";
      row += ok ? " y" : " .";
    }
    table << angle << "    " << row << '\n';
  }
  std::cout << table.str();
}

TEST(Lenz, TracesThroughTheCrossingOfAFigureEightSampledAtTheCrossing) {
  // n samples evenly in t, both branches sampled at the origin: one point there, of degree
  // 4 in the truth. Each branch reaches it straight, the other branch's points lie 90°
  // off, so the trace goes on through it along its own branch.
  for (const std::size_t n : {200u, 400u, 1000u}) {
    const auto eight = testing::figure_eight_sampled_at_the_crossing(n);
    const Edges edges = lenz_reconstruction(eight.points);
    EXPECT_EQ(edges, eight.truth) << n;
    EXPECT_EQ(degrees(edges, eight.points.size())[eight.crossing], 4u) << n;
  }
}

TEST(Lenz, ReconstructsTheCrossingEdgesOfAFigureEightSampledBetween) {
  // Samples at t = 2 pi (i + 1/2) / n: the crossing lies midway between two samples on
  // each branch, whose edges cross. The other branch's points lie about 45° off the probe.
  for (const std::size_t n : {200u, 400u, 1000u}) {
    const auto eight = testing::figure_eight_sampled_between(n);
    EXPECT_EQ(lenz_reconstruction(eight.points), eight.truth) << n;
  }
}

// ---------------------------------------------------------------- registry description

TEST(Lenz, DescribesItselfAsTheSurveyDoes) {
  const Algorithm algorithm = lenz_algorithm();
  EXPECT_EQ(algorithm.name, "lenz");
  EXPECT_EQ(algorithm.title, "Lenz");
  EXPECT_EQ(algorithm.category, "Feature Size Criteria");
  EXPECT_EQ(algorithm.parameters.size(), 2u);  // Table 1: two parameters, one the angle
  const Capabilities& c = algorithm.capabilities;
  EXPECT_EQ(c.non_uniform, Support::yes);
  EXPECT_EQ(c.noise, Support::no);
  EXPECT_EQ(c.outliers, Support::no);
  EXPECT_EQ(c.manifold, Support::no);
  EXPECT_EQ(c.open, Support::yes);
  EXPECT_EQ(c.multiple, Support::no);
  EXPECT_EQ(c.sharp, Support::yes);
  EXPECT_TRUE(c.guarantee);
  EXPECT_EQ(algorithm.condition.statement, "epsilon < 0.48 (no proof)");
  EXPECT_FALSE(algorithm.condition.epsilon_below.has_value());  // unproven: not certified

  // Through the registry's entry point: duplicates merged, parameters by name.
  const auto polygon = testing::regular_polygon(12, 2, 0.1);
  std::vector<Point> doubled = polygon;
  doubled.insert(doubled.end(), polygon.begin(), polygon.end());
  EXPECT_EQ(reconstruct(algorithm, doubled).edges, cycle_edges(12));
  const auto degree = degrees(reconstruct(algorithm, polygon, {{"alpha", 20}}).edges, 12);  // 30° turns: seeds only
  EXPECT_EQ(*std::max_element(degree.begin(), degree.end()), 1u);
  EXPECT_THROW(reconstruct(algorithm, polygon, {{"k", 1}}), std::invalid_argument);  // its nearest point is often behind: no trace
}

}  // namespace
}  // namespace curvebench::algorithms
