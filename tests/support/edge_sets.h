// Known answers for reconstruction tests: edge sets in the registry's canonical form
// (i < j, sorted, no repeats), the path and cycle through consecutive points, vertex
// degrees, and the regular polygon whose right reconstruction is that cycle.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::testing {

using geometry::canonical_edges;
inline std::vector<geometry::Edge> canonical(std::vector<geometry::Edge> edges) {
  return canonical_edges(std::move(edges));
}

// first -- first + 1 -- ... -- first + n - 1.
inline std::vector<geometry::Edge> path_edges(std::size_t n, std::size_t first = 0) {
  std::vector<geometry::Edge> edges;
  for (std::size_t i = 0; i + 1 < n; ++i) edges.emplace_back(first + i, first + i + 1);
  return edges;
}

// The path closed by its last edge when n > 2, canonical.
inline std::vector<geometry::Edge> cycle_edges(std::size_t n, std::size_t first = 0) {
  std::vector<geometry::Edge> edges = path_edges(n, first);
  if (n > 2) edges.emplace_back(first, first + n - 1);
  return canonical(std::move(edges));
}

// How many edges meet at each of the points 0 .. n - 1.
inline std::vector<std::size_t> degrees(const std::vector<geometry::Edge>& edges, std::size_t n) {
  std::vector<std::size_t> degree(n, 0);
  for (const auto& [i, j] : edges) ++degree[i], ++degree[j];
  return degree;
}

// k points evenly on a circle, counter-clockwise from angle `phase`.
inline std::vector<geometry::Point> regular_polygon(std::size_t k, double radius, double phase = 0,
                                                    geometry::Point centre = {0, 0}) {
  std::vector<geometry::Point> points;
  for (std::size_t i = 0; i < k; ++i) {
    const double t = phase + 2 * std::numbers::pi * double(i) / double(k);
    points.emplace_back(centre.x() + radius * std::cos(t), centre.y() + radius * std::sin(t));
  }
  return points;
}

// Points along the closed polygon `corners`, side i cut into steps[i] equal parameter
// steps (power-of-two steps on dyadic corners: exact, so collinear runs stay collinear).
inline std::vector<geometry::Point> along(const std::vector<geometry::Point>& corners, const std::vector<int>& steps) {
  std::vector<geometry::Point> points;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const geometry::Point &a = corners[i], &b = corners[(i + 1) % corners.size()];
    for (int k = 0; k < steps[i]; ++k) {
      const double t = double(k) / steps[i];
      points.emplace_back(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
    }
  }
  return points;
}

// Every point times 2^exponent: exact, so every predicate keeps its sign.
inline std::vector<geometry::Point> scaled_by(const std::vector<geometry::Point>& points, int exponent) {
  std::vector<geometry::Point> scaled;
  for (const geometry::Point& p : points) scaled.emplace_back(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent));
  return scaled;
}

}  // namespace curvebench::testing
