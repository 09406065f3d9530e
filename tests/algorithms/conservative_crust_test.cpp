// Conservative Crust (algorithms/conservative_crust.h) against a brute force of its
// definition in rationals (CGAL::Gmpq), on any input including degenerate ones: for
// every pair p, q, the Gabriel test against every point (closed diametral disk), then
// the dual Voronoi edge as the range of centres m + t n of circles through p and q with
// no point strictly inside, and its reach: the largest such circle has radius^2
// |pq|^2 (1/4 + t^2), at an end of the range (unbounded for a hull edge). None of the
// apex-angle rewriting of the implementation is used. Plus hand cases: an open arc gives
// a path, outliers stay isolated, regular polygons give their cycle, rho = 1 is the
// Gabriel graph, and rho orders the outputs by inclusion.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>

#include "algorithms/conservative_crust.h"
#include "algorithms/registry.h"
#include "graphs/gabriel_graph.h"
#include "tests/support/edge_sets.h"
#include "tests/support/point_generators.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;
using Q = CGAL::Gmpq;
using testing::canonical;
using testing::cycle_edges;
using testing::path_edges;
using testing::regular_polygon;

// ------------------------------------------------------------------ brute force

Edges brute_force_conservative_crust(const std::vector<Point>& points, double rho) {
  struct P {
    Q x, y;
  };
  std::vector<P> s;
  for (const Point& p : points) s.push_back({Q(p.x()), Q(p.y())});
  const auto squared_distance = [](const P& a, const P& b) {
    return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
  };
  Edges edges;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const P& p = s[i];
      const P& q = s[j];
      const P m{(p.x + q.x) / 2, (p.y + q.y) / 2};
      const Q h2 = squared_distance(p, m);
      bool gabriel = true;
      for (std::size_t k = 0; k < s.size() && gabriel; ++k)
        gabriel = k == i || k == j || squared_distance(s[k], m) > h2;
      if (!gabriel) continue;
      // Centres m + t n with no point strictly inside: low <= t <= high.
      const Q nx = p.y - q.y, ny = q.x - p.x;
      std::optional<Q> low, high;
      for (std::size_t k = 0; k < s.size(); ++k) {
        if (k == i || k == j) continue;
        const Q a = squared_distance(s[k], m) - h2;
        const Q b = Q(2) * (nx * (s[k].x - m.x) + ny * (s[k].y - m.y));
        if (CGAL::sign(b) == CGAL::ZERO) continue;  // on the line, outside segment pq (Gabriel)
        const Q t = a / b;
        if (CGAL::sign(b) == CGAL::POSITIVE) {
          if (!high || t < *high) high = t;
        } else if (!low || t > *low) {
          low = t;
        }
      }
      // Reach |pq| / (2 rho): rho^2 (1 + 4 t^2) >= 1 at an end, or an unbounded end.
      const Q r2 = Q(rho) * Q(rho);
      const auto reaches = [&](const Q& t) { return r2 * (Q(1) + Q(4) * t * t) >= Q(1); };
      if (!low || !high || reaches(*low) || reaches(*high)) edges.emplace_back(i, j);
    }
  return edges;
}

// ------------------------------------------------------------------- hand cases

TEST(ConservativeCrust, TinyAndCollinearInputs) {
  EXPECT_TRUE(conservative_crust_reconstruction({}).empty());
  const std::vector<Point> one{{1, 2}};
  EXPECT_TRUE(conservative_crust_reconstruction(one).empty());
  const std::vector<Point> two{{1, 2}, {3, 4}};
  EXPECT_EQ(conservative_crust_reconstruction(two), (Edges{{0, 1}}));
  const std::vector<Point> collinear{{3, 3}, {0, 0}, {5, 5}, {1, 1}, {-2, -2}};
  EXPECT_EQ(conservative_crust_reconstruction(collinear), (Edges{{0, 2}, {0, 3}, {1, 3}, {1, 4}}));
  // A triangle: all hull edges; the obtuse one's long side is not Gabriel.
  const std::vector<Point> obtuse{{0, 0}, {4, 0}, {2, 1}};
  EXPECT_EQ(conservative_crust_reconstruction(obtuse), (Edges{{0, 2}, {1, 2}}));
  EXPECT_THROW(conservative_crust_reconstruction(two, 1.5), std::invalid_argument);
  EXPECT_THROW(conservative_crust_reconstruction(two, -0.1), std::invalid_argument);
}

