// Crust (algorithms/crust.h) against two independent oracles of its definition, "the
// edges of the Delaunay triangulation of S ∪ V joining two points of S" (V = the Voronoi
// vertices of S):
//  - CGAL's Delaunay triangulation of S ∪ V with EXACT circumcentres
//    (Exact_predicates_exact_constructions_kernel), on points in general position;
//  - a brute force in rationals (CGAL::Gmpq) on any input, degenerate ones included: V
//    from every triple whose circumcircle has no point inside, and for every pair p, q a
//    scan of all circles through p and q against all of S ∪ V. It computes the strong
//    edges (a circle with every other point strictly outside: the crust's tie rule) and the
//    weak ones (no point strictly inside); both coincide in general position.
// Plus hand cases (regular polygons, cocircular lattice points, an ellipse, tiny and
// collinear input) and regression cases where Gold and Snoeyink's one-step test alone
// would keep an edge that is not in the crust.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>

#include "algorithms/crust.h"
#include "algorithms/registry.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sampling.h"
#include "graphs/gabriel_graph.h"
#include "tests/support/edge_sets.h"
#include "tests/support/point_generators.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;
using Q = CGAL::Gmpq;
using testing::canonical;
using testing::cycle_edges;
using testing::regular_polygon;

// ------------------------------------------------------------ brute force in rationals

struct Q_point {
  Q x, y;
  friend bool operator==(const Q_point&, const Q_point&) = default;
};
Q_point rational(const Point& p) { return {Q(p.x()), Q(p.y())}; }
Q cross(const Q_point& o, const Q_point& a, const Q_point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
Q squared_distance(const Q_point& a, const Q_point& b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}
Q_point circumcentre(const Q_point& a, const Q_point& b, const Q_point& c) {
  const Q d = Q(2) * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
  const Q aa = a.x * a.x + a.y * a.y, bb = b.x * b.x + b.y * b.y, cc = c.x * c.x + c.y * c.y;
  return {(aa * (b.y - c.y) + bb * (c.y - a.y) + cc * (a.y - b.y)) / d,
          (aa * (c.x - b.x) + bb * (a.x - c.x) + cc * (b.x - a.x)) / d};
}

// The Voronoi vertices: centres of circles through three points with no point inside.
std::vector<Q_point> voronoi_vertices(const std::vector<Q_point>& s) {
  std::vector<Q_point> v;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j)
      for (std::size_t k = j + 1; k < s.size(); ++k) {
        if (CGAL::sign(cross(s[i], s[j], s[k])) == CGAL::ZERO) continue;
        const Q_point c = circumcentre(s[i], s[j], s[k]);
        const Q r = squared_distance(c, s[i]);
        bool empty = true;
        for (std::size_t m = 0; m < s.size() && empty; ++m) empty = squared_distance(c, s[m]) >= r;
        if (empty && std::find(v.begin(), v.end(), c) == v.end()) v.push_back(c);
      }
  return v;
}

// Whether some circle through p and q has every point of `others` strictly outside
// (strict) or none strictly inside (weak). Circles through p and q are centred at
// m + t n; y is strictly inside iff |y - m|^2 - |p - m|^2 < 2 t n.(y - m).
bool circle_through(const Q_point& p, const Q_point& q, const std::vector<Q_point>& others, bool strict) {
  const Q_point m{(p.x + q.x) / 2, (p.y + q.y) / 2};
  const Q nx = p.y - q.y, ny = q.x - p.x;
  std::optional<Q> low, high;  // t > low (points right of pq), t < high (points left)
  for (const Q_point& y : others) {
    const Q a = squared_distance(y, m) - squared_distance(p, m);
    const Q b = Q(2) * (nx * (y.x - m.x) + ny * (y.y - m.y));
    if (CGAL::sign(b) == CGAL::ZERO) {
      if (CGAL::sign(a) == CGAL::NEGATIVE) return false;  // strictly inside segment pq
      continue;
    }
    const Q t = a / b;
    if (CGAL::sign(b) == CGAL::POSITIVE) {
      if (!high || t < *high) high = t;
    } else if (!low || t > *low) {
      low = t;
    }
  }
  if (!low || !high) return true;
  return strict ? *low < *high : *low <= *high;
}

struct Brute_force_crust {
  Edges strong, weak;
};

