// Small hand-made curves with their ground truths, for the algorithms' own tests: two
// circles of different spacing, a sine arc, a square and a kite with a 70-degree tip (each
// side cut into steps of about the same length), and a figure eight sampled at or between
// its crossing.
#pragma once

#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"
#include "tests/support/edge_sets.h"

namespace curvebench::testing {

struct Hand_made_curve {
  std::string_view name;
  std::vector<geometry::Point> points;
  std::vector<geometry::Edge> truth;  // canonical
};

// A circle of 60 points and radius 1, and one of 25 points and radius 0.5 three units away.
inline Hand_made_curve two_circles() {
  std::vector<geometry::Point> points = regular_polygon(60, 1.0);
  for (const geometry::Point& p : regular_polygon(25, 0.5, 0.1)) points.emplace_back(p.x() + 3, p.y());
  std::vector<geometry::Edge> truth = cycle_edges(60);
  for (const geometry::Edge& e : cycle_edges(25, 60)) truth.push_back(e);
  return {"two circles", std::move(points), canonical(std::move(truth))};
}

// 201 points of 0.4 sin x, uniform in x over [0, 6]: one path.
inline Hand_made_curve sine_arc() {
  std::vector<geometry::Point> points;
  for (int i = 0; i <= 200; ++i) points.emplace_back(i * 0.03, 0.4 * std::sin(i * 0.03));
  return {"sine arc", points, path_edges(points.size())};
}

inline Hand_made_curve sampled_square() {
  auto points = along({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {16, 16, 16, 16});
  return {"square", points, cycle_edges(points.size())};
}

// Tip at (0, 0), opening 70 degrees.
inline Hand_made_curve sampled_kite() {
  const double half = std::tan(35 * std::numbers::pi / 180) * 3;
  auto points = along({{0, 0}, {3, -half}, {4.5, 0}, {3, half}}, {30, 18, 18, 30});
  return {"kite", points, cycle_edges(points.size())};
}

// The lemniscate of Bernoulli (x^2 + y^2)^2 = x^2 - y^2: a figure eight whose branches
// cross at the origin at right angles (t = pi/2 and 3 pi/2), with an inflection there.
inline geometry::Point lemniscate(double t) {
  const double s = std::sin(t), c = std::cos(t), d = 1 + s * s;
  return {c / d, s * c / d};
}

// n samples evenly in t, both branches sampled at the origin: one point there, `crossing`,
// of degree 4 in the truth.
struct Figure_eight : Hand_made_curve {
  std::size_t crossing;
};
inline Figure_eight figure_eight_sampled_at_the_crossing(std::size_t n) {
  std::vector<geometry::Point> points;
  std::vector<std::size_t> index(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 3 * n / 4) {
      index[i] = index[n / 4];
      continue;
    }
    index[i] = points.size();
    points.push_back(i == n / 4 ? geometry::Point(0, 0) : lemniscate(2 * std::numbers::pi * double(i) / double(n)));
  }
  std::vector<geometry::Edge> truth;
  for (std::size_t i = 0; i < n; ++i) truth.emplace_back(index[i], index[(i + 1) % n]);
  return {{"figure eight sampled at the crossing", std::move(points), canonical(std::move(truth))}, index[n / 4]};
}

// Samples at t = 2 pi (i + 1/2) / n: the crossing lies midway between two samples on each
// branch, whose truth edges cross.
inline Hand_made_curve figure_eight_sampled_between(std::size_t n) {
  std::vector<geometry::Point> points;
  for (std::size_t i = 0; i < n; ++i) points.push_back(lemniscate(2 * std::numbers::pi * (double(i) + 0.5) / double(n)));
  return {"figure eight sampled between", std::move(points), cycle_edges(n)};
}

}  // namespace curvebench::testing
