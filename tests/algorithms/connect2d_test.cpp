// Connect2D (algorithms/connect2d.h) against a brute force of its steps on small point sets
// in general position: empty-circle Delaunay triangles, every length an exact rational
// (CGAL::Exact_rational), every choice a fresh scan. Plus its laws on any input (one simple
// polygon of Delaunay edges, through every point when sculpting does not stall), the cases
// its paper claims (dense smooth closed curves, sparse locally uniform samplings, convex
// position, the survey's sharp-corner family) and degenerate input.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

#include <CGAL/Exact_rational.h>
#include <CGAL/convex_hull_2.h>

#include "algorithms/connect2d.h"
#include "algorithms/registry.h"
#include "geometry/curves/corner_curve.h"
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
using testing::exact_squared_distance;
using testing::scaled_by;

Rational cross(const Point& o, const Point& a, const Point& b) {
  return (Rational(a.x()) - Rational(o.x())) * (Rational(b.y()) - Rational(o.y())) -
         (Rational(a.y()) - Rational(o.y())) * (Rational(b.x()) - Rational(o.x()));
}

// d strictly inside the circle through a, b, c (not collinear).
bool inside_circle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const auto lifted = [&](const Point& p) {
    const Rational x = Rational(p.x()) - Rational(d.x()), y = Rational(p.y()) - Rational(d.y());
    return std::array<Rational, 3>{x, y, x * x + y * y};
  };
  const auto u = lifted(a), v = lifted(b), w = lifted(c);
  const Rational det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                       u[2] * (v[0] * w[1] - v[1] * w[0]);
  return cross(a, b, c) > 0 ? det > 0 : det < 0;
}

