// graphs/exact_length_order.h against a brute force: edges sorted by exact squared length in
// rationals, ties by (source, target). On degenerate point sets at every scale, on an evenly
// sampled curve (whose edges agree in length to 15 digits, the case the finer keys are
// for), and on lengths that differ by 2^-100 and 2^-88 of themselves (below and above what
// the finer keys separate) or not at all. edge_ids_by_exact_length (the same sort giving
// positions) and sort_shortest_by_exact_length (a stretch of it) on degenerate input.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include <CGAL/Gmpq.h>

#include "geometry/curves/analytic_curves.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/exact_length_order.h"
#include "tests/support/point_generators.h"

namespace curvebench::graphs {
namespace {

CGAL::Gmpq squared_length(const Point& a, const Point& b) {
  const CGAL::Gmpq dx = CGAL::Gmpq(a.x()) - CGAL::Gmpq(b.x()), dy = CGAL::Gmpq(a.y()) - CGAL::Gmpq(b.y());
  return dx * dx + dy * dy;
}

std::vector<std::pair<Vertex, Vertex>> brute_force_order(std::span<const Point> points, std::vector<Edge_with_length> edges) {
  std::vector<std::tuple<CGAL::Gmpq, Vertex, Vertex>> keyed;
  for (const Edge_with_length& e : edges)
    keyed.emplace_back(squared_length(points[e.source], points[e.target]), e.source, e.target);
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::pair<Vertex, Vertex>> order;
  for (const auto& [length, source, target] : keyed) order.emplace_back(source, target);
  return order;
}

std::vector<std::pair<Vertex, Vertex>> sorted(std::span<const Point> points, std::vector<Edge_with_length> edges) {
  sort_by_exact_length(points, edges);
  std::vector<std::pair<Vertex, Vertex>> order;
  for (const Edge_with_length& e : edges) order.emplace_back(e.source, e.target);
  return order;
}

// The order of edge_ids_by_exact_length, as end points.
std::vector<std::pair<Vertex, Vertex>> sorted_ids(std::span<const Point> points, std::span<const Delaunay_edge> edges) {
  std::vector<std::pair<Vertex, Vertex>> order;
  for (const std::uint32_t id : edge_ids_by_exact_length(points, edges))
    order.emplace_back(edges[id].source, edges[id].target);
  return order;
}

RC_GTEST_PROP(ExactLengthOrder, MatchesTheBruteForceOnDegenerateInput, ()) {
  const std::vector<Point> points = *testing::point_sets(40);
  const Delaunay_triangulation dt(points);
  const auto edges = with_lengths(points, dt.edges());
  const auto expected = brute_force_order(points, edges);
  RC_ASSERT(sorted(points, edges) == expected);
  RC_ASSERT(sorted_ids(points, dt.edges()) == expected);
}

// A stretch sorted from a random position: what comes before stays, the stretch is the
// brute-force order's head of what came after (at least `count` of it), and the rest is
// the rest of it, in some order.
RC_GTEST_PROP(ExactLengthOrder, SortsTheShortestStretchAsTheBruteForce, ()) {
  const std::vector<Point> points = *testing::point_sets(40);
  const Delaunay_triangulation dt(points);
  std::vector<Edge_with_length> edges = with_lengths(points, dt.edges());
  const auto begin = *rc::gen::inRange<std::size_t>(0, edges.size() + 1);
  const auto count = *rc::gen::inRange<std::size_t>(0, edges.size() + 2);
  const std::vector<Edge_with_length> before(edges.begin(), edges.begin() + std::ptrdiff_t(begin));
  const auto expected = brute_force_order(points, {edges.begin() + std::ptrdiff_t(begin), edges.end()});
  const std::size_t end = sort_shortest_by_exact_length(points, edges, begin, count);
  RC_ASSERT(end >= begin + std::min(count, edges.size() - begin));
  RC_ASSERT(end <= edges.size());
  std::vector<std::pair<Vertex, Vertex>> prefix, stretch, rest;
  for (std::size_t i = 0; i < edges.size(); ++i)
    (i < begin ? prefix : i < end ? stretch : rest).emplace_back(edges[i].source, edges[i].target);
  std::vector<std::pair<Vertex, Vertex>> expected_prefix;
  for (const Edge_with_length& e : before) expected_prefix.emplace_back(e.source, e.target);
  RC_ASSERT(prefix == expected_prefix);
  RC_ASSERT(stretch == std::vector(expected.begin(), expected.begin() + std::ptrdiff_t(stretch.size())));
  std::sort(rest.begin(), rest.end());
  std::vector expected_rest(expected.begin() + std::ptrdiff_t(stretch.size()), expected.end());
  std::sort(expected_rest.begin(), expected_rest.end());
  RC_ASSERT(rest == expected_rest);
}

// Thousands of edges whose squares underflow, overflow or tie exactly: small integer
// offsets at five scales, in random order (the keys 0 and +inf fall into runs that only
// the exact comparison orders).
RC_GTEST_PROP(ExactLengthOrder, MatchesTheBruteForceOnManyEdgesOfEveryScale, ()) {
  const auto count = *rc::gen::inRange<std::size_t>(4096, 6000);
  const auto offsets = *rc::gen::container<std::vector<std::tuple<int, int, int>>>(
      count, rc::gen::tuple(rc::gen::element(-600, -30, 0, 30, 600), rc::gen::inRange(-8, 9), rc::gen::inRange(1, 9)));
  std::vector<Point> points;
  std::vector<Delaunay_edge> pairs;
  for (const auto& [exponent, dx, dy] : offsets) {
    const Vertex a = Vertex(points.size());
    points.emplace_back(0.0, 0.0);
    points.emplace_back(std::ldexp(dx, exponent), std::ldexp(dy, exponent));
    pairs.push_back({a, a + 1, no_vertex, no_vertex});
  }
  const auto edges = with_lengths(points, pairs);
  RC_ASSERT(sorted(points, edges) == brute_force_order(points, edges));
}

TEST(ExactLengthOrder, MatchesTheBruteForceOnAnEvenlySampledCurve) {
  const geometry::Curve curve = geometry::random_fourier_curve(3);
  const std::vector<Point> points = geometry::uniform_sampling(geometry::Local_feature_size(curve), 3000).points;
  const Delaunay_triangulation dt(points);
  const auto edges = with_lengths(points, dt.edges());
  const auto expected = brute_force_order(points, edges);
  EXPECT_EQ(sorted(points, edges), expected);
  EXPECT_EQ(sorted_ids(points, dt.edges()), expected);
}

// Squared lengths 2^100 + {0, 1, 2^12, 2^12, 2^13} and a copy of each shifted by 2^-20:
// differences of 2^-100 relative, which only the exact comparison sees, and of 2^-88,
// which the finer keys separate; equal lengths keep (source, target) order.
TEST(ExactLengthOrder, SeparatesNearTiesExactly) {
  std::vector<Point> points;
  std::vector<Edge_with_length> edges;
  const double big = std::ldexp(1.0, 50);
  for (const double shift : {0.0, std::ldexp(1.0, -20)})
    for (const double dy : {0.0, 1.0, 64.0, -64.0, 64 * std::sqrt(2.0)}) {
      const Vertex a = Vertex(points.size());
      points.emplace_back(shift, 0.0);
      points.emplace_back(shift + big, dy);
      edges.push_back({geometry::squared_distance_approximation(points[a], points[a + 1]), a, a + 1});
    }
  std::reverse(edges.begin(), edges.end());
  EXPECT_EQ(sorted(points, edges), brute_force_order(points, edges));
}

}  // namespace
}  // namespace curvebench::graphs
