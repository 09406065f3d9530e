// graphs/nearest_neighbor_stream.h against a brute force: every other point, sorted by
// exact squared distance (rationals) and then by index, on random points, grids full of
// ties, collinear points, and coordinates at 2^-1000 and 2^1000; and one stream restarted
// from centre to centre.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <CGAL/Gmpq.h>

#include "graphs/nearest_neighbor_stream.h"

namespace curvebench::graphs {
namespace {

std::vector<Vertex> brute_force_order(const std::vector<Point>& points, Vertex center) {
  const auto squared = [&](Vertex v) {
    const CGAL::Gmpq dx = CGAL::Gmpq(points[v].x()) - CGAL::Gmpq(points[center].x());
    const CGAL::Gmpq dy = CGAL::Gmpq(points[v].y()) - CGAL::Gmpq(points[center].y());
    return dx * dx + dy * dy;
  };
  std::vector<Vertex> order;
  for (Vertex v = 0; v < points.size(); ++v)
    if (v != center) order.push_back(v);
  std::sort(order.begin(), order.end(), [&](Vertex a, Vertex b) {
    const CGAL::Gmpq da = squared(a), db = squared(b);
    return da != db ? da < db : a < b;
  });
  return order;
}

std::vector<Vertex> streamed(const Delaunay_triangulation& dt, Vertex center) {
  Nearest_neighbor_stream stream(dt, center);
  std::vector<Vertex> order;
  for (Vertex v = stream.next(); v != no_vertex; v = stream.next()) order.push_back(v);
  EXPECT_EQ(stream.next(), no_vertex) << "an exhausted stream stays exhausted";
  return order;
}

std::vector<Point> distinct(std::vector<Point> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

RC_GTEST_PROP(NearestNeighborStream, GivesEveryPointInExactDistanceThenIndexOrder, ()) {
  const int grid = *rc::gen::inRange(2, 9);  // small grids: many equal distances
  const int n = *rc::gen::inRange(2, 40);
  const double scale = *rc::gen::element(1.0, 0x1p-1000, 0x1p+1000, 0.1);
  std::vector<Point> points;
  for (int i = 0; i < n; ++i)
    points.emplace_back(*rc::gen::inRange(0, grid) * scale, *rc::gen::inRange(0, grid) * scale);
  points = distinct(points);
  std::shuffle(points.begin(), points.end(), std::default_random_engine(*rc::gen::arbitrary<unsigned>()));
  const Delaunay_triangulation dt(points);
  for (Vertex c = 0; c < points.size(); ++c) RC_ASSERT(streamed(dt, c) == brute_force_order(points, c));
  // One stream restarted at each centre in turn, cut short at a random depth (as Lenz's
  // probes use it): what was left of the last centre must not leak into the next.
  Nearest_neighbor_stream stream(dt, 0);
  for (Vertex c = 0; c < points.size(); ++c) {
    stream.restart(c);
    const std::vector<Vertex> expected = brute_force_order(points, c);
    const std::size_t depth = *rc::gen::inRange<std::size_t>(0, expected.size() + 2);
    for (std::size_t k = 0; k < depth; ++k) RC_ASSERT(stream.next() == (k < expected.size() ? expected[k] : no_vertex));
  }
}

TEST(NearestNeighborStream, CollinearAndTinyInput) {
  std::vector<Point> line;
  for (int i = 0; i < 12; ++i) line.emplace_back((i * 5) % 12, 0);
  const Delaunay_triangulation dt(line);
  for (Vertex c = 0; c < line.size(); ++c) EXPECT_EQ(streamed(dt, c), brute_force_order(line, c)) << c;
  const std::vector<Point> one{{3, 4}};
  EXPECT_TRUE(streamed(Delaunay_triangulation(one), 0).empty());
  const std::vector<Point> random{{0.3, 0.1}, {-2, 5}, {1e-3, 7}, {4, -4}, {0.31, 0.1}, {9, 9}, {-3, -3}};
  const Delaunay_triangulation rdt(random);
  for (Vertex c = 0; c < random.size(); ++c) EXPECT_EQ(streamed(rdt, c), brute_force_order(random, c)) << c;
}

}  // namespace
}  // namespace curvebench::graphs
