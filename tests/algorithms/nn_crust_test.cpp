// NN-Crust (algorithms/nn_crust.h) against a brute force of its definition over ALL pairs
// of points, in rationals (CGAL::Gmpq): each point's nearest neighbour q (ties to the
// smaller index), and its nearest point s with (s - p).(q - p) < 0. The implementation
// finds both through the Delaunay triangulation; the brute force knows nothing of it. Plus
// hand cases: the point behind p that is NOT a Delaunay neighbour of p, regular polygons,
// tiny and collinear input. The epsilon < 1/3 theorem is the registry's property
// (proven_conditions_test.cpp).
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

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
using testing::regular_polygon;

std::vector<Nearest_and_half_neighbor> brute_neighbors(std::span<const Point> points) {
  return testing::brute_force_nearest_and_half_neighbors(points, Half_plane::behind_p);
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
  EXPECT_EQ(testing::neighbor_mismatch(points, Half_plane::behind_p), std::nullopt);
  EXPECT_EQ(nn_crust_reconstruction(points), brute_nn_crust(points));
}

// ------------------------------------------------------------ properties

RC_GTEST_PROP(NnCrust, MatchesTheDefinitionOverAllPairsOnDegenerateInput, ()) {
  const std::vector<Point> points = *testing::point_sets(40);
  RC_ASSERT(!testing::neighbor_mismatch(points, Half_plane::behind_p));
  RC_ASSERT(nn_crust_reconstruction(points) == brute_nn_crust(points));
}

// Clusters at several scales make half neighbours that hide behind other points' Delaunay
// edges, which the exact search must find.
RC_GTEST_PROP(NnCrust, MatchesTheDefinitionOverAllPairsOnClusteredInput, ()) {
  const std::vector<Point> points = *testing::clustered_points();
  RC_ASSERT(!testing::neighbor_mismatch(points, Half_plane::behind_p));
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
      EXPECT_EQ(nn_crust_reconstruction(points), cycle_edges(k)) << k << " " << phase;
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
  EXPECT_EQ(reconstruct(*algorithm, doubled).edges, cycle_edges(7));
}

}  // namespace
}  // namespace curvebench::algorithms
