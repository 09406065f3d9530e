// Peel (algorithms/peel.h): its three rules against a brute-force re-implementation in
// rationals, on points in general position with its own empty-circle Delaunay triangles and
// on degenerate input with the triangulation's; laws on any input (the peeled graph lies in
// the Gabriel graph and holds the relative neighbourhood graph but for exact ties; the
// result does not depend on the input order; scaling by 2^k changes nothing); hand cases
// whose answer follows from the rules (triangles, polygons, grids, a figure-eight with and
// without a sample at its crossing); dense smooth closed and open curves; tiny input.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include "algorithms/peel.h"
#include "algorithms/registry.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/gabriel_graph.h"
#include "graphs/graph.h"
#include "graphs/relative_neighborhood_graph.h"
#include "tests/support/edge_sets.h"
#include "tests/support/hand_made_curves.h"
#include "tests/support/point_generators.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

using Q = CGAL::Gmpq;
using Edges = std::vector<Edge>;
using Triangle = std::array<std::size_t, 3>;
using testing::canonical;
using testing::cycle_edges;

// ---------------------------------------------------------------- rational brute force

Q squared_distance(const Point& a, const Point& b) {
  const Q dx = Q(a.x()) - Q(b.x()), dy = Q(a.y()) - Q(b.y());
  return dx * dx + dy * dy;
}
Q orientation(const Point& a, const Point& b, const Point& c) {
  return (Q(b.x()) - Q(a.x())) * (Q(c.y()) - Q(a.y())) - (Q(b.y()) - Q(a.y())) * (Q(c.x()) - Q(a.x()));
}
// Positive iff d lies inside the circle through a, b, c (counterclockwise).
Q in_circle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const auto row = [&](const Point& p) {
    const Q x = Q(p.x()) - Q(d.x()), y = Q(p.y()) - Q(d.y());
    return std::array<Q, 3>{x, y, x * x + y * y};
  };
  const auto r = std::array{row(a), row(b), row(c)};
  return r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
         r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
}

bool in_general_position(const std::vector<Point>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        if (CGAL::sign(orientation(p[i], p[j], p[k])) == CGAL::ZERO) return false;
        for (std::size_t l = k + 1; l < n; ++l)
          if (CGAL::sign(in_circle(p[i], p[j], p[k], p[l])) == CGAL::ZERO) return false;
      }
  return true;
}

// The triangles whose open circumdisk holds no point (points in general position).
std::vector<Triangle> empty_circle_triangles(const std::vector<Point>& p) {
  std::vector<Triangle> triangles;
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        const CGAL::Sign o = CGAL::sign(orientation(p[i], p[j], p[k]));
        bool empty = true;
        for (std::size_t l = 0; l < n && empty; ++l)
          if (l != i && l != j && l != k) empty = CGAL::sign(in_circle(p[i], p[j], p[k], p[l])) * o != CGAL::POSITIVE;
        if (empty) triangles.push_back({i, j, k});
      }
  return triangles;
}

// The triangles of graphs::Delaunay_triangulation (its choice among cocircular points).
std::vector<Triangle> triangulation_triangles(const graphs::Delaunay_triangulation& dt) {
  std::set<Triangle> triangles;
  for (const auto& e : dt.edges())
    for (const graphs::Vertex apex : {e.left, e.right})
      if (apex != graphs::no_vertex) {
        Triangle t{e.source, e.target, apex};
        std::sort(t.begin(), t.end());
        triangles.insert(t);
      }
  return {triangles.begin(), triangles.end()};
}

