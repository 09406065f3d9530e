// VICUR (algorithms/vicur.h): DISCUR's growth plus a continuation rule. Its rules are
// checked against a brute force in discur_test.cpp (GrowthRulesEqualBruteForce...); here:
// the law that it is DISCUR with continuation off, the paper's claimed cases (closed,
// open, several, sharp corners), where continuation changes the answer, parameters.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>

#include "algorithms/discur.h"
#include "algorithms/registry.h"
#include "algorithms/vicur.h"
#include "tests/support/edge_sets.h"
#include "tests/support/hand_made_curves.h"
#include "tests/support/point_generators.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;

RC_GTEST_PROP(Vicur, IsDiscurWithContinuationOff, ()) {
  const auto points = *testing::point_sets(40);
  RC_ASSERT(vicur_reconstruction(points, 2, 180, 1, 2) == discur_reconstruction(points));
}

TEST(Vicur, ReconstructsDenseSmoothClosedCurves) {
  for (const int components : {1, 2, 3})
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto c = testing::sampled_fourier_curves(seed * 7919, components, 5, 0.1);
      EXPECT_EQ(vicur_reconstruction(c.sample.points), c.truth) << c;
    }
}

TEST(Vicur, ReconstructsOpenCurvesAndTwoCircles) {
  for (const auto& c : {testing::sine_arc(), testing::two_circles()})
    EXPECT_EQ(vicur_reconstruction(c.points), c.truth) << c.name;
}

// A square and a 70-degree kite, uniformly sampled: each corner turns by 90 degrees or
// more at an edge no longer than the end edge, which corner_ratio 1.5 admits.
TEST(Vicur, ReconstructsSharpCornersSampledUniformly) {
  for (const auto& c : {testing::sampled_square(), testing::sampled_kite()})
    EXPECT_EQ(vicur_reconstruction(c.points), c.truth) << c.name;
}

// Two open polylines of spacing 1 whose ends are 1.87 apart, meeting at a 105-degree
// turn: DISCUR's proximity (1.87 <= 2) joins them; VICUR sees a corner taken by an edge
// longer than 1.5 end edges and keeps two curves; with corner_ratio 2 it joins them too.
TEST(Vicur, ContinuationKeepsAbruptTurnsApart) {
  std::vector<Point> points;
  for (int i = 10; i >= 0; --i) points.emplace_back(i, 0);  // ends at (0, 0) heading -x
  const double c = std::cos(0.3), s = std::sin(0.3);
  for (int i = 0; i <= 10; ++i) points.emplace_back(0.5 + i * c, 1.8 + i * s);
  Edges apart = testing::path_edges(11);
  for (const Edge& e : testing::path_edges(11, 11)) apart.push_back(e);
  apart = testing::canonical(apart);
  Edges joined = apart;
  joined.emplace_back(10, 11);
  joined = testing::canonical(joined);
  EXPECT_EQ(discur_reconstruction(points), joined);
  EXPECT_EQ(vicur_reconstruction(points), apart);
  EXPECT_EQ(vicur_reconstruction(points, 2, 90, 2, 2), joined);
}

TEST(Vicur, ParametersAndDegenerateInput) {
  const Algorithm vicur = vicur_algorithm();
  ASSERT_EQ(vicur.parameters.size(), 4u);  // Table 1: 4
  const std::vector<Point> duplicates{{0, 0}, {1, 0}, {0, 0}, {2, 0}};
  EXPECT_EQ(reconstruct(vicur, duplicates).edges, (Edges{{0, 1}, {1, 3}}));
  EXPECT_THROW(reconstruct(vicur, duplicates, {{"turning_angle", 200}}), std::invalid_argument);
  EXPECT_THROW(reconstruct(vicur, duplicates, {{"closing_rank", 1.5}}), std::invalid_argument);
  EXPECT_THROW(vicur_reconstruction(duplicates, 2, 90, 0, 2), std::invalid_argument);  // equal points first
  EXPECT_THROW(vicur_reconstruction(std::vector<Point>{{0, 0}, {1, 1}}, 2, 90, 0, 2), std::invalid_argument);
  EXPECT_TRUE(vicur_reconstruction({}).empty());
  EXPECT_EQ(vicur_reconstruction(std::vector<Point>{{0, 0}, {1e-300, 0}}), (Edges{{0, 1}}));
  const std::vector<Point> unit{{1, 0}, {0.5, 0.9}, {-0.5, 0.8}, {-1, 0.1}, {-0.4, -0.9}, {0.6, -0.8}};
  for (const int exponent : {1000, -1000})
    EXPECT_EQ(vicur_reconstruction(testing::scaled_by(unit, exponent)), vicur_reconstruction(unit)) << exponent;
}

// Table 1's row "VICUR": 4 parameters, non-uniform, manifold, open, multiple, sharp, no
// guarantee, O(n log n).
TEST(Vicur, RowIsTheSurveys) {
  const Algorithm vicur = vicur_algorithm();
  EXPECT_EQ(vicur.name, "vicur");
  EXPECT_EQ(vicur.category, "HVS Based");
  const Capabilities& c = vicur.capabilities;
  EXPECT_EQ(c.non_uniform, Support::yes);
  EXPECT_EQ(c.noise, Support::no);
  EXPECT_EQ(c.outliers, Support::no);
  EXPECT_EQ(c.manifold, Support::yes);
  EXPECT_EQ(c.open, Support::yes);
  EXPECT_EQ(c.multiple, Support::yes);
  EXPECT_EQ(c.sharp, Support::yes);
  EXPECT_FALSE(c.guarantee);
  EXPECT_EQ(vicur.condition.statement, "none");
}

}  // namespace
}  // namespace curvebench::algorithms
