// HNN-Crust (algorithms/hnn_crust.h) against a brute force of its definition over ALL
// pairs of points, in rationals (CGAL::Gmpq): each point's nearest neighbour q (ties to
// the smaller index) and half neighbour, the nearest point s with |ps| < |qs|; an edge is
// kept when both ends chose it. Plus hand cases: a half neighbour that is NOT a Delaunay
// neighbour, regular polygons, open curves (a path whose two end points keep one edge),
// tiny and collinear input. The epsilon < 0.47 theorem is the registry's property
// (proven_conditions_test.cpp).
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "algorithms/hnn_crust.h"
#include "algorithms/nn_crust.h"
#include "algorithms/registry.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "graphs/delaunay_triangulation.h"
#include "tests/support/brute_force_neighbors.h"
#include "tests/support/edge_sets.h"
#include "tests/support/point_generators.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;
using testing::cycle_edges;
using testing::path_edges;
using testing::regular_polygon;
using testing::degrees;

std::vector<Nearest_and_half_neighbor> brute_neighbors(std::span<const Point> points) {
  return testing::brute_force_nearest_and_half_neighbors(points, Half_plane::beyond_bisector);
}

Edges brute_hnn_crust(std::span<const Point> points) {
  const auto neighbors = brute_neighbors(points);
  const auto chose = [&](std::size_t a, std::size_t b) { return neighbors[a].nearest == b || neighbors[a].half == b; };
  Edges edges;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (chose(i, j) && chose(j, i)) edges.emplace_back(i, j);
  return edges;
}

void expect_matches_brute_force(std::span<const Point> points) {
  EXPECT_EQ(testing::neighbor_mismatch(points, Half_plane::beyond_bisector), std::nullopt);
  EXPECT_EQ(hnn_crust_reconstruction(points), brute_hnn_crust(points));
}

// ------------------------------------------------------------ properties

RC_GTEST_PROP(HnnCrust, MatchesTheDefinitionOverAllPairsOnDegenerateInput, ()) {
  const std::vector<Point> points = *testing::point_sets(40);
  RC_ASSERT(!testing::neighbor_mismatch(points, Half_plane::beyond_bisector));
  const Edges edges = hnn_crust_reconstruction(points);
  RC_ASSERT(edges == brute_hnn_crust(points));
  for (const std::size_t degree : degrees(edges, points.size())) RC_ASSERT(degree <= 2u);
}

RC_GTEST_PROP(HnnCrust, MatchesTheDefinitionOverAllPairsOnClusteredInput, ()) {
  const std::vector<Point> points = *testing::clustered_points();
  RC_ASSERT(!testing::neighbor_mismatch(points, Half_plane::beyond_bisector));
  RC_ASSERT(hnn_crust_reconstruction(points) == brute_hnn_crust(points));
}

// ------------------------------------------------------------ hand cases

// p's nearest neighbour is q = (1, 0); the nearest point closer to p than to q is
// r = (0.4, 10), but x and y see pr under angles summing to more than 180 degrees, so r is
// not a Delaunay neighbour of p.
TEST(HnnCrust, FindsAHalfNeighbourThatIsNotADelaunayNeighbour) {
  const std::vector<Point> points{{0, 0}, {1, 0}, {0.4, 10}, {0.55, 1}, {-8, 8}};
  const graphs::Delaunay_triangulation dt(points);
  ASSERT_EQ(std::ranges::count(dt.neighbors(0), graphs::Vertex(2)), 0) << "the case needs pr to be non-Delaunay";
  const auto found = nearest_and_half_neighbors(points, Half_plane::beyond_bisector);
  EXPECT_EQ(found[0].nearest, 1u);
  EXPECT_EQ(found[0].half, 2u);
  expect_matches_brute_force(points);
}

TEST(HnnCrust, ReconstructsRegularPolygonsAsCycles) {
  for (int k = 4; k <= 40; ++k)
    for (const double phase : {0.0, 0.3, 1.0}) {
      const std::vector<Point> points = regular_polygon(k, 1 + k, phase, {-2.0, k * 0.1});
      EXPECT_EQ(hnn_crust_reconstruction(points), cycle_edges(k)) << k << " " << phase;
      expect_matches_brute_force(points);
    }
  // The exact square: every nearest neighbour is a tie, broken by index.
  EXPECT_EQ(hnn_crust_reconstruction(std::vector<Point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}), cycle_edges(4));
}

