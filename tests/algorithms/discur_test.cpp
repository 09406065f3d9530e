// DISCUR (algorithms/discur.h) against a brute force of its rules on small point sets in
// general position: the empty-circle Delaunay edges, every length an exact rational, and
// "accept the shortest acceptable edge, then look again from the shortest" in place of
// the event-driven retries. Plus the cases its paper claims (dense smooth closed curves,
// several at once, open curves, sharp corners) and degenerate input.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

#include <CGAL/Exact_rational.h>

#include "algorithms/discur.h"
#include "algorithms/registry.h"
#include "graphs/delaunay_graph.h"
#include "tests/support/brute_force_graphs.h"
#include "tests/support/edge_sets.h"
#include "tests/support/hand_made_curves.h"
#include "tests/support/point_generators.h"
#include "tests/support/reconstruction_laws.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;
using Rational = CGAL::Exact_rational;
using testing::exact_squared_distance;
using testing::degrees;


// The rules of discur.h in the plainest data structures: an adjacency list per point, a
// component label per point relabelled on every merge, the longest edge found by a scan.
Edges brute_grow_curves(const std::vector<Point>& points, const Edges& delaunay, const Curve_growth_rules& rules) {
  const std::size_t n = points.size(), k = rules.closing_rank;
  std::vector<std::vector<std::size_t>> neighbors(n), links(n);
  for (const auto& [i, j] : delaunay) neighbors[i].push_back(j), neighbors[j].push_back(i);
  const auto key = [&](std::size_t from, std::size_t to) { return std::make_tuple(exact_squared_distance(points[from], points[to]), to); };
  for (std::size_t v = 0; v < n; ++v)
    std::sort(neighbors[v].begin(), neighbors[v].end(), [&](std::size_t a, std::size_t b) { return key(v, a) < key(v, b); });
  const auto among_nearest = [&](std::size_t v, std::size_t w) {
    const std::size_t kept = std::min(k, neighbors[v].size());
    return std::find(neighbors[v].begin(), neighbors[v].begin() + kept, w) != neighbors[v].begin() + kept;
  };
  Edges sorted = delaunay;
  std::sort(sorted.begin(), sorted.end(), [&](const Edge& a, const Edge& b) {
    return std::make_tuple(exact_squared_distance(points[a.first], points[a.second]), a) <
           std::make_tuple(exact_squared_distance(points[b.first], points[b.second]), b);
  });
  std::vector<std::size_t> label(n);
  for (std::size_t v = 0; v < n; ++v) label[v] = v;
  Edges taken;
  const auto longest = [&](std::size_t l) {  // squared, 0 for a single point
    Rational best = 0;
    for (const auto& [i, j] : taken)
      if (label[i] == l) best = std::max(best, exact_squared_distance(points[i], points[j]));
    return best;
  };
  const Rational ratio2 = Rational(rules.proximity_ratio) * Rational(rules.proximity_ratio);
  const Rational corner2 = Rational(rules.corner_ratio) * Rational(rules.corner_ratio);
  const double c = rules.turning_angle_degrees == 90 ? 0.0 : std::cos(rules.turning_angle_degrees * std::numbers::pi / 180);
  const auto continues = [&](std::size_t p, std::size_t q) {
    if (rules.turning_angle_degrees >= 180 || links[p].size() != 1) return true;
    const std::size_t w = links[p][0];
    const Rational ux = Rational(points[p].x()) - points[w].x(), uy = Rational(points[p].y()) - points[w].y();
    const Rational vx = Rational(points[q].x()) - points[p].x(), vy = Rational(points[q].y()) - points[p].y();
    const Rational uv = ux * vx + uy * vy, uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
    // cos(turn) = uv / sqrt(uu vv) < c, squared with the signs kept apart.
    const bool sharp = c >= 0 ? (uv <= 0 && !(c == 0 && uv == 0)) || (c > 0 && uv * uv < Rational(c) * Rational(c) * uu * vv)
                              : uv < 0 && uv * uv > Rational(c) * Rational(c) * uu * vv;
    return !sharp || vv <= corner2 * uu;
  };
  for (bool grown = true; grown;) {
    grown = false;
    for (const auto& [a, b] : sorted) {
      if (links[a].size() == 2 || links[b].size() == 2) continue;
      if (std::find(taken.begin(), taken.end(), Edge{a, b}) != taken.end()) continue;
      const Rational d2 = exact_squared_distance(points[a], points[b]);
      bool accept;
      if (label[a] == label[b]) {
        const std::size_t size = std::count(label.begin(), label.end(), label[a]);
        accept = size >= 4 && among_nearest(a, b) && among_nearest(b, a) && d2 <= ratio2 * longest(label[a]) &&
                 continues(a, b) && continues(b, a);
      } else if (links[a].empty() && links[b].empty()) {
        accept = true;
      } else {
        const Rational l2 = std::max(longest(label[a]), longest(label[b]));
        accept = d2 <= ratio2 * l2 && continues(a, b) && continues(b, a);
      }
      if (!accept) continue;
      taken.emplace_back(a, b);
      links[a].push_back(b), links[b].push_back(a);
      const std::size_t from = label[b];
      for (std::size_t& l : label)
        if (l == from) l = label[a];
      grown = true;
      break;
    }
  }
  return testing::canonical(taken);
}

