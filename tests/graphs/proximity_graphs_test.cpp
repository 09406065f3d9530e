// Every proximity-graph builder against its brute-force definition, on point sets built
// to be degenerate (grids, collinear runs, extreme exponents), plus the laws that tie
// the graphs together.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

#include "graphs/alpha_shape_boundary.h"
#include "graphs/beta_skeleton.h"
#include "graphs/delaunay_edge_index.h"
#include "graphs/delaunay_graph.h"
#include "graphs/euclidean_minimum_spanning_tree.h"
#include "graphs/gabriel_graph.h"
#include "graphs/k_nearest_neighbor_graph.h"
#include "graphs/proximity_graph.h"
#include "graphs/relative_neighborhood_graph.h"
#include "graphs/sphere_of_influence_delaunay_graph.h"
#include "graphs/sphere_of_influence_graph.h"
#include "tests/support/brute_force_graphs.h"
#include "tests/support/point_generators.h"

namespace curvebench {
namespace {

using namespace graphs;
using testing::point_sets;
using Edges = std::vector<Edge>;

Edges edges_of(const Graph& g) { return edge_list(g); }

bool subset(const Edges& a, const Edges& b) { return std::includes(b.begin(), b.end(), a.begin(), a.end()); }

const auto beta_values = rc::gen::element(0.0, 0.3, 0.5, 0.9, 1.0, 1.2, 1.5, 2.0, 2.5, 7.0);

RC_GTEST_PROP(DelaunayGraph, IsATriangulationWhoseEdgesAdmitEmptyCircles, ()) {
  const auto points = *point_sets(14);
  const Edges dt = edges_of(delaunay_graph(points));
  RC_ASSERT(subset(testing::strong_delaunay_edges(points), dt));
  RC_ASSERT(subset(dt, testing::weak_delaunay_edges(points)));
  RC_ASSERT(!testing::has_crossing_or_overlap(points, dt));
  // A triangulation of n points, h of them on the hull boundary, has 3n - 3 - h edges;
  // a chain of n - 1 if all are collinear.
  const std::size_t n = points.size();
  const bool collinear = std::all_of(points.begin(), points.end(), [&](const Point& p) {
    return n < 3 || CGAL::collinear(points[0], points[1], p);
  });
  const std::size_t expected = n < 2 ? 0 : collinear ? n - 1 : 3 * n - 3 - testing::hull_boundary_size(points);
  RC_ASSERT(dt.size() == expected);
}

RC_GTEST_PROP(DelaunayTriangulation, ApexesNeighborsAndNearestNeighborsAreConsistent, ()) {
  const auto points = *point_sets(20);
  const Delaunay_triangulation dt(points);
  std::vector<std::vector<Vertex>> adjacent(points.size());
  for (const Delaunay_edge& e : dt.edges()) {
    RC_ASSERT(e.source < e.target);
    const Point &p = points[e.source], &q = points[e.target];
    if (e.left != no_vertex) RC_ASSERT(CGAL::orientation(p, q, points[e.left]) == CGAL::LEFT_TURN);
    if (e.right != no_vertex) RC_ASSERT(CGAL::orientation(p, q, points[e.right]) == CGAL::RIGHT_TURN);
    adjacent[e.source].push_back(e.target);
    adjacent[e.target].push_back(e.source);
  }
  for (Vertex v = 0; v < points.size(); ++v) {
    std::vector<Vertex> listed(dt.neighbors(v).begin(), dt.neighbors(v).end());
    std::sort(listed.begin(), listed.end());
    std::sort(adjacent[v].begin(), adjacent[v].end());
    RC_ASSERT(listed == adjacent[v]);
    // Brute force with CGAL's own exact distance comparison; ties to the smaller index.
    Vertex nearest = no_vertex;
    for (Vertex w = 0; w < points.size(); ++w)
      if (w != v && (nearest == no_vertex ||
                     CGAL::compare_distance_to_point(points[v], points[w], points[nearest]) == CGAL::SMALLER))
        nearest = w;
    RC_ASSERT(dt.nearest_neighbor(v) == nearest);
  }
}

RC_GTEST_PROP(DelaunayTriangulation, KeptTrianglesAreItsEmptyCircleFacesWithTheirSidesAndNeighbors, ()) {
  const auto points = *point_sets(20);
  const Delaunay_triangulation dt(points, Keep_triangles::yes);
  const auto triangles = dt.triangles();
  const auto edges = dt.edges();
  RC_ASSERT(Delaunay_triangulation(points).triangles().empty());  // only when asked for
  // Euler: a triangulation of n points, h on the hull boundary, has 2n - 2 - h triangles.
  const std::size_t n = points.size();
  const bool flat = std::none_of(edges.begin(), edges.end(),
                                 [](const Delaunay_edge& e) { return e.left != no_vertex || e.right != no_vertex; });
  RC_ASSERT(triangles.size() == (flat ? 0 : 2 * n - 2 - testing::hull_boundary_size(points)));
  std::vector<int> sides_of_edge(edges.size(), 0);
  for (Triangle_id t = 0; t < triangles.size(); ++t) {
    const auto& [corners, sides, across] = triangles[t];
    RC_ASSERT(CGAL::orientation(points[corners[0]], points[corners[1]], points[corners[2]]) == CGAL::LEFT_TURN);
    for (const Point& p : points)  // empty circle, brute force
      RC_ASSERT(CGAL::side_of_oriented_circle(points[corners[0]], points[corners[1]], points[corners[2]], p) !=
                CGAL::ON_POSITIVE_SIDE);
    for (int i = 0; i < 3; ++i) {
      // Side i joins the other two corners and has corner i as its apex on this side.
      const Delaunay_edge& e = edges[sides[i]];
      const Vertex from = corners[(i + 1) % 3], to = corners[(i + 2) % 3];
      RC_ASSERT(std::minmax(from, to) == std::minmax(e.source, e.target));
      RC_ASSERT((e.source == from ? e.left : e.right) == corners[i]);
      ++sides_of_edge[sides[i]];
      // Across it: the triangle on its other side, which has it too and leads back here.
      const Vertex other_apex = e.source == from ? e.right : e.left;
      if (other_apex == no_vertex) {
        RC_ASSERT(across[i] == no_triangle);
        continue;
      }
      RC_ASSERT(across[i] < triangles.size());
      const Delaunay_triangle& u = triangles[across[i]];
      const auto back = std::find(u.sides.begin(), u.sides.end(), sides[i]) - u.sides.begin();
      RC_ASSERT(back < 3);
      RC_ASSERT(u.corners[back] == other_apex);
      RC_ASSERT(u.across[back] == t);
    }
  }
  for (Edge_id id = 0; id < edges.size(); ++id)
    RC_ASSERT(sides_of_edge[id] == (edges[id].left != no_vertex) + (edges[id].right != no_vertex));
}

// Whether every edge's id comes back from its two ends, given either way round.
bool finds_every_edge(const Delaunay_triangulation& dt) {
  const Delaunay_edge_index index(dt);
  for (Delaunay_edge_index::Edge_id id = 0; id < dt.edges().size(); ++id) {
    const Delaunay_edge& e = dt.edges()[id];
    if (index.find(e.source, e.target) != id || index.find(e.target, e.source) != id) return false;
  }
  return true;
}

RC_GTEST_PROP(DelaunayEdgeIndex, FindsEveryEdgeFromEitherEnd, ()) {
  RC_ASSERT(finds_every_edge(Delaunay_triangulation(*point_sets(20))));
}

TEST(DelaunayEdgeIndex, FindsTheEdgesOfAWheelsHub) {
  // The hub, point 0, is the smaller end of 200 edges: one long group to search.
  std::vector<Point> wheel{{0, 0}};
  for (int i = 0; i < 200; ++i) wheel.emplace_back(std::cos(i * 0.0314), std::sin(i * 0.0314));
  const Delaunay_triangulation dt(wheel);
  ASSERT_EQ(dt.neighbors(0).size(), 200u);
  EXPECT_TRUE(finds_every_edge(dt));
}

RC_GTEST_PROP(DelaunayGraph, DoesNotDependOnInputOrder, ()) {
  const auto points = *point_sets(20);
  auto order = *rc::gen::container<std::vector<int>>(points.size(), rc::gen::arbitrary<int>());
  std::vector<std::size_t> permutation(points.size());
  std::iota(permutation.begin(), permutation.end(), 0);
  std::sort(permutation.begin(), permutation.end(), [&](auto a, auto b) { return std::tie(order[a], a) < std::tie(order[b], b); });
  std::vector<Point> shuffled;
  for (auto i : permutation) shuffled.push_back(points[i]);
  Edges mapped;
  for (const auto& [i, j] : edges_of(delaunay_graph(shuffled)))
    mapped.emplace_back(std::min(permutation[i], permutation[j]), std::max(permutation[i], permutation[j]));
  std::sort(mapped.begin(), mapped.end());
  RC_ASSERT(mapped == edges_of(delaunay_graph(points)));
}

RC_GTEST_PROP(EuclideanMinimumSpanningTree, EqualsPrimsTreeUnderTheSameExactOrder, ()) {
  const auto points = *point_sets(16);
  const Edges tree = edges_of(euclidean_minimum_spanning_tree(points));
  const Edges expected = testing::brute_force_minimum_spanning_tree(points);
  RC_ASSERT(tree == expected);
  RC_ASSERT(tree.size() == (points.empty() ? 0 : points.size() - 1));
  const double w = testing::total_length(points, tree), w_expected = testing::total_length(points, expected);
  RC_ASSERT(std::abs(w - w_expected) <= 1e-12 * std::abs(w_expected) || !std::isfinite(w_expected));
}

RC_GTEST_PROP(GabrielGraph, EqualsBruteForce, ()) {
  const auto points = *point_sets(16);
  RC_ASSERT(edges_of(gabriel_graph(points)) == testing::brute_force_gabriel_graph(points));
}

// build_graph takes any point list: each duplicate is merged into its first occurrence,
// which alone gets edges, on the input's indices. The oracle: the brute-force graph of the
// distinct points, renumbered by hand to their first occurrences.
RC_GTEST_PROP(BuildGraph, MergesDuplicatesIntoTheirFirstOccurrence, ()) {
  const auto distinct_points = *point_sets(12);
  // Each input point is one of the distinct ones, every distinct one at least once, in an
  // order drawn by sorting on random keys.
  std::vector<std::size_t> picks(distinct_points.size());
  std::iota(picks.begin(), picks.end(), std::size_t{0});
  if (!distinct_points.empty())
    for (const std::size_t extra : *rc::gen::container<std::vector<std::size_t>>(
             rc::gen::inRange<std::size_t>(0, distinct_points.size())))
      picks.push_back(extra);
  const auto keys = *rc::gen::container<std::vector<int>>(picks.size(), rc::gen::inRange(0, 1000));
  std::vector<std::size_t> order(picks.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  std::vector<Point> input;
  std::vector<std::size_t> first(distinct_points.size(), std::numeric_limits<std::size_t>::max());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t k = picks[order[i]];
    input.push_back(distinct_points[k]);
    first[k] = std::min(first[k], i);
  }
  Edges expected;
  for (const auto& [i, j] : testing::brute_force_gabriel_graph(distinct_points))
    expected.emplace_back(std::min(first[i], first[j]), std::max(first[i], first[j]));
  std::sort(expected.begin(), expected.end());
  RC_ASSERT(build_graph(*find_proximity_graph("gabriel"), input) == expected);
}

RC_GTEST_PROP(RelativeNeighborhoodGraph, EqualsBruteForce, ()) {
  const auto points = *point_sets(16);
  RC_ASSERT(edges_of(relative_neighborhood_graph(points)) == testing::brute_force_relative_neighborhood_graph(points));
}

RC_GTEST_PROP(BetaSkeleton, EqualsBruteForceForBothRegions, ()) {
  const auto points = *point_sets(12);
  const double beta = *beta_values;
  const Beta_region region = *rc::gen::element(Beta_region::lune, Beta_region::circle);
  RC_TAG(beta, region == Beta_region::lune ? "lune" : "circle");
  RC_ASSERT(edges_of(beta_skeleton(points, beta, region)) == testing::brute_force_beta_skeleton(points, beta, region));
}

RC_GTEST_PROP(ProximityGraphs, ContainmentChainAndBetaIdentities, ()) {
  const auto points = *point_sets(40);
  const Delaunay_triangulation dt(points);
  const Edges emst = edges_of(euclidean_minimum_spanning_tree(dt)), rng = edges_of(relative_neighborhood_graph(dt)),
              gabriel = edges_of(gabriel_graph(dt)), delaunay = edges_of(delaunay_graph(dt));
  RC_ASSERT(subset(emst, rng));
  RC_ASSERT(subset(rng, gabriel));
  RC_ASSERT(subset(gabriel, delaunay));
  RC_ASSERT(edges_of(beta_skeleton(dt, 1, Beta_region::lune)) == gabriel);
  RC_ASSERT(edges_of(beta_skeleton(dt, 1, Beta_region::circle)) == gabriel);
  RC_ASSERT(edges_of(beta_skeleton(dt, 2, Beta_region::lune)) == rng);
  // A larger beta forbids a larger region; for beta >= 1 the lune lies inside the circles.
  const double smaller = *beta_values, larger = *beta_values;
  if (smaller <= larger)
    for (const auto region : {Beta_region::lune, Beta_region::circle})
      RC_ASSERT(subset(edges_of(beta_skeleton(dt, larger, region)), edges_of(beta_skeleton(dt, smaller, region))));
  if (larger >= 1)
    RC_ASSERT(subset(edges_of(beta_skeleton(dt, larger, Beta_region::circle)),
                     edges_of(beta_skeleton(dt, larger, Beta_region::lune))));
}

RC_GTEST_PROP(SphereOfInfluenceGraph, EqualsBruteForce, ()) {
  const auto points = *point_sets(16);
  RC_ASSERT(edges_of(sphere_of_influence_graph(points)) == testing::brute_force_sphere_of_influence_graph(points));
}

Edges intersection(const Edges& a, const Edges& b) {
  Edges both;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  return both;
}

// SIGDT against the brute-force SIG and the empty-circle definition of Delaunay edges:
// cocircular points leave some edges to the triangulation's choice, so the exact
// statement is strong Delaunay edges within SIG <= SIGDT <= weak Delaunay edges within
// SIG, and SIGDT is the SIG's part of the triangulation actually built.
RC_GTEST_PROP(SphereOfInfluenceDelaunayGraph, IsTheBruteForceSigWithinTheTriangulation, ()) {
  const auto points = *point_sets(16);
  const Delaunay_triangulation dt(points);
  const Edges sigdt = edges_of(sphere_of_influence_delaunay_graph(dt));
  const Edges sig = testing::brute_force_sphere_of_influence_graph(points);
  RC_ASSERT(sigdt == intersection(sig, edges_of(delaunay_graph(dt))));
  RC_ASSERT(subset(intersection(sig, testing::strong_delaunay_edges(points)), sigdt));
  RC_ASSERT(subset(sigdt, intersection(sig, testing::weak_delaunay_edges(points))));
}

// Two tight pairs far apart on a line: the triangulation is the chain, and SIG keeps
// each pair's edge (0.1 <= 0.2) but not the gap between them (2.9 > 0.1 + 0.1).
TEST(SphereOfInfluenceDelaunayGraph, DropsTheGapBetweenTwoPairs) {
  const std::vector<Point> points{{0, 0}, {0.1, 0}, {3, 0}, {3.1, 0}};
  EXPECT_EQ(edges_of(delaunay_graph(points)), (Edges{{0, 1}, {1, 2}, {2, 3}}));
  EXPECT_EQ(edges_of(sphere_of_influence_delaunay_graph(points)), (Edges{{0, 1}, {2, 3}}));
}

RC_GTEST_PROP(KNearestNeighborGraph, EqualsBruteForce, ()) {
  const auto points = *point_sets(16);
  const auto k = *rc::gen::inRange<std::size_t>(0, 6);
  RC_ASSERT(edges_of(k_nearest_neighbor_graph(points, k)) == testing::brute_force_k_nearest_neighbor_graph(points, k));
}

// The ranked lists themselves, nearest first (what the outlier filter reads), against
// the rational brute force that the graph test above flattens.
RC_GTEST_PROP(KNearestNeighbors, RankAsTheBruteForce, ()) {
  const auto points = *point_sets(16);
  const auto k = *rc::gen::inRange<std::size_t>(0, 8);
  const auto ranked = k_nearest_neighbors(Delaunay_triangulation(points), k);
  const auto expected = testing::brute_force_k_nearest_neighbors(points, k);
  RC_ASSERT(ranked.size() == expected.size());
  for (std::size_t p = 0; p < ranked.size(); ++p)
    RC_ASSERT(std::equal(ranked[p].begin(), ranked[p].end(), expected[p].begin(), expected[p].end()));
}

RC_GTEST_PROP(AlphaShapeBoundary, EqualsBruteForce, ()) {
  const auto points = *point_sets(12);
  // alpha = 0, and squared radii of small grids (0.25, 0.5, 1.25, ...) to hit every tie.
  const double alpha = *rc::gen::element(0.0, 0.25, 0.5, 0.625, 1.0, 1.25, 2.0, 3.0, 1e9);
  RC_TAG(alpha);
  RC_ASSERT(edges_of(alpha_shape_boundary(points, alpha)) == testing::brute_force_alpha_shape_boundary(points, alpha));
}

// The default alpha: a quarter of the longest (exact) EMST edge's rounded squared length,
// four ulps up.
RC_GTEST_PROP(AlphaShapeBoundary, ConnectingAlphaIsTheLongestEmstEdge, ()) {
  const auto points = *point_sets(30);
  const Delaunay_triangulation dt(points);
  const Graph tree = euclidean_minimum_spanning_tree(dt);
  double longest = 0;
  for (const auto e : boost::make_iterator_range(boost::edges(tree)))
    longest = std::max(longest, boost::get(boost::edge_weight, tree, e));
  double expected = longest / 4;
  for (int i = 0; i < 4; ++i) expected = std::nextafter(expected, std::numeric_limits<double>::infinity());
  RC_ASSERT(connecting_alpha(dt) == std::min(expected, std::numeric_limits<double>::max()));
}

TEST(ProximityGraphs, EveryBuilderRejectsDuplicatePoints) {
  const std::vector<Point> points{{0, 0}, {1, 0}, {0, 0}};
  for (const auto& graph : proximity_graphs())
    EXPECT_THROW(graph.build(Delaunay_triangulation(points), {}), std::invalid_argument) << graph.name;
  EXPECT_THROW(alpha_shape_boundary(points, 1), std::invalid_argument);
}

TEST(ProximityGraphs, EveryBuilderHandlesZeroToThreePoints) {
  const std::vector<std::vector<Point>> inputs{{}, {{1, 1}}, {{0, 0}, {1, 0}}, {{0, 0}, {1, 0}, {2, 0}}, {{0, 0}, {1, 0}, {0, 1}}};
  for (const auto& points : inputs)
    for (const auto& graph : proximity_graphs()) {
      const Graph g = graph.build(Delaunay_triangulation(points), {});
      EXPECT_EQ(boost::num_vertices(g), points.size()) << graph.name;
      EXPECT_LE(boost::num_edges(g), points.size() * (points.size() - (points.empty() ? 0 : 1)) / 2) << graph.name;
    }
}

TEST(RelativeNeighborhoodGraph, EquidistantPointsDoNotBlockButCornersOfASquareDo) {
  // |pq| = |pr| = 5: r is on the boundary of pq's lune and q on pr's, so neither blocks.
  const std::vector<Point> isosceles{{0, 0}, {5, 0}, {3, 4}};
  EXPECT_EQ(edges_of(relative_neighborhood_graph(isosceles)), (Edges{{0, 1}, {0, 2}, {1, 2}}));
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(edges_of(relative_neighborhood_graph(square)), (Edges{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
  EXPECT_EQ(edges_of(gabriel_graph(square)), (Edges{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
  EXPECT_EQ(edges_of(delaunay_graph(square)).size(), 5u);
}

TEST(BetaSkeleton, RejectsNegativeOrNonFiniteBeta) {
  const std::vector<Point> points{{0, 0}, {1, 0}};
  EXPECT_THROW(beta_skeleton(points, -1, Beta_region::lune), std::invalid_argument);
  EXPECT_THROW(beta_skeleton(points, std::numeric_limits<double>::quiet_NaN(), Beta_region::lune), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench
