// The shape hull (algorithms/shape_hull.h) against a brute force of its rule on small point
// sets in general position: the empty-circle Delaunay triangles, every length and angle an
// exact rational (CGAL::Exact_rational), and at every step a fresh scan for the longest
// boundary edge whose triangle may go. Plus its laws on any input (one simple cycle of
// Delaunay edges through every convex-hull point), the cases its paper claims (dense
// samplings of smooth closed curves with wide concavities, sharp corners), hand-made
// cases whose answer follows from the rule, and degenerate input.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

#include <CGAL/Exact_rational.h>
#include <CGAL/convex_hull_2.h>

#include "algorithms/registry.h"
#include "algorithms/shape_hull.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "graphs/delaunay_graph.h"
#include "tests/support/brute_force_graphs.h"
#include "tests/support/edge_sets.h"
#include "tests/support/point_generators.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;
using Rational = CGAL::Exact_rational;
using testing::along;
using testing::scaled_by;
using testing::degrees;

struct Vec {
  Rational x, y;
};
Vec minus(const Point& a, const Point& b) { return {Rational(a.x()) - Rational(b.x()), Rational(a.y()) - Rational(b.y())}; }
Rational dot(const Vec& u, const Vec& v) { return u.x * v.x + u.y * v.y; }

// The rule in its plainest form: while some boundary edge pq has its triangle's apex r off
// the boundary and (p - r).(q - r) < 0, remove the triangle of the longest such edge (ties to
// the smaller (p, q)); output the boundary. Triangles: triples of Delaunay edges whose
// circumcircle holds no other point (general position: the triangulation is unique).
Edges brute_shape_hull(const std::vector<Point>& points, const Edges& delaunay) {
  const std::size_t n = points.size();
  const auto triangles = testing::brute_force_delaunay_triangles(points, delaunay);
  if (triangles.empty()) return delaunay;  // collinear: the chain

  std::vector<bool> present(triangles.size(), true);
  const auto boundary = [&] {
    std::map<Edge, std::vector<std::size_t>> incident;  // edge -> present triangles on it
    for (std::size_t t = 0; t < triangles.size(); ++t)
      if (present[t]) {
        const auto [a, b, c] = triangles[t];
        incident[{a, b}].push_back(t);
        incident[{b, c}].push_back(t);
        incident[{a, c}].push_back(t);
      }
    std::map<Edge, std::size_t> result;  // boundary edge -> its one triangle
    for (const auto& [edge, ts] : incident)
      if (ts.size() == 1) result[edge] = ts.front();
    return result;
  };
  for (;;) {
    const auto edges = boundary();
    std::vector<bool> on_boundary(n, false);
    for (const auto& [edge, t] : edges) on_boundary[edge.first] = on_boundary[edge.second] = true;
    std::optional<std::pair<Edge, std::size_t>> best;
    const auto length = [&](const Edge& e) { const Vec d = minus(points[e.first], points[e.second]); return dot(d, d); };
    for (const auto& [edge, t] : edges) {
      const auto [p, q] = edge;
      const auto& tri = triangles[t];
      const std::size_t r = tri[0] != p && tri[0] != q ? tri[0] : tri[1] != p && tri[1] != q ? tri[1] : tri[2];
      if (on_boundary[r] || dot(minus(points[p], points[r]), minus(points[q], points[r])) >= 0) continue;
      // std::map iterates edges in increasing (p, q): a strictly longer edge replaces.
      if (!best || length(edge) > length(best->first)) best = {edge, t};
    }
    if (!best) {
      Edges result;
      for (const auto& [edge, t] : edges) result.push_back(edge);
      return result;
    }
    present[best->second] = false;
  }
}