Brute_force_crust brute_force_crust(const std::vector<Point>& points) {
  std::vector<Q_point> s;
  for (const Point& p : points) s.push_back(rational(p));
  std::vector<Q_point> all = s;
  for (const Q_point& v : voronoi_vertices(s)) all.push_back(v);
  Brute_force_crust result;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      std::vector<Q_point> others;
      for (std::size_t k = 0; k < all.size(); ++k)
        if (k != i && k != j) others.push_back(all[k]);
      if (circle_through(s[i], s[j], others, true)) result.strong.emplace_back(i, j);
      if (circle_through(s[i], s[j], others, false)) result.weak.emplace_back(i, j);
    }
  return result;
}

// ------------------------------------------- CGAL's triangulation of S ∪ V, exactly

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;

Edges exact_delaunay_crust(const std::vector<Point>& points) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<long, Exact>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Dt = CGAL::Delaunay_triangulation_2<Exact, Tds>;
  Dt sample;
  for (std::size_t i = 0; i < points.size(); ++i)
    sample.insert(Exact::Point_2(points[i].x(), points[i].y()))->info() = static_cast<long>(i);
  Dt with_voronoi = sample;
  if (sample.dimension() == 2)
    for (const auto face : sample.finite_face_handles())
      with_voronoi.insert(CGAL::circumcenter(face->vertex(0)->point(), face->vertex(1)->point(),
                                             face->vertex(2)->point()))
          ->info() = -1;
  Edges edges;
  for (const auto& edge : with_voronoi.finite_edges()) {
    const long a = edge.first->vertex(Dt::cw(edge.second))->info();
    const long b = edge.first->vertex(Dt::ccw(edge.second))->info();
    if (a >= 0 && b >= 0) edges.emplace_back(a, b);
  }
  return canonical(edges);
}

// ---------------------------------------------------------------------------- helpers

// ------------------------------------------------------------------------- hand cases

TEST(Crust, TinyInputs) {
  EXPECT_TRUE(crust_reconstruction({}).empty());
  const std::vector<Point> one{{1, 2}};
  EXPECT_TRUE(crust_reconstruction(one).empty());
  const std::vector<Point> two{{1, 2}, {3, 4}};
  EXPECT_EQ(crust_reconstruction(two), (Edges{{0, 1}}));
  const std::vector<Point> acute{{0, 0}, {4, 0}, {1, 3}};
  EXPECT_EQ(crust_reconstruction(acute), cycle_edges(3));
  // An obtuse triangle: its circumcentre lies beyond the long side, which is dropped.
  const std::vector<Point> obtuse{{0, 0}, {4, 0}, {2, 1}};
  EXPECT_EQ(crust_reconstruction(obtuse), (Edges{{0, 2}, {1, 2}}));
  // A right triangle: the circumcentre is the hypotenuse's midpoint.
  const std::vector<Point> right{{0, 0}, {4, 0}, {0, 3}};
  EXPECT_EQ(crust_reconstruction(right), (Edges{{0, 1}, {0, 2}}));
}

TEST(Crust, CollinearPointsGiveTheChain) {
  const std::vector<Point> points{{3, 3}, {0, 0}, {5, 5}, {1, 1}, {-2, -2}};
  EXPECT_EQ(crust_reconstruction(points), (Edges{{0, 2}, {0, 3}, {1, 3}, {1, 4}}));
}

TEST(Crust, RegularPolygonsGiveTheirCycle) {
  for (std::size_t k = 3; k <= 40; ++k) {
    EXPECT_EQ(crust_reconstruction(regular_polygon(k, 1, 0)), cycle_edges(k)) << k;
    EXPECT_EQ(crust_reconstruction(regular_polygon(k, 1e-200, 0.3)), cycle_edges(k)) << k;
    EXPECT_EQ(crust_reconstruction(regular_polygon(k, 1e200, 0.7)), cycle_edges(k)) << k;
  }
}

