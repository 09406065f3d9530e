// NN-Crust (algorithms/nn_crust.h) against a brute force of its definition over ALL pairs
// of points, in rationals (CGAL::Gmpq): each point's nearest neighbour q (ties to the
// smaller index), and its nearest point s with (s - p).(q - p) < 0. The implementation
// finds both through the Delaunay triangulation; the brute force knows nothing of it. Plus
// hand cases: the point behind p that is NOT a Delaunay neighbour of p, regular polygons,
// tiny and collinear input. The epsilon < 1/3 theorem is the registry's property
// (proven_conditions_test.cpp).
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "algorithms/nn_crust.h"
#include "algorithms/registry.h"
#include "geometry/analytic_curves.h"
#include "geometry/local_feature_size.h"
#include "geometry/sampling.h"
#include "graphs/delaunay_triangulation.h"
#include "tests/support/point_generators.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;
using Q = CGAL::Gmpq;

// ------------------------------------------------------------ brute force in rationals

struct Q_point {
  Q x, y;
};
Q squared_distance(const Q_point& a, const Q_point& b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

// The first point by (squared distance to p, index) among those `eligible`; no_neighbor if none.
template <class Eligible>
std::uint32_t brute_nearest(const std::vector<Q_point>& points, std::size_t p, Eligible eligible) {
  std::uint32_t best = no_neighbor;
  Q best_distance;
  for (std::size_t s = 0; s < points.size(); ++s) {
    if (s == p || !eligible(s)) continue;
    const Q d = squared_distance(points[p], points[s]);
    if (best == no_neighbor || d < best_distance) {  // ascending s: equal keeps the smaller index
      best = std::uint32_t(s);
      best_distance = d;
    }
  }
  return best;
}

std::vector<Nearest_and_half_neighbor> brute_neighbors(std::span<const Point> input) {
  std::vector<Q_point> points;
  for (const Point& p : input) points.push_back({Q(p.x()), Q(p.y())});
  std::vector<Nearest_and_half_neighbor> result(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const std::uint32_t q = brute_nearest(points, p, [](std::size_t) { return true; });
    result[p].nearest = q;
    if (q == no_neighbor) continue;
    result[p].half = brute_nearest(points, p, [&](std::size_t s) {
      const Q_point &a = points[p], &b = points[q], &c = points[s];
      return (c.x - a.x) * (b.x - a.x) + (c.y - a.y) * (b.y - a.y) < 0;
    });
  }
  return result;
}

Edges brute_nn_crust(std::span<const Point> points) {
  Edges edges;
  const auto neighbors = brute_neighbors(points);
  for (std::size_t p = 0; p < points.size(); ++p)
    for (const std::uint32_t s : {neighbors[p].nearest, neighbors[p].half})
      if (s != no_neighbor) edges.emplace_back(std::min<std::size_t>(p, s), std::max<std::size_t>(p, s));
  std::ranges::sort(edges);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

void expect_matches_brute_force(std::span<const Point> points) {
  const auto expected = brute_neighbors(points);
  const auto found = nearest_and_half_neighbors(points, Half_plane::behind_p);
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    EXPECT_EQ(found[p].nearest, expected[p].nearest) << "point " << p;
    EXPECT_EQ(found[p].half, expected[p].half) << "point " << p;
  }
  EXPECT_EQ(nn_crust_reconstruction(points), brute_nn_crust(points));
}

std::vector<Point> regular_polygon(int k, double radius, double phase, Point centre = {0, 0}) {
  std::vector<Point> points;
  for (int i = 0; i < k; ++i) {
    const double t = phase + 2 * std::numbers::pi * i / k;
    points.emplace_back(centre.x() + radius * std::cos(t), centre.y() + radius * std::sin(t));
  }
  return points;
}

Edges cycle(std::size_t k) {
  Edges edges;
  for (std::size_t i = 0; i + 1 < k; ++i) edges.emplace_back(i, i + 1);
  edges.emplace_back(0, k - 1);
  std::ranges::sort(edges);
  return edges;
}

// ------------------------------------------------------------ properties

RC_GTEST_PROP(NnCrust, MatchesTheDefinitionOverAllPairsOnDegenerateInput, ()) {
  const std::vector<Point> points = *testing::point_sets(40);
  const auto expected = brute_neighbors(points);
  const auto found = nearest_and_half_neighbors(points, Half_plane::behind_p);
  for (std::size_t p = 0; p < points.size(); ++p) {
    RC_ASSERT(found[p].nearest == expected[p].nearest);
    RC_ASSERT(found[p].half == expected[p].half);
  }
  RC_ASSERT(nn_crust_reconstruction(points) == brute_nn_crust(points));
}

// Clusters at several scales make half neighbours that hide behind other points' Delaunay
// edges, which the exact search must find.
RC_GTEST_PROP(NnCrust, MatchesTheDefinitionOverAllPairsOnClusteredInput, ()) {
  const auto seed = *rc::gen::inRange<std::uint32_t>(0, 1u << 30);
  const int n = *rc::gen::inRange(3, 150);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<Point> points;
  for (int c = 0; c < 1 + n / 20; ++c) {
    const double scale = std::ldexp(1.0, int(random() % 12) - 6);
    const Point centre(unit(random), unit(random));
    for (int i = 0; i < 20 && int(points.size()) < n; ++i)
      points.emplace_back(centre.x() + scale * unit(random), centre.y() + scale * unit(random) * 0.1);
  }
  points = testing::distinct(points);
  const auto expected = brute_neighbors(points);
  const auto found = nearest_and_half_neighbors(points, Half_plane::behind_p);
  for (std::size_t p = 0; p < points.size(); ++p) {
    RC_ASSERT(found[p].nearest == expected[p].nearest);
    RC_ASSERT(found[p].half == expected[p].half);
  }
}

// ------------------------------------------------------------ hand cases

// p's nearest neighbour is q = (0.9, 0); the nearest point behind p is r = (-0.1, 10), but
// x and y see pr under angles that sum to more than 180 degrees: no empty circle passes
// through p and r, so r is not a Delaunay neighbour of p. The paper's rule restricted to
// Delaunay edges would pick y; the definition picks r.
TEST(NnCrust, FindsAHalfNeighbourThatIsNotADelaunayNeighbour) {
  const std::vector<Point> points{{0, 0}, {0.9, 0}, {-0.1, 10}, {0.05, 1}, {-8, 8}};
  const graphs::Delaunay_triangulation dt(points);
  const auto around_p = dt.neighbors(0);
  ASSERT_EQ(std::ranges::count(around_p, graphs::Vertex(2)), 0) << "the case needs pr to be non-Delaunay";
  const auto found = nearest_and_half_neighbors(points, Half_plane::behind_p);
  EXPECT_EQ(found[0].nearest, 1u);
  EXPECT_EQ(found[0].half, 2u);
  expect_matches_brute_force(points);
}

TEST(NnCrust, ReconstructsRegularPolygonsAsCycles) {
  for (int k = 5; k <= 40; ++k)
    for (const double phase : {0.0, 0.3, 1.0}) {
      const std::vector<Point> points = regular_polygon(k, 1 + k, phase, {k * 0.1, -3.0});
      EXPECT_EQ(nn_crust_reconstruction(points), cycle(k)) << k << " " << phase;
      expect_matches_brute_force(points);
    }
}

// At 90 degrees nothing lies strictly behind a corner of a square: each corner keeps its
// nearest neighbour only (ties to the smaller index).
TEST(NnCrust, SquareKeepsNearestNeighbourEdgesOnly) {
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(nn_crust_reconstruction(square), (Edges{{0, 1}, {0, 3}, {1, 2}}));
  expect_matches_brute_force(square);
}

TEST(NnCrust, TinyAndCollinearInput) {
  EXPECT_TRUE(nn_crust_reconstruction(std::vector<Point>{}).empty());
  EXPECT_TRUE(nn_crust_reconstruction(std::vector<Point>{{1, 2}}).empty());
  EXPECT_EQ(nn_crust_reconstruction(std::vector<Point>{{0, 0}, {3, 4}}), (Edges{{0, 1}}));
  // Collinear, given out of order: the chain along the line.
  const std::vector<Point> line{{3, 3}, {0, 0}, {1, 1}, {-2, -2}, {2, 2}};
  EXPECT_EQ(nn_crust_reconstruction(line), (Edges{{0, 4}, {1, 2}, {1, 3}, {2, 4}}));
  expect_matches_brute_force(line);
  const std::vector<Point> triangle{{0, 0}, {1, 0}, {0, 1}};
  expect_matches_brute_force(triangle);
  EXPECT_THROW(nn_crust_reconstruction(std::vector<Point>{{0, 0}, {1, 1}, {0, 0}}), std::invalid_argument);
  EXPECT_THROW(nn_crust_reconstruction(std::vector<Point>{{0, 0}, {INFINITY, 1}}), std::invalid_argument);
}

// Samples of smooth closed curves, large enough that the fast path decides most points:
// the brute force over all pairs agrees point by point; on a densely sampled ellipse (lfs
// >= 1/2, spacing 0.02) the result is the curve.
TEST(NnCrust, MatchesTheDefinitionOnCurveSamples) {
  const geometry::Curve curve = geometry::random_fourier_curve(7);
  expect_matches_brute_force(geometry::uniform_sampling(geometry::Local_feature_size(curve), 600).points);
  const geometry::Sample ellipse = geometry::uniform_sampling(geometry::Local_feature_size(geometry::ellipse(2, 1)), 500);
  expect_matches_brute_force(ellipse.points);
  Edges truth = ellipse.edges;
  for (auto& [i, j] : truth)
    if (i > j) std::swap(i, j);
  std::ranges::sort(truth);
  EXPECT_EQ(nn_crust_reconstruction(ellipse.points), truth);
}

TEST(NnCrust, IsRegisteredWithItsCondition) {
  const Algorithm* algorithm = find_algorithm("nn-crust");
  ASSERT_NE(algorithm, nullptr);
  EXPECT_EQ(algorithm->title, "NN-Crust");
  EXPECT_EQ(algorithm->condition.epsilon_below, 1.0 / 3);
  EXPECT_TRUE(algorithm->capabilities.guarantee);
  EXPECT_EQ(algorithm->capabilities.open, Support::yes);
  // Duplicates are merged by the registry: the same edges as the distinct points.
  const std::vector<Point> points = regular_polygon(7, 2, 0.1);
  std::vector<Point> doubled = points;
  doubled.insert(doubled.end(), points.begin(), points.end());
  EXPECT_EQ(reconstruct(*algorithm, doubled).edges, cycle(7));
}

}  // namespace
}  // namespace curvebench::algorithms