// The steps of connect2d.h in their plainest form, on points in general position.
Edges brute_connect2d(const std::vector<Point>& points, const Edges& delaunay) {
  const std::size_t n = points.size();
  std::map<Edge, std::size_t> rank;  // by exact squared length, then the pair
  {
    Edges sorted = delaunay;
    std::sort(sorted.begin(), sorted.end(), [&](const Edge& a, const Edge& b) {
      return std::make_tuple(exact_squared_distance(points[a.first], points[a.second]), a) <
             std::make_tuple(exact_squared_distance(points[b.first], points[b.second]), b);
    });
    for (std::size_t r = 0; r < sorted.size(); ++r) rank[sorted[r]] = r;
  }
  const auto key = [](std::size_t i, std::size_t j) { return Edge(std::min(i, j), std::max(i, j)); };
  using Tri = std::array<std::size_t, 3>;
  std::vector<Tri> triangles;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        if (!rank.count({i, j}) || !rank.count({j, k}) || !rank.count({i, k}) || cross(points[i], points[j], points[k]) == 0)
          continue;
        bool empty = true;
        for (std::size_t m = 0; m < n && empty; ++m)
          if (m != i && m != j && m != k && inside_circle(points[i], points[j], points[k], points[m])) empty = false;
        if (empty) triangles.push_back({i, j, k});
      }
  if (triangles.empty()) return delaunay;  // fewer than three points, or collinear: the chain
  const auto sides = [&](const Tri& t) {
    return std::array<Edge, 3>{key(t[1], t[2]), key(t[0], t[2]), key(t[0], t[1])};  // side i opposite corner i
  };
  std::map<Edge, std::vector<std::size_t>> on_edge;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (const Edge& e : sides(triangles[t])) on_edge[e].push_back(t);
  std::set<std::size_t> hull;
  for (const auto& [e, ts] : on_edge)
    if (ts.size() == 1) hull.insert(e.first), hull.insert(e.second);

  // 1. EMST by Kruskal (components as labels), then valence completion.
  Edges by_rank(delaunay.size());
  for (const auto& [e, r] : rank) by_rank[r] = e;
  std::vector<std::size_t> label(n), valence(n, 0);
  for (std::size_t v = 0; v < n; ++v) label[v] = v;
  std::set<Edge> bc;
  for (const Edge& e : by_rank)
    if (label[e.first] != label[e.second]) {
      const std::size_t old = label[e.first];
      for (std::size_t& l : label)
        if (l == old) l = label[e.second];
      bc.insert(e), ++valence[e.first], ++valence[e.second];
    }
  for (const Edge& e : by_rank)
    if (!bc.count(e) && (valence[e.first] < 2 || valence[e.second] < 2)) bc.insert(e), ++valence[e.first], ++valence[e.second];

  // 2. Outside: reached from a hull side not in the BC, then across non-BC edges.
  std::vector<bool> outside(triangles.size(), false);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      if (outside[t]) continue;
      for (const Edge& e : sides(triangles[t])) {
        if (bc.count(e)) continue;
        const auto& ts = on_edge[e];
        if (ts.size() == 1 || outside[ts[0] == t ? ts[1] : ts[0]]) outside[t] = true;
      }
      changed |= outside[t];
    }
  }

  // 3. Inflate by fresh scans.
  std::vector<bool> region(triangles.size(), false);
  const auto reached = [&](std::size_t v) {
    for (std::size_t t = 0; t < triangles.size(); ++t)
      if (region[t] && std::count(triangles[t].begin(), triangles[t].end(), v)) return true;
    return false;
  };
  const auto in_region_across = [&](std::size_t t, const Edge& e) {
    const auto& ts = on_edge[e];
    return ts.size() == 2 && region[ts[0] == t ? ts[1] : ts[0]];
  };
  const auto ranks_longest_first = [&](std::size_t t) {
    std::array<std::size_t, 3> r;
    for (int i = 0; i < 3; ++i) r[i] = rank[sides(triangles[t])[i]];
    std::sort(r.rbegin(), r.rend());
    return r;
  };
  using Key = std::tuple<int, std::array<std::size_t, 3>>;
  const auto join_key = [&](std::size_t t) -> std::optional<Key> {
    int touching = 0, side = 0;
    for (int i = 0; i < 3; ++i)
      if (in_region_across(t, sides(triangles[t])[i])) ++touching, side = i;
    if (touching == 0 || touching == 3 || (touching == 1 && reached(triangles[t][side]))) return std::nullopt;
    return Key{outside[t] ? touching : 0, ranks_longest_first(t)};
  };
  {
    std::size_t seed = 0;
    for (std::size_t t = 1; t < triangles.size(); ++t)
      if (std::make_tuple(outside[t], ranks_longest_first(t)) < std::make_tuple(outside[seed], ranks_longest_first(seed)))
        seed = t;
    region[seed] = true;
  }
  for (;;) {
    std::optional<std::pair<Key, std::size_t>> best;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      if (region[t]) continue;
      if (const auto k = join_key(t); k && (!best || *k < best->first)) best = {{*k, t}};
    }
    bool all_reached = true;
    for (std::size_t v = 0; v < n; ++v) all_reached = all_reached && reached(v);
    if (!best || (all_reached && std::get<0>(best->first) != 0)) break;
    region[best->second] = true;
  }

  // 4. Sculpt by fresh scans: the longest boundary edge with an interior apex.
  const auto interior = [&](std::size_t v) {
    if (hull.count(v)) return false;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      if (!region[t] && std::count(triangles[t].begin(), triangles[t].end(), v)) return false;
    return true;
  };
  for (;;) {
    std::optional<std::pair<std::size_t, std::size_t>> best;  // (rank, triangle)
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      if (!region[t]) continue;
      for (int i = 0; i < 3; ++i) {
        const Edge e = sides(triangles[t])[i];
        if (!in_region_across(t, e) && interior(triangles[t][i]) && (!best || rank[e] > best->first))
          best = {{rank[e], t}};
      }
    }
    if (!best) break;
    region[best->second] = false;
  }
  Edges result;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (region[t])
      for (const Edge& e : sides(triangles[t]))
        if (!in_region_across(t, e)) result.push_back(e);
  return testing::canonical(result);
}

// One simple closed polygon: every listed vertex of degree 2, one cycle, no two edges
// crossing or overlapping (exact orientations). Returns its vertex count, 0 if it is not.
std::size_t simple_polygon_size(const std::vector<Point>& points, const Edges& edges) {
  std::map<std::size_t, std::vector<std::size_t>> adjacent;
  for (const auto& [i, j] : edges) adjacent[i].push_back(j), adjacent[j].push_back(i);
  for (const auto& [v, next] : adjacent)
    if (next.size() != 2) return 0;
  if (adjacent.size() < 3) return 0;
  std::size_t length = 0, previous = adjacent.begin()->first, at = adjacent.begin()->second[0];
  for (++length; at != adjacent.begin()->first; ++length) {
    const std::size_t next = adjacent[at][0] == previous ? adjacent[at][1] : adjacent[at][0];
    previous = at, at = next;
  }
  if (length != adjacent.size()) return 0;
  const auto sign = [](const Rational& r) { return (r > 0) - (r < 0); };
  for (std::size_t a = 0; a < edges.size(); ++a)
    for (std::size_t b = a + 1; b < edges.size(); ++b) {
      const auto [p, q] = edges[a];
      const auto [r, s] = edges[b];
      if (p == r || p == s || q == r || q == s) continue;  // polygon neighbours share an end
      const int d1 = sign(cross(points[p], points[q], points[r])), d2 = sign(cross(points[p], points[q], points[s]));
      const int d3 = sign(cross(points[r], points[s], points[p])), d4 = sign(cross(points[r], points[s], points[q]));
      if (d1 == 0 && d2 == 0) {  // on one line: they meet iff their extents overlap on both axes
        const auto overlap = [](double a, double b, double c, double d) {
          return std::max(std::min(a, b), std::min(c, d)) <= std::min(std::max(a, b), std::max(c, d));
        };
        if (overlap(points[p].x(), points[q].x(), points[r].x(), points[s].x()) &&
            overlap(points[p].y(), points[q].y(), points[r].y(), points[s].y()))
          return 0;
      } else if (d1 * d2 <= 0 && d3 * d4 <= 0) {
        return 0;  // touching or crossing
      }
    }
  return length;
}

RC_GTEST_PROP(Connect2d, EqualsBruteForceInGeneralPosition, ()) {
  const auto points = *testing::uniform_points(18);
  const Edges strong = testing::strong_delaunay_edges(points);
  RC_PRE(strong == testing::weak_delaunay_edges(points));
  RC_ASSERT(connect2d_reconstruction(points) == brute_connect2d(points, strong));
}

// On every input of three or more points not all on a line: a simple polygon of Delaunay
// edges through every convex-hull corner; the same after exact scaling. (Not always through
// every point: see the header's step 5.)
RC_GTEST_PROP(Connect2d, GivesOneSimplePolygonOfDelaunayEdges, ()) {
  const auto points = *testing::point_sets(30);
  const Edges edges = connect2d_reconstruction(points);
  const Edges delaunay = graphs::edge_list(graphs::delaunay_graph(points));
  RC_ASSERT(std::includes(delaunay.begin(), delaunay.end(), edges.begin(), edges.end()));
  const bool collinear = std::all_of(points.begin(), points.end(), [&](const Point& p) {
    return points.size() < 3 || CGAL::collinear(points[0], points[1], p);
  });
  if (collinear) {
    RC_ASSERT(edges.size() + 1 == std::max<std::size_t>(points.size(), 1));  // the chain
  } else {
    RC_ASSERT(simple_polygon_size(points, edges) >= 3u);
    std::vector<Point> corners;
    CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(corners));
    std::set<std::size_t> on_polygon;
    for (const auto& [i, j] : edges) on_polygon.insert(i), on_polygon.insert(j);
    for (const Point& corner : corners)
      RC_ASSERT(on_polygon.count(std::find(points.begin(), points.end(), corner) - points.begin()) == 1u);
  }
  const int exponent = *rc::gen::element(-40, -3, 5, 60);
  const auto scaled = scaled_by(points, exponent);
  if (std::all_of(scaled.begin(), scaled.end(), [](const Point& p) {
        return (std::isnormal(p.x()) || p.x() == 0) && (std::isnormal(p.y()) || p.y() == 0);
      }))
    RC_ASSERT(connect2d_reconstruction(scaled) == edges);
}

// The paper's main claim: one smooth closed curve sampled at epsilon < 1/2, exact (the
// local uniformity u < 1.609 is not measured; the safe sampler spaces points evenly by lfs).
TEST(Connect2d, ReconstructsDenseSmoothClosedCurves) {
  std::ostringstream table;
  for (const double epsilon : {0.1, 0.2, 0.3, 0.4, 0.49}) {
    int exact = 0, total = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      const auto c = testing::sampled_fourier_curves(seed * 7919, 1, 2 + seed % 7, epsilon);
      if (!(c.measured_epsilon < 0.5)) continue;
      ++total;
      const Edges edges = connect2d_reconstruction(c.sample.points);
      exact += edges == c.truth;
      EXPECT_EQ(edges, c.truth) << c;  // measured epsilon < 1/2: the paper's bound
    }
    table << "epsilon " << epsilon << ": exact " << exact << "/" << total << '\n';
  }
  std::cout << table.str();
}

// Sparse but uniform: points in convex position have one simple polygon through them all,
// the convex polygon in angular order, whatever the spacing.
TEST(Connect2d, ConnectsConvexPositionAsItsConvexPolygon) {
  for (const std::size_t n : {3u, 4u, 5u, 8u, 10u, 12u, 100u})
    EXPECT_EQ(connect2d_reconstruction(testing::regular_polygon(n, 1.0, 0.1)), testing::cycle_edges(n)) << n;
  std::mt19937_64 random(5);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 3 + trial % 10;
    std::vector<double> angles;
    for (std::size_t i = 0; i < n; ++i) angles.push_back(std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(random));
    std::sort(angles.begin(), angles.end());
    std::vector<Point> points;  // on an ellipse, in angular order: convex position
    for (const double t : angles) points.emplace_back(3 * std::cos(t), std::sin(t));
    EXPECT_EQ(connect2d_reconstruction(points), testing::cycle_edges(n)) << "trial " << trial;
  }
}