// An open arc: an end point's half-plane holds no point, so the end point keeps one edge and
// the curve is the path. (Beyond 180 degrees the two ends lie in each other's half-planes
// and choose each other: HNN-Crust closes such an arc, as the definition says.)
TEST(HnnCrust, ReconstructsOpenCurvesAsPathsWithTwoEndPoints) {
  for (const double degrees_spanned : {60.0, 120.0, 180.0}) {
    for (const int k : {5, 12, 40}) {
      std::vector<Point> arc;
      for (int i = 0; i < k; ++i) {
        const double t = degrees_spanned * std::numbers::pi / 180 * i / (k - 1);
        arc.emplace_back(3 * std::cos(t) + 1, 3 * std::sin(t) - 2);
      }
      const Edges edges = hnn_crust_reconstruction(arc);
      EXPECT_EQ(edges, path_edges(k)) << degrees_spanned << " degrees, " << k << " points";
      const auto degree = degrees(edges, arc.size());
      EXPECT_EQ(std::ranges::count(degree, 1u), 2);
      expect_matches_brute_force(arc);
    }
  }
  // A wave, sampled unevenly (denser where it bends), given in shuffled order.
  std::vector<Point> wave;
  for (int i = 0; i < 60; ++i) {
    const double x = 6.0 * i / 59 + 0.02 * std::sin(3.0 * i);
    wave.emplace_back(x, 0.5 * std::sin(x));
  }
  std::vector<std::size_t> order(wave.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = (i * 37) % order.size();
  std::vector<Point> shuffled;
  for (const std::size_t i : order) shuffled.push_back(wave[i]);
  Edges expected;
  std::vector<std::size_t> position(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) position[order[k]] = k;
  for (std::size_t i = 0; i + 1 < wave.size(); ++i)
    expected.emplace_back(std::min(position[i], position[i + 1]), std::max(position[i], position[i + 1]));
  std::ranges::sort(expected);
  EXPECT_EQ(hnn_crust_reconstruction(shuffled), expected);
  expect_matches_brute_force(shuffled);
}

TEST(HnnCrust, TinyAndCollinearInput) {
  EXPECT_TRUE(hnn_crust_reconstruction(std::vector<Point>{}).empty());
  EXPECT_TRUE(hnn_crust_reconstruction(std::vector<Point>{{1, 2}}).empty());
  EXPECT_EQ(hnn_crust_reconstruction(std::vector<Point>{{0, 0}, {3, 4}}), (Edges{{0, 1}}));
  const std::vector<Point> line{{3, 3}, {0, 0}, {1, 1}, {-2, -2}, {2, 2}};
  EXPECT_EQ(hnn_crust_reconstruction(line), (Edges{{0, 4}, {1, 2}, {1, 3}, {2, 4}}));
  expect_matches_brute_force(line);
  expect_matches_brute_force(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}});
  EXPECT_THROW(hnn_crust_reconstruction(std::vector<Point>{{0, 0}, {1, 1}, {0, 0}}), std::invalid_argument);
}

TEST(HnnCrust, MatchesTheDefinitionOnCurveSamples) {
  for (const std::uint64_t seed : {3u, 11u}) {
    const geometry::Curve curve = geometry::random_fourier_curve(seed);
    expect_matches_brute_force(geometry::uniform_sampling(geometry::Local_feature_size(curve), 500).points);
  }
  const geometry::Sample ellipse = geometry::uniform_sampling(geometry::Local_feature_size(geometry::ellipse(2, 1)), 300);
  Edges truth = ellipse.edges;
  for (auto& [i, j] : truth)
    if (i > j) std::swap(i, j);
  std::ranges::sort(truth);
  EXPECT_EQ(hnn_crust_reconstruction(ellipse.points), truth);
  expect_matches_brute_force(ellipse.points);
}

TEST(HnnCrust, IsRegisteredWithItsCondition) {
  const Algorithm* algorithm = find_algorithm("hnn-crust");
  ASSERT_NE(algorithm, nullptr);
  EXPECT_EQ(algorithm->title, "HNN-Crust");
  EXPECT_EQ(algorithm->condition.epsilon_below, 0.47);
  EXPECT_EQ(algorithm->condition.rho_below, 0.9);
  EXPECT_TRUE(algorithm->capabilities.guarantee);
  const std::vector<Point> points = regular_polygon(9, 2, 0.1);
  std::vector<Point> doubled = points;
  doubled.insert(doubled.end(), points.begin(), points.end());
  EXPECT_EQ(reconstruct(*algorithm, doubled).edges, cycle_edges(9));
}

}  // namespace
}  // namespace curvebench::algorithms
