// Crawl (algorithms/crawl.h) against a brute force of its definition on small point sets
// in general position: the empty-circle Delaunay edges, every distance an exact rational
// (CGAL::Exact_rational), every "nearest unvisited" a fresh scan. Plus the cases its
// paper claims (dense smooth closed curves, several of them, open curves), the small
// polygons where the authors' "four growth steps" rule decides, and degenerate input.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>

#include <CGAL/Exact_rational.h>

#include "algorithms/crawl.h"
#include "algorithms/registry.h"
#include "graphs/delaunay_graph.h"
#include "tests/support/brute_force_graphs.h"
#include "tests/support/edge_sets.h"
#include "tests/support/point_generators.h"
#include "tests/support/reconstruction_laws.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

using Edges = std::vector<Edge>;
using Rational = CGAL::Exact_rational;
using testing::exact_squared_distance;
using testing::degrees;


// The definition, in the plainest data structures.
Edges brute_crawl(const std::vector<Point>& points, const Edges& delaunay, Crawl_closing closing) {
  const std::size_t n = points.size();
  std::vector<std::vector<std::size_t>> adjacent(n);
  for (const auto& [i, j] : delaunay) {
    adjacent[i].push_back(j);
    adjacent[j].push_back(i);
  }
  const auto key = [&](std::size_t from, std::size_t to) { return std::make_tuple(exact_squared_distance(points[from], points[to]), to); };
  for (std::size_t v = 0; v < n; ++v)
    std::sort(adjacent[v].begin(), adjacent[v].end(), [&](std::size_t a, std::size_t b) { return key(v, a) < key(v, b); });
  const auto rank_of = [&](std::size_t v, std::size_t w) {  // 0 for the nearest, ...
    return std::size_t(std::find(adjacent[v].begin(), adjacent[v].end(), w) - adjacent[v].begin());
  };
  const auto closes = [&](std::size_t a, std::size_t b) {
    if (closing == Crawl_closing::authors) return rank_of(a, b) == 1 || rank_of(b, a) == 1;
    return rank_of(a, b) < 2 && rank_of(b, a) < 2;
  };

  Edges seeds;
  for (const auto& [i, j] : delaunay)
    if (adjacent[i].front() == j || adjacent[j].front() == i) seeds.emplace_back(i, j);
  std::sort(seeds.begin(), seeds.end(), [&](const Edge& a, const Edge& b) {
    return std::make_tuple(exact_squared_distance(points[a.first], points[a.second]), a) <
           std::make_tuple(exact_squared_distance(points[b.first], points[b.second]), b);
  });

  Edges edges;
  std::vector<bool> visited(n, false);
  const auto nearest_unvisited = [&](std::size_t v) -> std::optional<std::size_t> {
    for (const std::size_t w : adjacent[v])
      if (!visited[w]) return w;
    return std::nullopt;
  };
  for (auto [a, b] : seeds) {
    if (visited[a] || visited[b]) continue;
    visited[a] = visited[b] = true;
    edges.emplace_back(a, b);
    for (int grown = 0;; ++grown) {
      if (grown >= 4 && closes(a, b)) {
        edges.emplace_back(a, b);
        break;
      }
      const auto next_a = nearest_unvisited(a), next_b = nearest_unvisited(b);
      if (!next_a && !next_b) break;
      const bool grow_a =
          !next_b || (next_a && exact_squared_distance(points[a], points[*next_a]) < exact_squared_distance(points[b], points[*next_b]));
      std::size_t& end = grow_a ? a : b;
      const std::size_t next = grow_a ? *next_a : *next_b;
      visited[next] = true;
      edges.emplace_back(end, next);
      end = next;
    }
  }
  return testing::canonical(edges);
}

// Where the Delaunay triangulation is unique (no four cocircular points that matter), the
// brute force's empty-circle edges are the triangulation.
RC_GTEST_PROP(Crawl, EqualsBruteForceInGeneralPosition, ()) {
  const auto points = *testing::uniform_points(24);
  const Edges strong = testing::strong_delaunay_edges(points);
  RC_PRE(strong == testing::weak_delaunay_edges(points));
  const auto closing = *rc::gen::element(Crawl_closing::authors, Crawl_closing::mutual);
  RC_ASSERT(crawl_reconstruction(points, closing) == brute_crawl(points, strong, closing));
}

// On every input (grids, collinear runs, extreme scales): paths and cycles of Delaunay
// edges, the same after scaling by a power of two (exact, so every decision is the same).
RC_GTEST_PROP(Crawl, GivesPathsAndCyclesOfDelaunayEdgesOnAnyInput, ()) {
  const auto points = *testing::point_sets(30);
  const auto closing = *rc::gen::element(Crawl_closing::authors, Crawl_closing::mutual);
  testing::rc_assert_delaunay_paths_and_cycles([&](const auto& p) { return crawl_reconstruction(p, closing); }, points);
}