RC_GTEST_PROP(Discur, EqualsBruteForceInGeneralPosition, ()) {
  const auto points = *testing::uniform_points(24);
  const Edges strong = testing::strong_delaunay_edges(points);
  RC_PRE(strong == testing::weak_delaunay_edges(points));
  RC_ASSERT(discur_reconstruction(points) == brute_grow_curves(points, strong, {}));
}

// The same with continuation on and other ratios: the rules VICUR exposes.
RC_GTEST_PROP(Discur, GrowthRulesEqualBruteForceInGeneralPosition, ()) {
  const auto points = *testing::uniform_points(20);
  const Edges strong = testing::strong_delaunay_edges(points);
  RC_PRE(strong == testing::weak_delaunay_edges(points));
  const Curve_growth_rules rules{.proximity_ratio = *rc::gen::element(1.0, 1.5, 2.0, 3.0),
                                 .closing_rank = *rc::gen::inRange(1, 4),
                                 .turning_angle_degrees = *rc::gen::element(30.0, 90.0, 135.0, 180.0),
                                 .corner_ratio = *rc::gen::element(0.5, 1.0, 1.5)};
  RC_ASSERT(grow_curves(points, rules) == brute_grow_curves(points, strong, rules));
}

// On every input (grids, collinear runs, extreme scales): paths and cycles of Delaunay
// edges, the same after scaling by a power of two.
RC_GTEST_PROP(Discur, GivesPathsAndCyclesOfDelaunayEdgesOnAnyInput, ()) {
  const auto points = *testing::point_sets(30);
  testing::rc_assert_delaunay_paths_and_cycles([](const auto& p) { return discur_reconstruction(p); }, points);
}

// The paper's claim: dense (epsilon-, so non-uniform) samplings of smooth closed curves,
// one or several.
TEST(Discur, ReconstructsDenseSmoothClosedCurves) {
  for (const int components : {1, 2, 3})
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto c = testing::sampled_fourier_curves(seed * 7919, components, 5, 0.1);
      EXPECT_EQ(discur_reconstruction(c.sample.points), c.truth) << c;
    }
}

// Two disjoint circles of different spacing: two cycles.
TEST(Discur, ReconstructsTwoDisjointCircles) {
  const auto circles = testing::two_circles();
  EXPECT_EQ(discur_reconstruction(circles.points), circles.truth);
}

// Open curves: one path, both ends of degree one. A sine arc (uniform in x), a circular
// arc of 300 degrees whose ends are Delaunay neighbours, and an arc whose spacing grows
// by 5% per step (non-uniform).
TEST(Discur, ReconstructsOpenCurves) {
  std::vector<Point> sine = testing::sine_arc().points;
  std::vector<Point> arc, growing;
  for (int i = 0; i <= 100; ++i) {
    const double t = i * (300.0 / 100) * std::numbers::pi / 180;
    arc.emplace_back(std::cos(t), std::sin(t));
  }
  double x = 0, step = 0.01;
  for (int i = 0; i <= 60; ++i, x += step, step *= 1.05) growing.emplace_back(x, 0.3 * std::sin(3 * x));
  for (const auto* points : {&sine, &arc, &growing})
    EXPECT_EQ(discur_reconstruction(*points), testing::path_edges(points->size())) << points->size();
}

// Sharp corners, uniformly sampled: a square (90 degrees) and a kite with a 70-degree
// tip, each side cut into equal steps of about the same length.
TEST(Discur, ReconstructsSharpCornersSampledUniformly) {
  for (const auto& c : {testing::sampled_square(), testing::sampled_kite()})
    EXPECT_EQ(discur_reconstruction(c.points), c.truth) << c.name;
}

TEST(Discur, TinyAndDegenerateInput) {
  EXPECT_TRUE(discur_reconstruction({}).empty());
  const std::vector<Point> one{{1, 2}}, two{{0, 0}, {1e-300, 0}}, three{{0, 0}, {1, 0}, {2, 0}};
  EXPECT_TRUE(discur_reconstruction(one).empty());
  EXPECT_EQ(discur_reconstruction(two), (Edges{{0, 1}}));
  EXPECT_EQ(discur_reconstruction(three), (Edges{{0, 1}, {1, 2}}));
  // A collinear run with spacing 1 then a gap of 3: the gap is more than twice the longest.
  const std::vector<Point> gap{{0, 0}, {1, 0}, {2, 0}, {5, 0}, {6, 0}};
  EXPECT_EQ(discur_reconstruction(gap), (Edges{{0, 1}, {1, 2}, {3, 4}}));
  // A square: a 4-cycle (the smallest cycle DISCUR closes); a triangle stays a path.
  EXPECT_EQ(discur_reconstruction(testing::regular_polygon(4, 1.0)), testing::cycle_edges(4));
  EXPECT_EQ(discur_reconstruction(testing::regular_polygon(3, 1.0)).size(), 2u);
  // Huge and tiny coordinates: the same edges as at scale 1.
  const std::vector<Point> unit{{1, 0}, {0.5, 0.9}, {-0.5, 0.8}, {-1, 0.1}, {-0.4, -0.9}, {0.6, -0.8}};
  for (const int exponent : {1000, -1000})
    EXPECT_EQ(discur_reconstruction(testing::scaled_by(unit, exponent)), discur_reconstruction(unit)) << exponent;
  const std::vector<Point> duplicates{{0, 0}, {1, 0}, {0, 0}, {2, 0}};
  EXPECT_EQ(reconstruct(discur_algorithm(), duplicates).edges, (Edges{{0, 1}, {1, 3}}));
  EXPECT_THROW(discur_reconstruction(std::vector<Point>{{0, 0}, {0, 0}}), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(discur_reconstruction(std::vector<Point>{{0, 0}, {nan, 1}}), std::invalid_argument);
  EXPECT_THROW(grow_curves(unit, {.proximity_ratio = 0}), std::invalid_argument);
}

// Table 1's row "DISCUR": 0 parameters, non-uniform, manifold, open, multiple, sharp,
// guaranteed (the "vision function" condition), O(n log n).
TEST(Discur, RowIsTheSurveys) {
  const Algorithm discur = discur_algorithm();
  EXPECT_EQ(discur.name, "discur");
  EXPECT_EQ(discur.category, "HVS Based");
  EXPECT_TRUE(discur.parameters.empty());
  const Capabilities& c = discur.capabilities;
  EXPECT_EQ(c.non_uniform, Support::yes);
  EXPECT_EQ(c.noise, Support::no);
  EXPECT_EQ(c.outliers, Support::no);
  EXPECT_EQ(c.manifold, Support::yes);
  EXPECT_EQ(c.open, Support::yes);
  EXPECT_EQ(c.multiple, Support::yes);
  EXPECT_EQ(c.sharp, Support::yes);
  EXPECT_TRUE(c.guarantee);
  EXPECT_EQ(discur.condition.statement, "vision function");
  EXPECT_FALSE(discur.condition.epsilon_below);
}

}  // namespace
}  // namespace curvebench::algorithms