// Every vertex of degree 0 or 2 and the edges one connected cycle.
::testing::AssertionResult one_cycle(const Edges& edges, std::size_t n) {
  if (edges.size() < 3) return ::testing::AssertionFailure() << edges.size() << " edges";
  const auto degree = degrees(edges, n);
  std::vector<std::vector<std::size_t>> adjacent(n);
  for (const auto& [i, j] : edges) adjacent[i].push_back(j), adjacent[j].push_back(i);
  for (std::size_t v = 0; v < n; ++v)
    if (degree[v] != 0 && degree[v] != 2) return ::testing::AssertionFailure() << "vertex " << v << " has degree " << degree[v];
  std::size_t previous = edges.front().first, current = edges.front().second, length = 1;
  while (current != edges.front().first) {
    const std::size_t next = adjacent[current][0] == previous ? adjacent[current][1] : adjacent[current][0];
    previous = current, current = next, ++length;
  }
  if (length != edges.size()) return ::testing::AssertionFailure() << "a cycle of " << length << " of " << edges.size() << " edges";
  return ::testing::AssertionSuccess();
}

bool all_collinear(const std::vector<Point>& points) {
  return std::all_of(points.begin(), points.end(), [&](const Point& p) { return CGAL::collinear(points[0], points[1], p); });
}

// Points on the convex hull's boundary, corners and points along its sides: those through
// which a line through another point has every point on one closed side.
std::vector<std::size_t> hull_boundary_points(const std::vector<Point>& points) {
  std::vector<std::size_t> result;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (j == i) continue;
      bool left = false, right = false;
      for (const Point& x : points) {
        const auto o = CGAL::orientation(points[i], points[j], x);
        left = left || o == CGAL::LEFT_TURN;
        right = right || o == CGAL::RIGHT_TURN;
      }
      if (!(left && right)) {
        result.push_back(i);
        break;
      }
    }
  return result;
}

bool convex_position(const std::vector<Point>& points) {
  std::vector<Point> hull;
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  return hull.size() == points.size();
}



// Where the Delaunay triangulation is unique, the brute force's empty-circle triangles are it.
RC_GTEST_PROP(ShapeHull, EqualsBruteForceInGeneralPosition, ()) {
  const auto points = *testing::uniform_points(24);
  const Edges strong = testing::strong_delaunay_edges(points);
  RC_PRE(strong == testing::weak_delaunay_edges(points));
  const Edges edges = shape_hull_reconstruction(points);
  RC_CLASSIFY(points.size() >= 3 && edges.size() > testing::hull_boundary_size(points), "sculpted");
  RC_ASSERT(edges == brute_shape_hull(points, strong));
}

// Flat clusters: many long obtuse triangles, so many removals and many refusals.
RC_GTEST_PROP(ShapeHull, EqualsBruteForceOnFlatClusters, ()) {
  auto points = *testing::clustered_points();
  if (points.size() > 32) points.resize(32);
  const Edges strong = testing::strong_delaunay_edges(points);
  RC_PRE(strong == testing::weak_delaunay_edges(points));
  const Edges edges = shape_hull_reconstruction(points);
  RC_CLASSIFY(points.size() >= 3 && edges.size() > testing::hull_boundary_size(points), "sculpted");
  RC_ASSERT(edges == brute_shape_hull(points, strong));
}

// On every input (grids, collinear runs, extreme scales): Delaunay edges; one simple cycle
// through every convex-hull point unless the points are collinear (then the chain); the same
// after scaling by a power of two (exact, so every decision is the same).
RC_GTEST_PROP(ShapeHull, GivesOneSimpleCycleThroughTheHullOnAnyInput, ()) {
  const auto points = *testing::point_sets(30);
  const Edges edges = shape_hull_reconstruction(points);
  const Edges delaunay = graphs::edge_list(graphs::delaunay_graph(points));
  RC_ASSERT(std::includes(delaunay.begin(), delaunay.end(), edges.begin(), edges.end()));
  if (points.size() < 3 || all_collinear(points)) {
    RC_ASSERT(edges == delaunay);
  } else {
    if (const auto cycle = one_cycle(edges, points.size()); !cycle) RC_FAIL(cycle.message());
    RC_ASSERT(!testing::has_crossing_or_overlap(points, edges));
    const auto degree = degrees(edges, points.size());
    const auto hull = hull_boundary_points(points);
    for (const std::size_t v : hull) RC_ASSERT(degree[v] == 2u);
    RC_CLASSIFY(edges.size() > hull.size(), "sculpted");
  }
  const std::vector<Point> scaled = scaled_by(points, *rc::gen::element(-40, -3, 5, 60));
  if (std::all_of(scaled.begin(), scaled.end(), [](const Point& p) {
        return (std::isnormal(p.x()) || p.x() == 0) && (std::isnormal(p.y()) || p.y() == 0);
      }))
    RC_ASSERT(shape_hull_reconstruction(scaled) == edges);
}