// The paper's claim: dense samplings of smooth closed curves, one or several.
TEST(Crawl, ReconstructsDenseSmoothClosedCurves) {
  int cases = 0;
  for (const int components : {1, 2, 3})
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto c = testing::sampled_fourier_curves(seed * 7919, components, 5, 0.1);
      EXPECT_EQ(crawl_reconstruction(c.sample.points), c.truth) << c;
      ++cases;
    }
  EXPECT_EQ(cases, 30);
}

// An open arc (a sine wave over [0, 6]) is where the two closing rules part. With mutual
// closing it is the arc. With the authors' rule, the path closes across the wave's bay
// as soon as an end becomes the other's second nearest Delaunay neighbour, leaving two
// loops and a path: the authors' program gives these very edges on the same arc moved to
// (1000, 1000) (at the origin, theirs ranks CGAL's unset infinite vertex, at (0, 0), as
// point 0's nearest, and keeps the arc).
TEST(Crawl, ReconstructsAnOpenArcWithMutualClosing) {
  std::vector<Point> points;
  Edges truth;
  for (int i = 0; i <= 200; ++i) {
    const double t = i * 0.03;
    points.emplace_back(t, 0.4 * std::sin(t));
    if (i > 0) truth.emplace_back(i - 1, i);
  }
  EXPECT_EQ(crawl_reconstruction(points, Crawl_closing::mutual), truth);

  Edges authors = truth;
  std::erase(authors, Edge{104, 105});
  std::erase(authors, Edge{114, 115});
  authors.insert(authors.end(), {Edge{0, 104}, Edge{115, 200}});
  EXPECT_EQ(crawl_reconstruction(points, Crawl_closing::authors), geometry::canonical_edges(std::move(authors)));
}

// Regular polygons: every point's two nearest are its sides' ends. Six or more close into
// a cycle; five and fewer stay the path the seed grew, as the authors' rule has it.
TEST(Crawl, ClosesRegularPolygonsOfSixOrMoreSides) {
  for (const std::size_t n : {3u, 4u, 5u, 6u, 7u, 12u, 100u}) {
    const auto polygon = testing::regular_polygon(n, 1.0);
    const Edges edges = crawl_reconstruction(polygon);
    if (n >= 6) {
      EXPECT_EQ(edges, testing::cycle_edges(n)) << n;
    } else {
      EXPECT_EQ(edges.size(), n - 1) << n;
      const auto degree = degrees(edges, n);
      EXPECT_EQ(std::count(degree.begin(), degree.end(), 1u), 2) << n;
    }
  }
}

TEST(Crawl, TinyAndDegenerateInput) {
  EXPECT_TRUE(crawl_reconstruction({}).empty());
  const std::vector<Point> one{{1, 2}}, two{{0, 0}, {1e-300, 0}}, three{{0, 0}, {1, 0}, {2, 0}};
  EXPECT_TRUE(crawl_reconstruction(one).empty());
  EXPECT_EQ(crawl_reconstruction(two), (Edges{{0, 1}}));
  EXPECT_EQ(crawl_reconstruction(three), (Edges{{0, 1}, {1, 2}}));
  // A pentagon-like hexagon at 2^1000 and at 2^-1000: the same edges as at scale 1.
  const std::vector<Point> unit{{1, 0}, {0.5, 0.9}, {-0.5, 0.8}, {-1, 0.1}, {-0.4, -0.9}, {0.6, -0.8}};
  for (const int exponent : {1000, -1000}) {
    std::vector<Point> scaled;
    for (const Point& p : unit) scaled.emplace_back(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent));
    EXPECT_EQ(crawl_reconstruction(scaled), crawl_reconstruction(unit)) << exponent;
  }
  const Algorithm& crawl = *find_algorithm("crawl");
  const std::vector<Point> duplicates{{0, 0}, {1, 0}, {0, 0}, {2, 0}};
  EXPECT_EQ(reconstruct(crawl, duplicates).edges, (Edges{{0, 1}, {1, 3}}));
  EXPECT_THROW(crawl_reconstruction(std::vector<Point>{{0, 0}, {0, 0}}), std::invalid_argument);
}

TEST(Crawl, RegistryRowIsTheSurveys) {
  const Algorithm* crawl = find_algorithm("crawl");
  ASSERT_NE(crawl, nullptr);
  EXPECT_EQ(crawl->capabilities.open, Support::yes);
  EXPECT_EQ(crawl->capabilities.multiple, Support::yes);
  EXPECT_EQ(crawl->capabilities.manifold, Support::no);
  EXPECT_FALSE(crawl->capabilities.guarantee);
  EXPECT_FALSE(crawl->condition.epsilon_below);
}

}  // namespace
}  // namespace curvebench::algorithms