TEST(Crust, CocircularLatticePointsGiveTheirCycle) {
  // The 12 lattice points at distance 5 from the origin, in angular order: every Delaunay
  // triangle has the same circumcentre, the origin.
  const std::vector<Point> points{{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                  {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  EXPECT_EQ(crust_reconstruction(points), cycle_edges(points.size()));
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(crust_reconstruction(square), cycle_edges(4));
}

TEST(Crust, ReconstructsADenseEllipse) {
  std::vector<Point> points;
  const std::size_t n = 400;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * double(i) / double(n);
    points.emplace_back(2 * std::cos(angle), std::sin(angle));
  }
  EXPECT_EQ(crust_reconstruction(points), cycle_edges(n));
}

TEST(Crust, ReconstructsASampledFourierCurve) {
  // A random Fourier curve epsilon-sampled at 0.15, below the proven 0.252.
  geometry::Curve curve = geometry::random_fourier_curve(7, {.harmonics = 4, .amplitude = 0.3});
  const geometry::Local_feature_size lfs(curve);
  const geometry::Sample sample = geometry::safe_epsilon_sampling(lfs, 0.15, geometry::default_minimum_lfs(lfs));
  EXPECT_EQ(crust_reconstruction(sample.points), canonical(sample.edges));
}

// Edges that Gold and Snoeyink's one-step test (steps 1-3 of crust.h) would keep: each is
// killed by a Voronoi vertex other than the two dual to it (found by the brute force).
TEST(Crust, DropsEdgesThatTheOneStepTestAloneWouldKeep) {
  struct Case {
    std::vector<Point> points;
    Edge not_in_crust;
  };
  const std::vector<Case> cases{
      // An interior edge, killed by the circumcentre of a triangle around one end.
      {{{146276, 845060}, {203215, 47014}, {517969, 30080}, {290078, 846519}, {565414, 821682}, {134556, 992964},
        {88928, 661468}, {13489, 630337}, {981001, 906309}, {797087, 557694}, {538775, 772110}},
       {4, 8}},
      {{{285015, 860281}, {294341, 987921}, {84393, 77652}, {168030, 438787}, {294670, 129042}, {896941, 999172},
        {244539, 917380}},
       {2, 3}},
      // A hull edge, killed by a circumcentre far outside the hull (of a triangle two hull
      // edges away).
      {{{204107, 381060}, {233452, 847930}, {377306, 329740}, {639067, 898196}, {292144, 535782}, {7276, 885666},
        {55712, 156875}, {466429, 427331}, {853586, 715608}, {322082, 299227}},
       {6, 9}},
  };
  for (const Case& c : cases) {
    const Edges crust = crust_reconstruction(c.points);
    EXPECT_EQ(crust, brute_force_crust(c.points).strong);
    EXPECT_EQ(crust, exact_delaunay_crust(c.points));
    EXPECT_EQ(std::ranges::count(crust, c.not_in_crust), 0);
    // ... and the dual Voronoi vertices alone would not exclude it.
    const auto gabriel = graphs::edge_list(graphs::gabriel_graph(c.points));
    EXPECT_EQ(std::ranges::count(gabriel, c.not_in_crust), 1);
  }
}

TEST(Crust, IsRegisteredWithItsCondition) {
  const Algorithm* crust = find_algorithm("crust");
  ASSERT_NE(crust, nullptr);
  EXPECT_EQ(crust->title, "Crust");
  ASSERT_TRUE(crust->condition.epsilon_below);
  EXPECT_EQ(*crust->condition.epsilon_below, 0.252);
  EXPECT_TRUE(crust->parameters.empty());
  // Duplicates are merged by the registry; the crust is the same.
  const std::vector<Point> points{{0, 0}, {4, 0}, {1, 3}, {4, 0}};
  EXPECT_EQ(reconstruct(*crust, points).edges, cycle_edges(3));
}

// ------------------------------------------------------------------ properties

// Points of a 2^20 grid in general position (almost surely; the rare degenerate draw,
// where the strong and weak crusts differ, is discarded).
RC_GTEST_PROP(Crust, EqualsTheExactDelaunayTriangulationOfSampleAndVoronoiVertices, ()) {
  const std::vector<Point> points = *testing::uniform_points(14);
  const Brute_force_crust brute = brute_force_crust(points);
  RC_PRE(brute.strong == brute.weak);
  const Edges crust = crust_reconstruction(points);
  RC_ASSERT(crust == exact_delaunay_crust(points));
  RC_ASSERT(crust == brute.strong);
}

// Any input, degenerate ones included (lattices, collinear runs, extreme scales): the
// strong crust, independent of the input order, and inside the Gabriel graph.
RC_GTEST_PROP(Crust, EqualsTheStrongCrustOnAnyInput, ()) {
  const std::vector<Point> points = *testing::point_sets(12);
  const Edges crust = crust_reconstruction(points);
  RC_ASSERT(crust == brute_force_crust(points).strong);

  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(*rc::gen::arbitrary<std::uint32_t>()));
  std::vector<Point> shuffled;
  for (const std::size_t i : order) shuffled.push_back(points[i]);
  Edges mapped;
  for (const auto& [i, j] : crust_reconstruction(shuffled)) mapped.emplace_back(order[i], order[j]);
  RC_ASSERT(canonical(mapped) == crust);

  const Edges gabriel = graphs::edge_list(graphs::gabriel_graph(points));
  RC_ASSERT(std::ranges::includes(gabriel, crust));
}

}  // namespace
}  // namespace curvebench::algorithms