TEST(ConservativeCrust, RegularPolygonsGiveTheirCycle) {
  for (std::size_t k = 3; k <= 40; ++k) {
    EXPECT_EQ(conservative_crust_reconstruction(regular_polygon(k, 1)), cycle_edges(k)) << k;
    EXPECT_EQ(conservative_crust_reconstruction(regular_polygon(k, 1e-250)), cycle_edges(k)) << k;
  }
}

TEST(ConservativeCrust, AnOpenArcGivesAPath) {
  // A parabola arc and a spiral arc, in order along the curve.
  std::vector<Point> parabola, spiral;
  for (int i = -30; i <= 30; ++i) parabola.emplace_back(i / 30.0, (i / 30.0) * (i / 30.0));
  for (int i = 0; i <= 120; ++i) {
    const double angle = 0.05 * i, radius = 1 + 0.1 * angle;
    spiral.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  EXPECT_EQ(conservative_crust_reconstruction(parabola), path_edges(parabola.size()));
  EXPECT_EQ(conservative_crust_reconstruction(spiral), path_edges(spiral.size()));
}

TEST(ConservativeCrust, OutliersStayIsolated) {
  std::vector<Point> points = regular_polygon(64, 1);
  const std::size_t n = points.size();
  points.emplace_back(3, 0.1);     // far outside
  points.emplace_back(0.05, 0.02);  // near the centre
  points.emplace_back(-2, 2.5);    // far outside
  EXPECT_EQ(conservative_crust_reconstruction(points), cycle_edges(n));
}

TEST(ConservativeCrust, RhoOneIsTheGabrielGraph) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(0, 1);
  std::vector<Point> points;
  for (int i = 0; i < 120; ++i) points.emplace_back(coordinate(random), coordinate(random));
  EXPECT_EQ(conservative_crust_reconstruction(points, 1), graphs::edge_list(graphs::gabriel_graph(points)));
  EXPECT_EQ(conservative_crust_reconstruction(points, 0.3), brute_force_conservative_crust(points, 0.3));
}

TEST(ConservativeCrust, IsRegisteredWithItsParameter) {
  const Algorithm* crust = find_algorithm("conservative-crust");
  ASSERT_NE(crust, nullptr);
  EXPECT_EQ(crust->title, "Conservative Crust");
  ASSERT_TRUE(crust->condition.epsilon_below);
  EXPECT_EQ(*crust->condition.epsilon_below, 0.0625);
  ASSERT_EQ(crust->parameters.size(), 1u);
  EXPECT_EQ(crust->parameters[0].name, "rho");
  EXPECT_EQ(crust->parameters[0].default_value, default_conservative_crust_rho);
  const std::vector<Point> points = regular_polygon(12, 1);
  EXPECT_EQ(reconstruct(*crust, points).edges, cycle_edges(12));
  EXPECT_EQ(reconstruct(*crust, points, {{"rho", 1}}).edges, cycle_edges(12));
  EXPECT_THROW(reconstruct(*crust, points, {{"rho", 2}}), std::invalid_argument);
}

// ------------------------------------------------------------------- properties

RC_GTEST_PROP(ConservativeCrust, EqualsTheBruteForceOnAnyInput, ()) {
  const std::vector<Point> points = *testing::point_sets(14);
  const double rho = *rc::gen::element(0.0, 0.1, 0.25, 0.5, 0.9, 1.0);
  const Edges crust = conservative_crust_reconstruction(points, rho);
  RC_ASSERT(crust == brute_force_conservative_crust(points, rho));
}

RC_GTEST_PROP(ConservativeCrust, IsMonotoneInRhoAndOrderIndependent, ()) {
  const std::vector<Point> points = *testing::point_sets(30);
  const Edges small = conservative_crust_reconstruction(points, 0.2);
  const Edges large = conservative_crust_reconstruction(points, 0.6);
  RC_ASSERT(std::ranges::includes(large, small));
  RC_ASSERT(conservative_crust_reconstruction(points, 1) == graphs::edge_list(graphs::gabriel_graph(points)));

  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(*rc::gen::arbitrary<std::uint32_t>()));
  std::vector<Point> shuffled;
  for (const std::size_t i : order) shuffled.push_back(points[i]);
  Edges mapped;
  for (const auto& [i, j] : conservative_crust_reconstruction(shuffled, 0.2)) mapped.emplace_back(order[i], order[j]);
  RC_ASSERT(canonical(mapped) == small);
}

}  // namespace
}  // namespace curvebench::algorithms
