#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <utility>
#include <vector>

#include "geometry/curves/curve_spec.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/lfs/nearest_point_index.h"
#include "geometry/sampling/seeded_random.h"

namespace curvebench::geometry {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// The definition: sqrt of the smallest CGAL::squared_distance.
double brute_force(const std::vector<Point>& points, const Point& query) {
  double best = infinity;
  for (const Point& p : points)
    if (const double d = CGAL::squared_distance(query, p); d < best) best = d;
  return std::sqrt(best);
}

// What medial points look like: tight clusters (near sharp corners), dense runs along
// lines and arcs, exact duplicates, and a few far-away outliers.
std::vector<Point> medial_like_points(std::uint64_t seed) {
  Seeded_random random(seed);
  std::vector<Point> points;
  for (int cluster = 0; cluster < 6; ++cluster) {
    const double x = random.uniform(-10, 10), y = random.uniform(-10, 10), r = std::pow(10.0, -random.uniform(2, 9));
    for (int i = 0; i < 300; ++i) points.emplace_back(x + r * random.uniform(-1, 1), y + r * random.uniform(-1, 1));
  }
  for (int line = 0; line < 4; ++line) {
    const Point a(random.uniform(-10, 10), random.uniform(-10, 10)), b(random.uniform(-10, 10), random.uniform(-10, 10));
    for (int i = 0; i < 500; ++i) points.push_back(a + (b - a) * (i / 499.0));
  }
  for (int i = 0; i < 200; ++i) points.push_back(points[static_cast<std::size_t>(random.uniform() * 100)]);
  points.emplace_back(1e12, -3e11);
  points.emplace_back(-2e15, 5e14);
  points.emplace_back(7, 1e300);
  return points;
}

TEST(NearestPointIndex, IsInfiniteForNoPoints) {
  EXPECT_EQ(Nearest_point_index({}).distance(Point(1, 2)), infinity);
}

TEST(NearestPointIndex, OfOnePointIsTheDistanceToIt) {
  const std::vector<Point> one{{3, 4}};
  EXPECT_EQ(Nearest_point_index(one).distance(Point(0, 0)), 5);
}

TEST(NearestPointIndex, SkipsPointsWithANanCoordinate) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Point> points{{nan, 0}, {0, 0}, {1, nan}};
  EXPECT_EQ(Nearest_point_index(points).distance(Point(0, 2)), 2);
  EXPECT_EQ(Nearest_point_index(std::vector<Point>{{nan, nan}}).distance(Point(0, 0)), infinity);
}

TEST(NearestPointIndex, MatchesTheBruteForceMinimumExactly) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const std::vector<Point> points = medial_like_points(seed);
    const Nearest_point_index index(points);
    Seeded_random random(seed + 100);
    // Random queries, then queries near the points (where ties and near-ties are), then
    // a walk of small steps (where the guess from the last query is good).
    for (int i = 0; i < 2000; ++i) {
      const Point q(random.uniform(-12, 12), random.uniform(-12, 12));
      ASSERT_EQ(index.distance(q), brute_force(points, q)) << q;
    }
    for (int i = 0; i < 2000; ++i) {
      const Point& p = points[static_cast<std::size_t>(random.uniform() * static_cast<double>(points.size()))];
      const double r = std::pow(10.0, -random.uniform(0, 12));
      const Point q(p.x() + r * random.uniform(-1, 1), p.y() + r * random.uniform(-1, 1));
      ASSERT_EQ(index.distance(q), brute_force(points, q)) << q;
    }
    Point q(-11, -11);
    for (int i = 0; i < 2000; ++i) {
      q = q + Vector(0.011, 0.0097);
      ASSERT_EQ(index.distance(q), brute_force(points, q)) << q;
    }
  }
}

TEST(NearestPointIndex, StaysExactWhenQueriesAlternateBetweenManyIndexes) {
  std::vector<std::vector<Point>> sets;
  std::vector<Nearest_point_index> indexes;
  for (std::uint64_t seed = 1; seed <= 7; ++seed) sets.push_back(medial_like_points(seed));
  for (const auto& set : sets) indexes.emplace_back(set);
  Nearest_point_index moved = std::move(indexes.back());
  indexes.back() = std::move(moved);
  Seeded_random random(9);
  for (int i = 0; i < 3000; ++i) {
    const std::size_t k = static_cast<std::size_t>(random.uniform() * static_cast<double>(sets.size()));
    const Point q(random.uniform(-12, 12), random.uniform(-12, 12));
    ASSERT_EQ(indexes[k].distance(q), brute_force(sets[k], q)) << k << " " << q;
  }
}

// Local_feature_size::at(component, s) keeps its values at the grid points: they must be
// the values it computes without (a fresh estimate of the same curve, queried in another
// order), from any number of threads at once.
TEST(LocalFeatureSize, GridValuesAreTheSameFromEveryThreadAndInAnyOrder) {
  const Curve curve = make_curve("glyph:g");
  const Local_feature_size shared(curve), fresh(curve);
  std::vector<std::pair<std::size_t, double>> queries;
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const double n = static_cast<double>(curve.components[c].piece_count());
    for (const int subdivisions : {8, 4, 1})
      for (const double s : shared.grid(c, 0.3, n - 0.2, subdivisions)) queries.emplace_back(c, s);
    for (const double s : shared.grid(c, n - 0.5, n + 0.7, 8)) queries.emplace_back(c, s);  // round the end
  }
  std::vector<std::uint64_t> expected;
  for (auto it = queries.rbegin(); it != queries.rend(); ++it)
    expected.push_back(std::bit_cast<std::uint64_t>(fresh.at(it->first, it->second)));
  std::reverse(expected.begin(), expected.end());

  constexpr int threads = 4;
  std::vector<std::vector<std::uint64_t>> found(threads);
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t)
    workers.emplace_back([&, t] {
      for (int round = 0; round < 2; ++round)  // the second round reads what the first stored
        for (std::size_t i = 0; i < queries.size(); ++i) {
          const std::size_t k = (i * 7919 + static_cast<std::size_t>(t) * 104729) % queries.size();
          const double value = shared.at(queries[k].first, queries[k].second);
          if (round == 1) found[t].push_back(std::bit_cast<std::uint64_t>(value) ^ expected[k]);
        }
    });
  for (std::thread& worker : workers) worker.join();
  for (int t = 0; t < threads; ++t)
    for (std::size_t i = 0; i < found[t].size(); ++i) ASSERT_EQ(found[t][i], 0u) << "thread " << t << " query " << i;
}

TEST(LocalFeatureSize, AtAParameterIsAtItsPointExceptAtSharpPoints) {
  const Curve curve = make_curve("glyph:A");
  const Local_feature_size lfs(curve);
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const double n = static_cast<double>(curve.components[c].piece_count());
    for (const double s : lfs.grid(c, 0, n, 8)) {
      bool sharp = false;
      for (const Sharp_point& point : lfs.sharp_points())
        sharp |= point.location.component == c &&
                 (std::abs(point.location.parameter - s) <= 1e-12 * n || std::abs(std::abs(point.location.parameter - s) - n) <= 1e-12 * n);
      const double expected = sharp ? 0 : lfs.at(curve.components[c].point(s));
      EXPECT_EQ(lfs.at(c, s), expected) << c << " " << s;
      EXPECT_EQ(lfs.at(c, s), expected) << c << " " << s;  // from the cache
    }
  }
}

}  // namespace
}  // namespace curvebench::geometry