// Peel re-implemented from its header, every step a fresh scan in rationals. `delaunay`: the
// triangulation's edges, `triangles` its triangles.
Peel_stages brute_force_peel(const std::vector<Point>& p, const Edges& delaunay, const std::vector<Triangle>& triangles,
                             double reach) {
  const std::size_t n = p.size();
  const auto d2 = [&](std::size_t a, std::size_t b) { return squared_distance(p[a], p[b]); };
  Peel_stages stages;

  // P1: not a longest side (>=) of any triangle holding it.
  for (const auto& [i, j] : delaunay) {
    bool longest = false;
    for (const Triangle& t : triangles) {
      if (std::count(t.begin(), t.end(), i) == 0 || std::count(t.begin(), t.end(), j) == 0) continue;
      const std::size_t k = t[0] + t[1] + t[2] - i - j;
      longest = longest || (d2(i, j) >= d2(i, k) && d2(i, j) >= d2(j, k));
    }
    if (!longest) stages.peeled.emplace_back(i, j);
  }
  stages.peeled = canonical(stages.peeled);

  // P2: fewer than two other peeled edges strictly shorter, at each end.
  const auto shorter_beside = [&](std::size_t a, std::size_t b) {
    int count = 0;
    for (const auto& [i, j] : stages.peeled) {
      const std::size_t other = i == a ? j : j == a ? i : n;
      if (other != n && other != b && d2(a, other) < d2(a, b)) ++count;
    }
    return count;
  };
  for (const auto& [a, b] : stages.peeled)
    if (shorter_beside(a, b) < 2 && shorter_beside(b, a) < 2) stages.filtered.emplace_back(a, b);

  // P3: rounds; in each, every end (degree exactly 1, having had degree 1 after P2 or 0
  // before the previous round) joins its nearest other Delaunay neighbour within reach.
  std::set<Edge> result(stages.filtered.begin(), stages.filtered.end());
  const auto neighbours_in_result = [&](std::size_t v) {
    std::vector<std::size_t> out;
    for (const auto& [i, j] : result)
      if (i == v || j == v) out.push_back(i == v ? j : i);
    return out;
  };
  std::vector<std::size_t> ends;
  for (std::size_t v = 0; v < n; ++v)
    if (neighbours_in_result(v).size() == 1) ends.push_back(v);
  const Q reach2 = Q(reach) * Q(reach);
  while (!ends.empty()) {
    std::vector<std::size_t> degree_before(n);
    for (std::size_t v = 0; v < n; ++v) degree_before[v] = neighbours_in_result(v).size();
    std::set<Edge> joins;
    for (const std::size_t a : ends) {
      const std::size_t w = neighbours_in_result(a).front();
      std::size_t best = n;
      for (const auto& [i, j] : delaunay) {
        const std::size_t x = i == a ? j : j == a ? i : n;
        if (x == n || x == w || !(d2(a, x) < reach2 * d2(a, w))) continue;
        if (best == n || d2(a, x) < d2(a, best) || (d2(a, x) == d2(a, best) && x < best)) best = x;
      }
      if (best != n) joins.insert(std::minmax(a, best));
    }
    result.insert(joins.begin(), joins.end());
    ends.clear();
    for (std::size_t v = 0; v < n; ++v)
      if (degree_before[v] == 0 && neighbours_in_result(v).size() == 1) ends.push_back(v);
  }
  stages.result = {result.begin(), result.end()};
  return stages;
}

Edges edges_of(const std::vector<Triangle>& triangles) {
  Edges edges;
  for (const Triangle& t : triangles) edges.insert(edges.end(), {{t[0], t[1]}, {t[0], t[2]}, {t[1], t[2]}});
  return canonical(edges);
}

void expect_same_stages(const Peel_stages& actual, const Peel_stages& expected) {
  RC_ASSERT(actual.peeled == expected.peeled);
  RC_ASSERT(actual.filtered == expected.filtered);
  RC_ASSERT(actual.result == expected.result);
}

double any_reach() { return *rc::gen::element(0.0, 0.5, 1.0, 1.2, 1.5, 2.5, 10.0); }

