// The survey's evaluation distances ("Evaluation Criteria") against closed forms and a
// brute-force oracle, the nearest-segment index against a scan of every segment, and the
// topology counts against a breadth-first search.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <vector>

#include "geometry/metrics/curve_distance.h"
#include "geometry/metrics/curve_topology.h"
#include "geometry/metrics/nearest_segment_index.h"

namespace curvebench::geometry {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

struct Polyline {
  std::vector<Point> points;
  std::vector<Edge> edges;
  Polyline_view view() const { return {points, edges}; }
};

// A closed polygon through `corners`.
Polyline polygon(std::vector<Point> corners) {
  Polyline p{std::move(corners), {}};
  for (std::size_t i = 0; i < p.points.size(); ++i) p.edges.emplace_back(i, (i + 1) % p.points.size());
  return p;
}

Polyline square(double x, double y) { return polygon({{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}); }

double spacing_of(const Polyline& p) { return default_distance_spacing(p.view()); }

TEST(CurveDistance, ParallelSegmentsAtDistanceD) {
  for (const double d : {1e-6, 0.25, 3.0}) {
    const Polyline a{{{0, 0}, {1, 0}}, {{0, 1}}}, b{{{0, d}, {1, d}}, {{0, 1}}};
    const Curve_distance distance = curve_distance(a.view(), b.view(), spacing_of(a));
    EXPECT_NEAR(distance.hausdorff, d, 1e-12 * (1 + d));
    EXPECT_NEAR(distance.rms, d, 1e-12 * (1 + d));
  }
}

// Unit square against its copy shifted by s in x (0 < s < 1/2): the farthest points are s
// apart, and per direction the integral of the squared distance along the boundary is
// s^2 (left side) + 2 s^3 / 3 (top and bottom, near the corners) + s^2 - 4 s^3 / 3 (right
// side, inside the other square: min(s, y, 1 - y)^2), so RMS^2 = (2 s^2 - 2 s^3 / 3) / 4.
TEST(CurveDistance, SquareAgainstItsShiftedCopy) {
  for (const double s : {0.05, 0.1, 0.3}) {
    const Polyline a = square(0, 0), b = square(s, 0);
    const Curve_distance distance = curve_distance(a.view(), b.view(), spacing_of(a));
    EXPECT_NEAR(distance.hausdorff, s, 1e-12);
    EXPECT_NEAR(distance.rms, std::sqrt((2 * s * s - 2 * s * s * s / 3) / 4), 1e-6) << s;
  }
}

TEST(CurveDistance, CircleAgainstAConcentricCircle) {
  // Polygons of 2000 sides, radii 1 and 1.1: every point is 0.1 from the other (up to the
  // polygons' sagitta, 1.2e-6).
  const auto circle = [](double r) {
    std::vector<Point> corners;
    for (int i = 0; i < 2000; ++i)
      corners.emplace_back(r * std::cos(2 * std::numbers::pi * i / 2000), r * std::sin(2 * std::numbers::pi * i / 2000));
    return polygon(corners);
  };
  const Curve_distance distance = curve_distance(circle(1).view(), circle(1.1).view(), 1e-3);
  EXPECT_NEAR(distance.hausdorff, 0.1, 2e-6);
  EXPECT_NEAR(distance.rms, 0.1, 2e-6);
}

TEST(CurveDistance, IdenticalCurvesAreAtZeroAndEmptyOnesAtInfinity) {
  const Polyline a = square(2, 3), none;
  EXPECT_EQ(curve_distance(a.view(), a.view(), spacing_of(a)).hausdorff, 0);
  EXPECT_EQ(curve_distance(a.view(), a.view(), spacing_of(a)).rms, 0);
  EXPECT_EQ(curve_distance(a.view(), none.view(), 1).hausdorff, infinity);
  EXPECT_EQ(curve_distance(none.view(), a.view(), 1).rms, infinity);
  EXPECT_EQ(curve_distance(none.view(), none.view(), 1).hausdorff, 0);
}

TEST(CurveDistance, ADegenerateEdgeIsAPoint) {
  const Polyline a{{{0, 0}, {1, 0}}, {{0, 1}}}, b{{{0.5, 2}, {0.5, 2}}, {{0, 1}}};
  const Curve_distance distance = curve_distance(a.view(), b.view(), 0.01);
  EXPECT_NEAR(distance.hausdorff, std::hypot(0.5, 2), 1e-12);  // from an end of a to b
  // b has no length: only a's samples carry weight, each at hypot(x - 0.5, 2).
  double squares = 0;
  for (int k = 0; k < 100; ++k) squares += std::pow((k + 0.5) / 100 - 0.5, 2) + 4;
  EXPECT_NEAR(distance.rms, std::sqrt(squares / 100), 1e-9);
}

// A regular polygon of n sides inscribed in the circle of radius r about the origin, a
// corner at angle 0: for n divisible by 4, corners on both axes.
Polyline circle_polygon(double r, int n) {
  std::vector<Point> corners;
  for (int i = 0; i < n; ++i)
    corners.emplace_back(r * std::cos(2 * std::numbers::pi * i / n), r * std::sin(2 * std::numbers::pi * i / n));
  return polygon(corners);
}

// Points as a simplifier's isolated output vertices: each an edge whose ends coincide.
Polyline isolated_points(std::vector<Point> points) {
  Polyline p{std::move(points), {}};
  for (std::size_t i = 0; i < p.points.size(); ++i) p.edges.emplace_back(i, i);
  return p;
}

// [0, 1] lies on [0, 2]; the other way, x in [1, 2] is x - 1 away: H = 1 and
// RMS^2 = (1 / 2) * integral of (x - 1)^2 over [1, 2] = 1 / 6.
TEST(OneWayCurveDistance, ASegmentAndOneTwiceAsLongDifferByDirection) {
  const Polyline shorter{{{0, 0}, {1, 0}}, {{0, 1}}}, longer{{{0, 0}, {2, 0}}, {{0, 1}}};
  const Curve_distance in = one_way_curve_distance(shorter.view(), longer.view(), spacing_of(longer));
  EXPECT_EQ(in.hausdorff, 0);
  EXPECT_EQ(in.rms, 0);
  const Curve_distance out = one_way_curve_distance(longer.view(), shorter.view(), spacing_of(longer));
  EXPECT_NEAR(out.hausdorff, 1, 1e-12);
  EXPECT_NEAR(out.rms, std::sqrt(1.0 / 6), 1e-6);
}

// The unit circle against its four points on the axes, as isolated vertices: a point of
// the circle at angle t in [0, pi/4] is 2 sin(t/2) from (1, 0), so H = 2 sin(pi/8) and
// RMS^2 = (4 / pi) * integral over [0, pi/4] of 4 sin^2(t/2) dt = 2 - 4 sqrt(2) / pi.
// The points lie on the curve: 0 the other way.
TEST(OneWayCurveDistance, TheCircleAgainstFourOfItsPoints) {
  const Polyline circle = circle_polygon(1, 4000), points = isolated_points({{1, 0}, {0, 1}, {-1, 0}, {0, -1}});
  const Curve_distance from_curve = one_way_curve_distance(circle.view(), points.view(), 1e-3);
  EXPECT_NEAR(from_curve.hausdorff, 2 * std::sin(std::numbers::pi / 8), 1e-9);
  EXPECT_NEAR(from_curve.rms, std::sqrt(2 - 4 * std::sqrt(2.0) / std::numbers::pi), 1e-5);
  const Curve_distance to_curve = one_way_curve_distance(points.view(), circle.view(), 1e-3);
  EXPECT_NEAR(to_curve.hausdorff, 0, 1e-12);
  EXPECT_NEAR(to_curve.rms, 0, 1e-12);
}

// A vertex at the centre and an edge on the circle: the vertex is 1 from the curve (up to the
// polygon's sagitta, 3.1e-7), which its Hausdorff distance says and the RMS, weighted by
// length, does not; alone, the vertex is the whole RMS.
TEST(OneWayCurveDistance, AnIsolatedVertexCountsInHausdorffAndWeighsNothingBesideEdges) {
  const Polyline circle = circle_polygon(1, 4000);
  Polyline output = isolated_points({{0, 0}});
  output.points.insert(output.points.end(), {circle.points[0], circle.points[1]});
  output.edges.emplace_back(1, 2);
  const Curve_distance mixed = one_way_curve_distance(output.view(), circle.view(), 1e-4);
  EXPECT_NEAR(mixed.hausdorff, 1, 1e-6);
  EXPECT_NEAR(mixed.rms, 0, 1e-12);
  const Curve_distance alone = one_way_curve_distance(isolated_points({{0, 0}}).view(), circle.view(), 1e-3);
  EXPECT_NEAR(alone.hausdorff, 1, 1e-6);
  EXPECT_NEAR(alone.rms, 1, 1e-6);
  // Points without length weigh the same: one on the circle, one at its centre.
  const Curve_distance two = one_way_curve_distance(isolated_points({{1, 0}, {0, 0}}).view(), circle.view(), 1e-3);
  EXPECT_NEAR(two.hausdorff, 1, 1e-6);
  EXPECT_NEAR(two.rms, std::sqrt(0.5), 1e-6);
  // The circle is 1 from the centre everywhere.
  const Curve_distance back = one_way_curve_distance(circle.view(), isolated_points({{0, 0}}).view(), 1e-3);
  EXPECT_NEAR(back.hausdorff, 1, 1e-12);
  EXPECT_NEAR(back.rms, 1, 1e-6);
}

TEST(OneWayCurveDistance, NothingToMapIsZeroAndNothingToMapOntoIsInfinite) {
  const Polyline a = square(0, 0), none;
  EXPECT_EQ(one_way_curve_distance(none.view(), a.view(), 1).hausdorff, 0);
  EXPECT_EQ(one_way_curve_distance(none.view(), none.view(), 1).rms, 0);
  EXPECT_EQ(one_way_curve_distance(a.view(), none.view(), 1).hausdorff, infinity);
  EXPECT_EQ(one_way_curve_distance(a.view(), none.view(), 1).rms, infinity);
}

TEST(NormalDeviation, IsTheAngleBetweenTheLines) {
  const Polyline original{{{-10, 0}, {10, 0}}, {{0, 1}}};
  for (const double degrees : {0.0, 30.0, 90.0, 150.0}) {
    const double a = degrees * std::numbers::pi / 180;
    const Polyline edge{{{0, 0}, {std::cos(a), std::sin(a)}}, {{0, 1}}};
    EXPECT_NEAR(normal_deviation_degrees(original.view(), edge.view()), degrees > 90 ? 180 - degrees : degrees, 1e-9);
  }
  EXPECT_TRUE(std::isnan(normal_deviation_degrees(Polyline{}.view(), original.view())));
  EXPECT_EQ(normal_deviation_degrees(original.view(), Polyline{}.view()), 0);
}

// Random segment soups: long and short, degenerate, clustered, at scales from 1e-9 to 1e9.
rc::Gen<Polyline> segment_soups() {
  return rc::gen::exec([] {
    const double scale = std::pow(10.0, *rc::gen::inRange(-9, 10));
    const int n = *rc::gen::inRange(1, 40);
    Polyline p;
    for (int i = 0; i < 2 * n; ++i)
      p.points.emplace_back(scale * *rc::gen::inRange(-1000, 1001) / 1000.0, scale * *rc::gen::inRange(-1000, 1001) / 1000.0);
    for (int i = 0; i < n; ++i) {
      const bool degenerate = *rc::gen::inRange(0, 8) == 0;
      p.edges.emplace_back(2 * i, degenerate ? 2 * i : 2 * i + 1);
    }
    return p;
  });
}

double squared_distance_to_segment(const Point& q, const Point& a, const Point& b) {
  return a == b ? CGAL::squared_distance(q, a) : CGAL::squared_distance(q, Kernel::Segment_2(a, b));
}

RC_GTEST_PROP(NearestSegmentIndex, IsTheClosestOfAllSegments, ()) {
  const Polyline soup = *segment_soups();
  const Nearest_segment_index index(soup.points, soup.edges);
  const double scale = std::abs(soup.points.front().x()) + std::abs(soup.points.front().y()) + 1e-9;
  for (int k = 0; k < 20; ++k) {
    const double far = *rc::gen::element(1.0, 3.0, 1e3);
    const Point q(far * scale * *rc::gen::inRange(-1000, 1001) / 1000.0, far * scale * *rc::gen::inRange(-1000, 1001) / 1000.0);
    double best = infinity;
    for (const auto& [i, j] : soup.edges) best = std::min(best, squared_distance_to_segment(q, soup.points[i], soup.points[j]));
    const auto nearest = index.nearest(q);
    RC_ASSERT(nearest.has_value());
    RC_ASSERT(std::abs(nearest->squared_distance - best) <= 1e-9 * best + 1e-300);
    const auto& [i, j] = soup.edges[nearest->edge];
    RC_ASSERT(std::abs(squared_distance_to_segment(q, soup.points[i], soup.points[j]) - best) <= 1e-9 * best + 1e-300);
  }
}

// The oracle: both directions sampled ten times finer than the tested spacing, each sample
// against every segment. The distance to the other curve is 1-Lipschitz along a curve, so
// the tested value lies within half a sample step of the true one either way: the fine
// oracle's step is a tenth of the spacing.
double brute_force_one_way(const Polyline& from, const Polyline& to, double spacing) {
  double largest = 0;
  for (const auto& [i, j] : from.edges) {
    const Point &p = from.points[i], &q = from.points[j];
    const int steps = 10 * static_cast<int>(std::ceil(std::sqrt(CGAL::squared_distance(p, q)) / spacing)) + 1;
    for (int k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      const Point s(p.x() + t * (q.x() - p.x()), p.y() + t * (q.y() - p.y()));
      double nearest = infinity;
      for (const auto& [u, v] : to.edges) nearest = std::min(nearest, squared_distance_to_segment(s, to.points[u], to.points[v]));
      largest = std::max(largest, std::sqrt(nearest));
    }
  }
  return largest;
}

RC_GTEST_PROP(CurveDistance, HausdorffMatchesAFineBruteForce, ()) {
  const Polyline a = *segment_soups(), b = *segment_soups();
  const double spacing = 0.05 * std::max(spacing_of(a), spacing_of(b)) * 1000;
  const double oracle = std::max(brute_force_one_way(a, b, spacing), brute_force_one_way(b, a, spacing));
  const Curve_distance tested = curve_distance(a.view(), b.view(), spacing);
  RC_ASSERT(tested.hausdorff <= oracle * (1 + 1e-9) + spacing / 10);
  RC_ASSERT(tested.hausdorff >= oracle - spacing);
  RC_ASSERT(tested.rms <= tested.hausdorff * (1 + 1e-12) + 1e-300);
  RC_ASSERT(curve_distance(b.view(), a.view(), spacing).hausdorff == tested.hausdorff);
}

// Each direction against the same oracle, and the two directions against the symmetric
// distance: its Hausdorff is the larger, its RMS the length-weighted mean of their squares.
RC_GTEST_PROP(OneWayCurveDistance, MatchesAFineBruteForceAndMakesUpTheSymmetricDistance, ()) {
  const Polyline a = *segment_soups(), b = *segment_soups();
  const double spacing = 0.05 * std::max(spacing_of(a), spacing_of(b)) * 1000;
  const Curve_distance ab = one_way_curve_distance(a.view(), b.view(), spacing);
  const Curve_distance ba = one_way_curve_distance(b.view(), a.view(), spacing);
  for (const auto& [tested, oracle] : {std::pair(ab.hausdorff, brute_force_one_way(a, b, spacing)),
                                       std::pair(ba.hausdorff, brute_force_one_way(b, a, spacing))}) {
    RC_ASSERT(tested <= oracle * (1 + 1e-9) + spacing / 10);
    RC_ASSERT(tested >= oracle - spacing);
  }
  const Curve_distance both = curve_distance(a.view(), b.view(), spacing);
  RC_ASSERT(both.hausdorff == std::max(ab.hausdorff, ba.hausdorff));
  const auto length = [](const Polyline& p) {
    double sum = 0;
    for (const auto& [i, j] : p.edges) sum += std::sqrt(CGAL::squared_distance(p.points[i], p.points[j]));
    return sum;
  };
  const double la = length(a), lb = length(b);
  if (la > 0 && lb > 0) {
    const double mean_square = (ab.rms * ab.rms * la + ba.rms * ba.rms * lb) / (la + lb);
    RC_ASSERT(std::abs(both.rms - std::sqrt(mean_square)) <= 1e-9 * both.hausdorff + 1e-300);
  }
}

// Components and degrees by breadth-first search, written independently.
Curve_topology by_search(std::size_t n, const std::vector<Edge>& edges) {
  std::vector<std::vector<std::size_t>> adjacent(n);
  for (const auto& [i, j] : edges) adjacent[i].push_back(j), adjacent[j].push_back(i);
  Curve_topology t;
  std::vector<bool> seen(n, false);
  for (std::size_t v = 0; v < n; ++v) {
    t.max_degree = std::max(t.max_degree, adjacent[v].size());
    if (adjacent[v].empty()) ++t.unconnected;
    if (adjacent[v].empty() || seen[v]) continue;
    std::size_t vertices = 0, degree_sum = 0, ones = 0, high = 0;
    std::queue<std::size_t> queue;
    queue.push(v), seen[v] = true;
    while (!queue.empty()) {
      const std::size_t u = queue.front();
      queue.pop();
      ++vertices, degree_sum += adjacent[u].size(), ones += adjacent[u].size() == 1, high += adjacent[u].size() > 2;
      for (const std::size_t w : adjacent[u])
        if (!seen[w]) seen[w] = true, queue.push(w);
    }
    ++t.components;
    if (high == 0 && ones == 0 && degree_sum == 2 * vertices) ++t.closed_components;
    if (high == 0 && ones == 2) ++t.open_components;
  }
  t.manifold = t.max_degree <= 2;
  return t;
}

TEST(CurveTopology, CountsPathsCyclesBranchesAndLonePoints) {
  // 0-1-2 a path, 3-4-5-3 a triangle, 6 alone, 7-8 7-9 7-10 a star.
  const std::vector<Edge> edges{{0, 1}, {1, 2}, {3, 4}, {3, 5}, {4, 5}, {7, 8}, {7, 9}, {7, 10}};
  const Curve_topology t = curve_topology(11, edges);
  EXPECT_FALSE(t.manifold);
  EXPECT_EQ(t.components, 3u);
  EXPECT_EQ(t.open_components, 1u);
  EXPECT_EQ(t.closed_components, 1u);
  EXPECT_EQ(t.unconnected, 1u);
  EXPECT_EQ(t.max_degree, 3u);
  EXPECT_TRUE(curve_topology(3, std::vector<Edge>{}).manifold);
  EXPECT_EQ(curve_topology(3, std::vector<Edge>{}).unconnected, 3u);
}

RC_GTEST_PROP(CurveTopology, MatchesABreadthFirstSearch, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 30);
  std::vector<Edge> edges;
  if (n >= 2)
    for (int k = *rc::gen::inRange(0, 40); k > 0; --k) {
      const auto i = *rc::gen::inRange<std::size_t>(0, n), j = *rc::gen::inRange<std::size_t>(0, n);
      if (i != j) edges.emplace_back(i, j);
    }
  edges = canonical_edges(std::move(edges));
  const Curve_topology tested = curve_topology(n, edges), oracle = by_search(n, edges);
  RC_ASSERT(tested.manifold == oracle.manifold);
  RC_ASSERT(tested.components == oracle.components);
  RC_ASSERT(tested.open_components == oracle.open_components);
  RC_ASSERT(tested.closed_components == oracle.closed_components);
  RC_ASSERT(tested.unconnected == oracle.unconnected);
  RC_ASSERT(tested.max_degree == oracle.max_degree);
}

}  // namespace
}  // namespace curvebench::geometry