// A random Fourier curve (geometry::random_fourier_curve) epsilon-sampled, with its chain.
testing::Sampled_case sampled_curve(std::uint64_t seed, int harmonics, double amplitude, double decay, double epsilon) {
  testing::Sampled_case c;
  c.curve = geometry::random_fourier_curve(seed, {.harmonics = harmonics, .amplitude = amplitude, .decay = decay});
  const geometry::Local_feature_size lfs(c.curve);
  c.sample = geometry::safe_epsilon_sampling(lfs, epsilon, geometry::default_minimum_lfs(lfs));
  c.truth = testing::canonical(c.sample.edges);
  c.requested_epsilon = epsilon;
  return c;
}

// The paper's claim: a dense sampling of a smooth closed curve whose concavities widen
// towards the convex hull ("divergent concavity") gives exactly the curve. Measured, seeds
// k * 7919 for k = 1..20 or 30, single curves:
//   - testing::sampled_fourier_curves (amplitude 0.3, decay 2), harmonics 0-8, epsilon 0.1,
//     0.05, 0.02: 360 of 360 (harmonics 8: 11 of 20 not in convex position);
//   - amplitude 0.6 decay 2, and amplitude 0.3 decay 1, harmonics 3-8, epsilon 0.1 and
//     0.03: 360 of 360, of which 330 have concavities;
//   - amplitude 0.6 decay 1: 77 of 90 at epsilon 0.1, 83 of 90 at 0.03 (harmonics 8: 19
//     and 23 of 30); amplitude 1 decay 1: 45 of 89 and 56 of 89 (harmonics 8: 6 and 8 of
//     29). Those curves have narrow, deep pockets whose Delaunay triangles stop the
//     sculpting (an acute apex); not claimed, but the result is still one simple cycle.
TEST(ShapeHull, ReconstructsDenseSmoothClosedCurves) {
  int cases = 0, concave = 0;
  for (const double epsilon : {0.1, 0.03})
    for (const int harmonics : {1, 3, 5, 8})
      for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const auto c = testing::sampled_fourier_curves(seed * 7919, 1, harmonics, epsilon);
        EXPECT_EQ(shape_hull_reconstruction(c.sample.points), c.truth) << c;
        concave += !convex_position(c.sample.points);
        ++cases;
      }
  EXPECT_EQ(cases, 160);
  EXPECT_GT(concave, 10);  // the claim is not only about convex curves
}

TEST(ShapeHull, ReconstructsModeratelyConcaveCurves) {
  int concave = 0;
  for (const auto& [amplitude, decay] : {std::pair{0.6, 2.0}, std::pair{0.3, 1.0}})
    for (const int harmonics : {3, 5, 8})
      for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const auto c = sampled_curve(seed * 7919, harmonics, amplitude, decay, 0.1);
        EXPECT_EQ(shape_hull_reconstruction(c.sample.points), c.truth) << c;
        concave += !convex_position(c.sample.points);
      }
  EXPECT_GE(concave, 100);
}

// Where the claim does not hold the output is still a manifold: one simple cycle through
// every convex-hull point, the other points left out.
TEST(ShapeHull, StaysOneCycleOnDeeplyConcaveCurves) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto c = sampled_curve(seed * 7919, 5, 1.0, 1.0, 0.1);
    const Edges edges = shape_hull_reconstruction(c.sample.points);
    EXPECT_TRUE(one_cycle(edges, c.sample.size())) << c;
    EXPECT_FALSE(testing::has_crossing_or_overlap(c.sample.points, edges)) << c;
    std::vector<Point> hull;
    CGAL::convex_hull_2(c.sample.points.begin(), c.sample.points.end(), std::back_inserter(hull));
    const auto degree = degrees(edges, c.sample.size());
    for (std::size_t i = 0; i < c.sample.size(); ++i)
      if (std::find(hull.begin(), hull.end(), c.sample.points[i]) != hull.end()) {
        EXPECT_EQ(degree[i], 2u) << c << " point " << i;
      }
  }
}