// 3 to 16 points in general position, at ordinary scale or scaled by 2^-1020 / 2^990
// (squared distances underflow / overflow doubles: the exact stages of every predicate).
std::vector<Point> general_position_points() {
  const auto coordinate = rc::gen::inRange(-(1 << 20), 1 << 20);
  const auto xy = *rc::gen::container<std::vector<std::pair<int, int>>>(*rc::gen::inRange(3, 17),
                                                                         rc::gen::pair(coordinate, coordinate));
  const int exponent = *rc::gen::element(0, -1020, 990);
  std::vector<Point> points;
  for (const auto& [x, y] : xy) points.emplace_back(std::ldexp(x / 3.0, exponent), std::ldexp(y / 7.0, exponent));
  points = testing::distinct(points);
  RC_PRE(in_general_position(points));
  return points;
}

RC_GTEST_PROP(PeelOracle, MatchesABruteForceWithItsOwnDelaunayTrianglesInGeneralPosition, ()) {
  const std::vector<Point> points = general_position_points();
  const double reach = any_reach();
  const std::vector<Triangle> triangles = empty_circle_triangles(points);
  expect_same_stages(peel_stages(points, reach), brute_force_peel(points, edges_of(triangles), triangles, reach));
}

RC_GTEST_PROP(PeelOracle, MatchesABruteForceOnDegenerateInput, ()) {
  // Grids, collinear runs, extreme scales: the triangulation among cocircular points is
  // CGAL's (symbolic perturbation), so the brute force reads its triangles.
  const std::vector<Point> points = *testing::point_sets(24);
  const double reach = any_reach();
  if (points.size() < 2) {
    RC_ASSERT(peel_reconstruction(points, reach).empty());
    return;
  }
  const graphs::Delaunay_triangulation dt(points);
  Edges delaunay;
  for (const auto& e : dt.edges()) delaunay.emplace_back(e.source, e.target);
  expect_same_stages(peel_stages(points, reach),
                     brute_force_peel(points, canonical(delaunay), triangulation_triangles(dt), reach));
}

// ---------------------------------------------------------------- laws on any input

RC_GTEST_PROP(Peel, PeeledGraphLiesBetweenTheRelativeNeighbourhoodAndGabrielGraphs, ()) {
  const std::vector<Point> points = *rc::gen::weightedOneOf<std::vector<Point>>(
      {{3, testing::point_sets(40)}, {1, testing::clustered_points()}});
  RC_PRE(points.size() >= 2);
  const Edges peeled = peel_stages(points, 0).peeled;
  // An apex angle of 90 degrees or more makes an edge the strictly longest side.
  const Edges gabriel = graphs::edge_list(graphs::gabriel_graph(points));
  RC_ASSERT(std::includes(gabriel.begin(), gabriel.end(), peeled.begin(), peeled.end()));
  // An RNG edge pq has no point with max(|pc|, |qc|) < |pq|, so it is peeled only as a
  // longest side tied with another: some c with max(|pc|, |qc|) = |pq|.
  for (const auto& [p, q] : graphs::edge_list(graphs::relative_neighborhood_graph(points))) {
    if (std::binary_search(peeled.begin(), peeled.end(), Edge{p, q})) continue;
    const Q pq = squared_distance(points[p], points[q]);
    bool tie = false;
    for (std::size_t c = 0; c < points.size(); ++c)
      tie = tie || (c != p && c != q &&
                    std::max(squared_distance(points[p], points[c]), squared_distance(points[q], points[c])) == pq);
    RC_ASSERT(tie);
  }
}

RC_GTEST_PROP(Peel, DoesNotDependOnTheInputOrder, ()) {
  // Random points (no exact ties of distance, which go by index): permuting the input
  // permutes the output.
  const std::vector<Point> points = *testing::uniform_points(60);
  const double reach = any_reach();
  const auto order = *rc::gen::map(rc::gen::arbitrary<std::uint64_t>(), [&](std::uint64_t seed) {
    std::vector<std::size_t> o(points.size());
    std::iota(o.begin(), o.end(), 0);
    std::shuffle(o.begin(), o.end(), std::mt19937_64(seed));
    return o;
  });
  std::vector<Point> shuffled;
  for (const std::size_t i : order) shuffled.push_back(points[i]);
  Edges mapped;
  for (const auto& [i, j] : peel_reconstruction(shuffled, reach)) mapped.emplace_back(order[i], order[j]);
  RC_ASSERT(canonical(mapped) == peel_reconstruction(points, reach));
}

TEST(Peel, ScalingByPowersOfTwoChangesNothing) {
  // Every predicate is homogeneous in the coordinates and scaling by 2^k is exact, so the
  // edges at 1e-150 and 1e150 are those at 1 (squared lengths leave the double range there).
  const testing::Sampled_case c = testing::sampled_fourier_curves(17, 2, 4, 0.3);
  for (const double reach : {0.0, 1.5}) {
    const Edges at_one = peel_reconstruction(c.sample.points, reach);
    for (const int exponent : {-500, 500}) {
      std::vector<Point> scaled;
      for (const Point& p : c.sample.points)
        scaled.emplace_back(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent));
      EXPECT_EQ(peel_reconstruction(scaled, reach), at_one) << "2^" << exponent << ", reach " << reach;
    }
  }
}

// ---------------------------------------------------------------- hand cases

Edges reconstruct_peel(const std::vector<Point>& points, Parameter_values values = {}) {
  return reconstruct(*find_algorithm("peel"), points, values).edges;
}

TEST(Peel, TinyTrianglesAndCollinearInput) {
  EXPECT_TRUE(reconstruct_peel({}).empty());
  EXPECT_TRUE(reconstruct_peel({{1, 1}}).empty());
  EXPECT_EQ(reconstruct_peel({{0, 0}, {2, 1}}), (Edges{{0, 1}}));
  // 3-4-5: the hypotenuse is peeled. P3 then joins the end (4, 0), whose edge is 4 long, to
  // (0, 3), 5 away, iff 5 < 4 reach: not at reach 1.25 exactly, but just above it (the end
  // (0, 3) would need reach > 5/3).
  const std::vector<Point> right_triangle{{0, 0}, {4, 0}, {0, 3}};
  EXPECT_EQ(reconstruct_peel(right_triangle), (Edges{{0, 1}, {0, 2}}));
  EXPECT_EQ(reconstruct_peel(right_triangle, {{"reach", 1.25}}), (Edges{{0, 1}, {0, 2}}));
  EXPECT_EQ(reconstruct_peel(right_triangle, {{"reach", std::nextafter(1.25, 2.0)}}), cycle_edges(3));
  // Two equal longest sides (sqrt 5 > 2): both are peeled.
  EXPECT_EQ(reconstruct_peel({{0, 0}, {2, 0}, {1, 2}}), (Edges{{0, 1}}));
  // The unit square: both triangles peel the diagonal, whichever it is.
  EXPECT_EQ(reconstruct_peel({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), cycle_edges(4));
  // Collinear, shuffled: no triangle, so nothing is peeled; the chain along the line.
  const std::vector<Point> line{{3, 3}, {0, 0}, {4, 4}, {1, 1}, {2, 2}};
  EXPECT_EQ(reconstruct_peel(line), (Edges{{0, 2}, {0, 4}, {1, 3}, {3, 4}}));
  // P3 adds nothing: an end of the chain has no Delaunay neighbour besides its one edge's.
  EXPECT_EQ(reconstruct_peel(line, {{"reach", 10}}), (Edges{{0, 2}, {0, 4}, {1, 3}, {3, 4}}));
  // Duplicates merge into their first occurrence: the right isosceles triangle loses its
  // hypotenuse (1, 0)-(0, 1).
  EXPECT_EQ(reconstruct_peel({{0, 0}, {1, 0}, {0, 0}, {0, 1}}), (Edges{{0, 1}, {0, 3}}));
}

TEST(Peel, RegularPolygonsAreCycles) {
  // A side is shorter than every diagonal, and every diagonal is the longest side of the
  // triangle on its shorter arc, whichever triangulation of the cocircular points CGAL takes.
  for (std::size_t k = 4; k <= 40; ++k)
    for (const double rotation : {0.0, 0.3, 1.0})
      for (const double reach : {0.0, 1.5})
        EXPECT_EQ(peel_reconstruction(testing::regular_polygon(k, 1 + k / 7.0, rotation, Point(5, -3)), reach),
                  cycle_edges(k))
            << k << "-gon rotated by " << rotation << ", reach " << reach;
}

TEST(Peel, GridKeepsEveryUnitEdge) {
  // Each unit square is split by a diagonal, the longest side of both its triangles; the
  // unit edges at a vertex are equally long, so none has a strictly shorter one beside it.
  constexpr std::size_t side = 7;
  std::vector<Point> points;
  Edges expected;
  for (std::size_t y = 0; y < side; ++y)
    for (std::size_t x = 0; x < side; ++x) {
      points.emplace_back(double(x), double(y));
      const std::size_t i = y * side + x;
      if (x + 1 < side) expected.emplace_back(i, i + 1);
      if (y + 1 < side) expected.emplace_back(i, i + side);
    }
  for (const double reach : {0.0, 1.5}) EXPECT_EQ(peel_reconstruction(points, reach), canonical(expected)) << reach;
}

TEST(Peel, RecoversTheCrossingOfAFigureEightSampledAtTheCrossing) {
  // n samples evenly in t, so both branches are sampled at the origin: one point there, of
  // degree 4 in the truth, its four neighbours equally far (by symmetry, up to rounding).
  for (const std::size_t n : {200u, 400u, 1000u}) {
    const auto eight = testing::figure_eight_sampled_at_the_crossing(n);
    const std::vector<Point>& points = eight.points;
    const Edges& truth = eight.truth;
    const std::size_t centre = eight.crossing;

    // Without P3, the centre keeps two of its four edges (P2); the two neighbours it drops
    // are left with one edge each, and nothing else changes.
    const Edges without = peel_reconstruction(points, 0);
    ASSERT_TRUE(std::includes(truth.begin(), truth.end(), without.begin(), without.end())) << n;
    Edges missing;
    std::set_difference(truth.begin(), truth.end(), without.begin(), without.end(), std::back_inserter(missing));
    ASSERT_EQ(missing.size(), 2u) << n;
    for (const auto& [i, j] : missing) EXPECT_TRUE(i == centre || j == centre) << n;

    // With P3 (the survey's claim): each dropped neighbour's nearest other Delaunay
    // neighbour is the centre, as near as its own edge (< 1.5 times), so both come back.
    EXPECT_EQ(peel_reconstruction(points, 1.5), truth) << n;
  }
}

TEST(Peel, FigureEightCrossingBetweenSamplesBecomesARectangle) {
  // Samples at t = 2 pi (i + 1/2) / n: the crossing lies midway between a1 = n/4 - 1 and
  // a2 = n/4 on one branch and b1 = 3n/4 - 1, b2 = 3n/4 on the other. The four points are
  // (+-u, +-v) with v slightly below u: a rectangle whose diagonals a1a2, b1b2 are the
  // truth's two crossing edges. A planar graph cannot keep both; P1 peels the one that is a
  // Delaunay edge (the longest side of both its triangles); the four sides stay (P1, P2),
  // and at each corner the two sides, at most 2u, are shorter than the branch edge to the
  // outer neighbour (about 2.8u), which P2 drops. That outer neighbour is left with one
  // edge; P3 at reach 1.5 joins it back to its corner, as near as its own edge.
  for (const std::size_t n : {200u, 400u, 1000u}) {
    const auto eight = testing::figure_eight_sampled_between(n);
    const std::vector<Point>& points = eight.points;
    const Edges& truth = eight.truth;
    const std::size_t a1 = n / 4 - 1, a2 = n / 4, b1 = 3 * n / 4 - 1, b2 = 3 * n / 4;
    const std::set<Edge> diagonals{{a1, a2}, {b1, b2}};
    const std::set<Edge> outer{{a1 - 1, a1}, {a2, a2 + 1}, {b1 - 1, b1}, {b2, b2 + 1}};
    const Edges sides{{a1, b1}, {a1, b2}, {a2, b1}, {a2, b2}};

    Edges with, without;
    for (const Edge& e : canonical(truth)) {
      if (diagonals.count(e)) continue;
      with.push_back(e);
      if (!outer.count(e)) without.push_back(e);
    }
    with.insert(with.end(), sides.begin(), sides.end());
    without.insert(without.end(), sides.begin(), sides.end());
    EXPECT_EQ(peel_reconstruction(points, 0), canonical(without)) << n;
    EXPECT_EQ(peel_reconstruction(points, 1.5), canonical(with)) << n;
  }
}

// ---------------------------------------------------------------- smooth curves

TEST(Peel, ReconstructsDenseSmoothClosedCurves) {
  // Fixed seeds, one to three components; P3 has no end to act on, whatever the reach.
  std::ostringstream table;
  for (const double epsilon : {0.1, 0.15, 0.2, 0.3, 0.4}) {
    int total = 0, exact = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      const testing::Sampled_case c = testing::sampled_fourier_curves(seed * 7919, 1 + seed % 3, 2 + seed % 7, epsilon);
      ++total;
      const bool ok = peel_reconstruction(c.sample.points, 0) == c.truth;
      exact += ok;
      EXPECT_TRUE(ok || epsilon > 0.2) << c;  // above 0.2: measured, not claimed
      if (epsilon <= 0.2) {
        EXPECT_EQ(peel_reconstruction(c.sample.points, 1.5), c.truth) << c;
      }
    }
    table << "epsilon " << epsilon << ": peel exact on " << exact << "/" << total << '\n';
  }
  std::cout << table.str();
}

