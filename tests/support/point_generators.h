// RapidCheck generators of small point sets that stress exact geometry: random points,
// integer grids (every cocircular and collinear configuration), collinear runs, and
// each of them scaled towards the ends of the double range or shifted far from the
// origin. Points are distinct (graphs take merged point sets).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <rapidcheck.h>

#include "geometry/kernel.h"

namespace curvebench::testing {

using geometry::Point;

inline std::vector<Point> distinct(std::vector<Point> points) {
  std::vector<Point> kept;
  for (const Point& p : points)  // keep the generated order: builders must not depend on it
    if (std::find(kept.begin(), kept.end(), p) == kept.end()) kept.push_back(p);
  return kept;
}

inline rc::Gen<std::vector<Point>> grid_points(int max_n, int side) {
  return rc::gen::map(rc::gen::container<std::vector<std::pair<int, int>>>(
                          rc::gen::pair(rc::gen::inRange(0, side), rc::gen::inRange(0, side))),
                      [max_n](const std::vector<std::pair<int, int>>& xy) {
                        std::vector<Point> points;
                        for (const auto& [x, y] : xy) points.emplace_back(x, y);
                        points = distinct(points);
                        if (points.size() > std::size_t(max_n)) points.resize(max_n);
                        return points;
                      });
}

inline rc::Gen<std::vector<Point>> uniform_points(int max_n) {
  return rc::gen::map(rc::gen::container<std::vector<std::pair<int, int>>>(
                          rc::gen::pair(rc::gen::inRange(-1 << 20, 1 << 20), rc::gen::inRange(-1 << 20, 1 << 20))),
                      [max_n](const std::vector<std::pair<int, int>>& xy) {
                        std::vector<Point> points;
                        for (const auto& [x, y] : xy) points.emplace_back(std::ldexp(x, -20) / 3, std::ldexp(y, -20) / 7);
                        points = distinct(points);
                        if (points.size() > std::size_t(max_n)) points.resize(max_n);
                        return points;
                      });
}

inline rc::Gen<std::vector<Point>> collinear_points(int max_n) {
  return rc::gen::map(rc::gen::tuple(rc::gen::inRange(-5, 6), rc::gen::inRange(-5, 6), rc::gen::inRange(-3, 4),
                                     rc::gen::inRange(-3, 4), rc::gen::container<std::vector<int>>(rc::gen::inRange(-20, 21))),
                      [max_n](const auto& t) {
                        const auto& [ax, ay, dx, dy, steps] = t;
                        std::vector<Point> points;
                        for (const int s : steps) points.emplace_back(ax + s * (dx == 0 && dy == 0 ? 1 : dx), ay + s * dy);
                        points = distinct(points);
                        if (points.size() > std::size_t(max_n)) points.resize(max_n);
                        return points;
                      });
}

// Scaling by a power of two is exact, so degenerate configurations stay degenerate near
// 1e-300 and 1e+300; scaling by 1e300 or shifting by 1e8 perturbs them slightly instead.
inline rc::Gen<std::vector<Point>> transformed(rc::Gen<std::vector<Point>> base) {
  return rc::gen::map(rc::gen::pair(std::move(base), rc::gen::inRange(0, 6)), [](const auto& pair) {
    auto [points, how] = pair;
    for (Point& p : points) {
      switch (how) {
        case 1: p = Point(std::ldexp(p.x(), -1000), std::ldexp(p.y(), -1000)); break;
        case 2: p = Point(std::ldexp(p.x(), 990), std::ldexp(p.y(), 990)); break;
        case 3: p = Point(p.x() * 1e300, p.y() * 1e300); break;
        case 4: p = Point(p.x() + 1e8, p.y() - 1e8); break;
        default: break;
      }
    }
    return distinct(points);
  });
}

// A point set of at most max_n points from any of the families above.
inline rc::Gen<std::vector<Point>> point_sets(int max_n) {
  return transformed(rc::gen::weightedOneOf<std::vector<Point>>({{3, grid_points(max_n, 5)},
                                                                  {3, uniform_points(max_n)},
                                                                  {1, collinear_points(max_n)},
                                                                  {1, grid_points(4, 3)}}));
}

// Up to 150 points in flat clusters (aspect 10:1) at scales 2^-6 ... 2^5: nearest points
// that hide behind other points' Delaunay edges.
inline rc::Gen<std::vector<Point>> clustered_points() {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange<std::uint32_t>(0, 1u << 30), rc::gen::inRange(3, 150)),
                      [](const std::pair<std::uint32_t, int>& seed_and_size) {
                        const auto [seed, n] = seed_and_size;
                        std::mt19937 random(seed);
                        std::uniform_real_distribution<double> unit(-1, 1);
                        std::vector<Point> points;
                        for (int c = 0; c < 1 + n / 20; ++c) {
                          const double scale = std::ldexp(1.0, int(random() % 12) - 6);
                          const Point centre(unit(random), unit(random));
                          for (int i = 0; i < 20 && int(points.size()) < n; ++i)
                            points.emplace_back(centre.x() + scale * unit(random),
                                                centre.y() + scale * unit(random) * 0.1);
                        }
                        return distinct(points);
                      });
}

}  // namespace curvebench::testing