// Regular polygons: every point on the hull, so nothing is removed. A centre point sees
// each side at 360/n degrees, acute for n >= 5: it stays out.
TEST(ShapeHull, RegularPolygonsAreTheirCycle) {
  for (const std::size_t n : {3u, 4u, 5u, 6u, 7u, 12u, 100u, 1000u}) {
    auto polygon = testing::regular_polygon(n, 1.0, 0.1);
    EXPECT_EQ(shape_hull_reconstruction(polygon), testing::cycle_edges(n)) << n;
    if (n < 5) continue;
    polygon.emplace_back(0, 0);
    EXPECT_EQ(shape_hull_reconstruction(polygon), testing::cycle_edges(n)) << n << " with its centre";
  }
}

// Small cases decided by hand from the rule.
TEST(ShapeHull, RemovesAnObtuseTriangleOnlyThroughItsBoundaryEdge) {
  // Apex 3 sees the longest side 01 at an obtuse angle ((-2,-1).(4,-1) = -7): triangle 013
  // goes, 3 joins the boundary, and the obtuse angles it makes with 02 and 12 no longer count.
  EXPECT_EQ(shape_hull_reconstruction(std::vector<Point>{{0, 0}, {6, 0}, {2, 4}, {2, 1}}),
            (Edges{{0, 2}, {0, 3}, {1, 2}, {1, 3}}));
  // Sides 02 and 12 are equally long and both obtuse at 3: the tie goes to (0, 2).
  EXPECT_EQ(shape_hull_reconstruction(std::vector<Point>{{0, 0}, {4, 0}, {2, 4}, {2, 1}}),
            (Edges{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
  // A right angle puts the circumcentre on the edge, not beyond it: the square keeps its
  // four triangles round the centre.
  EXPECT_EQ(shape_hull_reconstruction(std::vector<Point>{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {0, 0}}),
            testing::cycle_edges(4));
}

// Sharp corners: convex ones are on the hull. A concave corner is carved when the pocket's
// opening angle there exceeds 90 degrees (the last triangle's apex is obtuse); at exactly 90
// degrees the last triangle is right-angled and the corner point stays out.
TEST(ShapeHull, SharpCorners) {
  const auto square = along({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {8, 8, 8, 8});
  EXPECT_EQ(shape_hull_reconstruction(square), testing::cycle_edges(square.size()));
  const auto triangle = along({{0, 0}, {2, 0}, {0.5, 1.5}}, {16, 8, 8});
  EXPECT_EQ(shape_hull_reconstruction(triangle), testing::cycle_edges(triangle.size()));
  // A house with a V roof: the notch at (2, 3) opens at 2 atan 2 = 127 degrees.
  const auto house = along({{0, 0}, {4, 0}, {4, 4}, {2, 3}, {0, 4}}, {16, 16, 8, 8, 16});
  EXPECT_EQ(shape_hull_reconstruction(house), testing::cycle_edges(house.size()));
  for (const int exponent : {1000, -1000})
    EXPECT_EQ(shape_hull_reconstruction(scaled_by(house, exponent)), testing::cycle_edges(house.size())) << exponent;
  // An L: the notch corner (1, 1) is point 32; its last triangle, with (1 + 1/8, 1) and
  // (1, 1 + 1/8), is right-angled at it, so the edge 31-33 stays and 32 is left out.
  const auto ell = along({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {16, 8, 8, 8, 8, 16});
  ASSERT_EQ(ell[32], Point(1, 1));
  Edges expected = testing::cycle_edges(ell.size());
  expected.erase(std::find(expected.begin(), expected.end(), Edge{31, 32}));
  expected.erase(std::find(expected.begin(), expected.end(), Edge{32, 33}));
  expected.emplace_back(31, 33);
  EXPECT_EQ(shape_hull_reconstruction(ell), testing::canonical(expected));
}

TEST(ShapeHull, TinyAndDegenerateInput) {
  EXPECT_TRUE(shape_hull_reconstruction({}).empty());
  const std::vector<Point> one{{1, 2}}, two{{0, 0}, {1e-300, 0}}, three{{0, 0}, {2, 0}, {1, 0}};
  EXPECT_TRUE(shape_hull_reconstruction(one).empty());
  EXPECT_EQ(shape_hull_reconstruction(two), (Edges{{0, 1}}));
  EXPECT_EQ(shape_hull_reconstruction(three), (Edges{{0, 2}, {1, 2}}));
  EXPECT_EQ(shape_hull_reconstruction(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}), testing::cycle_edges(3));
  // Grids: every Delaunay triangle is half a unit square, never obtuse, so the output is the
  // hull's boundary (every point along it) and the inner points stay out.
  for (const int side : {3, 5}) {
    std::vector<Point> grid;
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) grid.emplace_back(x, y);
    const Edges edges = shape_hull_reconstruction(grid);
    EXPECT_TRUE(one_cycle(edges, grid.size()));
    EXPECT_EQ(edges.size(), std::size_t(4 * (side - 1))) << side;
    const auto degree = degrees(edges, grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
      const bool on_side = grid[i].x() == 0 || grid[i].y() == 0 || grid[i].x() == side - 1 || grid[i].y() == side - 1;
      EXPECT_EQ(degree[i], on_side ? 2u : 0u) << side << " point " << i;
    }
  }
  const Algorithm& shape_hull = *find_algorithm("shape-hull");
  const std::vector<Point> duplicates{{0, 0}, {1, 0}, {0, 0}, {2, 0}};
  EXPECT_EQ(reconstruct(shape_hull, duplicates).edges, (Edges{{0, 1}, {1, 3}}));
  const std::vector<Point> triangle_twice{{0, 0}, {1, 0}, {0, 1}, {1, 0}, {0, 0}};
  EXPECT_EQ(reconstruct(shape_hull, triangle_twice).edges, testing::cycle_edges(3));
  EXPECT_THROW(shape_hull_reconstruction(std::vector<Point>{{0, 0}, {0, 0}}), std::invalid_argument);
  EXPECT_THROW(shape_hull_reconstruction(std::vector<Point>{{0, 0}, {1, NAN}}), std::invalid_argument);
}

TEST(ShapeHull, RegistryRowIsTheSurveys) {
  const Algorithm* shape_hull = find_algorithm("shape-hull");
  ASSERT_NE(shape_hull, nullptr);
  EXPECT_EQ(shape_hull->title, "Shape-hull graph");
  EXPECT_EQ(shape_hull->category, "Graph Based");
  EXPECT_TRUE(shape_hull->parameters.empty());
  const Capabilities& c = shape_hull->capabilities;
  EXPECT_EQ(c.non_uniform, Support::yes);
  EXPECT_EQ(c.noise, Support::no);
  EXPECT_EQ(c.outliers, Support::no);
  EXPECT_EQ(c.manifold, Support::yes);
  EXPECT_EQ(c.open, Support::no);
  EXPECT_EQ(c.multiple, Support::no);
  EXPECT_EQ(c.sharp, Support::yes);
  EXPECT_FALSE(c.guarantee);
  EXPECT_EQ(c.time_complexity, "O(n log n)");
  EXPECT_EQ(shape_hull->condition.statement, "none");
  // Table 1 order: before Crawl.
  const auto all = registry();
  const auto position = [&](std::string_view name) {
    return std::find_if(all.begin(), all.end(), [&](const Algorithm& a) { return a.name == name; }) - all.begin();
  };
  EXPECT_LT(position("shape-hull"), position("crawl"));
}

}  // namespace
}  // namespace curvebench::algorithms