TEST(Peel, ReconstructsSeveralClosedCurvesAndAnOpenArc) {
  auto points = testing::regular_polygon(24, 1, 0.1, Point(0, 0));
  const auto second = testing::regular_polygon(18, 0.8, 0.2, Point(4, 1));
  points.insert(points.end(), second.begin(), second.end());
  Edges expected = cycle_edges(24);
  for (const Edge& e : cycle_edges(18, 24)) expected.push_back(e);
  // An open parabolic arc, well away from both, spacing about 0.17: its ends' next nearest
  // points are two spacings away, beyond reach 1.5, so they stay open.
  for (int i = 0; i <= 20; ++i) {
    const double x = -1.5 + 3.0 * i / 20;
    points.emplace_back(10 + x, 0.3 * x * x);
    if (i > 0) expected.emplace_back(points.size() - 2, points.size() - 1);
  }
  expected = canonical(expected);
  for (const double reach : {0.0, 1.5}) EXPECT_EQ(reconstruct_peel(points, {{"reach", reach}}), expected) << reach;
}

TEST(Peel, IsRegisteredAsTheSurveyDescribesIt) {
  const Algorithm* peel = find_algorithm("peel");
  ASSERT_NE(peel, nullptr);
  EXPECT_EQ(peel->title, "Peel");
  EXPECT_EQ(peel->category, "Non-manifold");
  EXPECT_EQ(peel->condition.statement, "none");
  EXPECT_FALSE(peel->condition.epsilon_below.has_value());
  const Capabilities& c = peel->capabilities;
  EXPECT_EQ(c.manifold, Support::no);
  EXPECT_EQ(c.noise, Support::yes);
  EXPECT_EQ(c.outliers, Support::yes);
  EXPECT_EQ(c.sharp, Support::no);
  ASSERT_EQ(peel->parameters.size(), 1u);
  EXPECT_EQ(peel->parameters[0].name, "reach");
  EXPECT_EQ(peel->parameters[0].default_value, 0);
  const std::vector<Point> two{{0, 0}, {1, 0}};
  EXPECT_THROW(reconstruct(*peel, two, {{"reach", -1}}), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench::algorithms