// The survey's sharp-corner family (as gathan_test.cpp builds it): a unit circle opening to
// two tangents meeting at the given angle, sampled uniformly by arc length from the apex.
TEST(Connect2d, SharpCornerFamily) {
  std::ostringstream table;
  int exact = 0, total = 0;
  for (int angle = 10; angle <= 90; angle += 5) {
    std::string row;
    for (const int per_circle : {10, 16, 20}) {
      const geometry::Curve curve = geometry::sharp_corner_curve(angle);
      const geometry::Local_feature_size lfs(curve);
      const auto n = static_cast<std::size_t>(std::ceil(curve.components.front().length() / (2 * std::numbers::pi / per_circle)));
      const geometry::Sample sample = geometry::uniform_sampling(lfs, n);
      const Edges edges = connect2d_reconstruction(sample.points);
      const bool ok = edges == testing::canonical(sample.edges);
      EXPECT_EQ(simple_polygon_size(sample.points, edges), sample.points.size()) << angle << ", " << per_circle;
      exact += ok, ++total;
      row += ok ? 'y' : '.';
    }
    table << angle << " " << row << '\n';
  }
  std::cout << "sharp corners (10, 16, 20 per circle):\n" << table.str() << "exact " << exact << "/" << total << '\n';
  EXPECT_GE(3 * exact, 2 * total);  // the survey: 65.95% of its sharp-corner set, second best
}

TEST(Connect2d, TinyAndDegenerateInput) {
  EXPECT_TRUE(connect2d_reconstruction({}).empty());
  const std::vector<Point> one{{1, 2}}, two{{0, 0}, {1e-300, 0}}, line{{0, 0}, {2, 0}, {1, 0}, {3, 0}};
  EXPECT_TRUE(connect2d_reconstruction(one).empty());
  EXPECT_EQ(connect2d_reconstruction(two), (Edges{{0, 1}}));
  EXPECT_EQ(connect2d_reconstruction(line), (Edges{{0, 2}, {1, 2}, {1, 3}}));
  EXPECT_EQ(connect2d_reconstruction(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}), (Edges{{0, 1}, {0, 2}, {1, 2}}));
  // Cocircular: a square with its centre-free grid of ties, and its scaled copies.
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(connect2d_reconstruction(square), testing::cycle_edges(4));
  const std::vector<Point> unit{{1, 0}, {0.5, 0.9}, {-0.5, 0.8}, {-1, 0.1}, {-0.4, -0.9}, {0.6, -0.8}, {0.1, 0.05}};
  for (const int exponent : {1000, -1000})
    EXPECT_EQ(connect2d_reconstruction(scaled_by(unit, exponent)), connect2d_reconstruction(unit)) << exponent;
  std::vector<Point> huge;
  for (const Point& p : unit) huge.emplace_back(p.x() * 1e300, p.y() * 1e300);
  EXPECT_EQ(simple_polygon_size(huge, connect2d_reconstruction(huge)), unit.size());
  const std::vector<Point> duplicates{{0, 0}, {1, 0}, {0, 0}, {0, 1}};
  EXPECT_EQ(reconstruct(connect2d_algorithm(), duplicates).edges, (Edges{{0, 1}, {0, 3}, {1, 3}}));
  EXPECT_THROW(connect2d_reconstruction(std::vector<Point>{{0, 0}, {0, 0}}), std::invalid_argument);
  EXPECT_THROW(connect2d_reconstruction(std::vector<Point>{{0, 0}, {NAN, 0}}), std::invalid_argument);
}

TEST(Connect2d, RegistryRowIsTheSurveys) {
  const Algorithm connect2d = connect2d_algorithm();
  EXPECT_EQ(connect2d.name, "connect2d");
  EXPECT_EQ(connect2d.title, "Connect2D");
  EXPECT_TRUE(connect2d.parameters.empty());
  const Capabilities& c = connect2d.capabilities;
  EXPECT_EQ(std::make_tuple(c.non_uniform, c.noise, c.outliers, c.manifold, c.open, c.multiple, c.sharp),
            std::make_tuple(Support::yes, Support::yes, Support::no, Support::yes, Support::no, Support::no, Support::yes));
  EXPECT_TRUE(c.guarantee);
  EXPECT_EQ(connect2d.condition.epsilon_below, 0.5);
}

}  // namespace
}  // namespace curvebench::algorithms
