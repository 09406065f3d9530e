// A naive NN-Crust (Dey and Kumar 1999) in plain C++17, shared by the two ways this folder's
// examples run it: as a program behind `exec:` (naive_nn_crust.cpp here) and in-process,
// registered with the installed curvebench library (../in-process/).
//
// Each point is joined to its nearest neighbour q and to its half neighbour, the nearest
// point r with angle q-p-r above `half_angle_degrees` (90 in the paper). O(n^2), in floating
// point: curvebench's own NN-Crust (algorithms/nn_crust.h) decides exactly, and
// `curvebench hunt` shows where that matters.
#pragma once

#include <cmath>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace naive {

struct Point {
  double x, y;
};

// The edges (i, j), i < j, sorted, between indices of `points`.
inline std::set<std::pair<std::size_t, std::size_t>> nn_crust(const std::vector<Point>& points,
                                                              double half_angle_degrees) {
  const double cos_limit = std::cos(half_angle_degrees * M_PI / 180);
  const auto distance2 = [&](std::size_t a, std::size_t b) {
    return std::pow(points[a].x - points[b].x, 2) + std::pow(points[a].y - points[b].y, 2);
  };
  std::set<std::pair<std::size_t, std::size_t>> edges;
  const auto join = [&](std::size_t a, std::size_t b) { edges.insert({std::min(a, b), std::max(a, b)}); };
  const std::size_t n = points.size(), none = n;
  for (std::size_t p = 0; p < n; ++p) {
    std::size_t q = none;
    for (std::size_t r = 0; r < n; ++r)
      if (r != p && (q == none || distance2(p, r) < distance2(p, q))) q = r;
    if (q == none) continue;
    join(p, q);
    // The half neighbour: the nearest r whose direction makes more than the angle with q's.
    std::size_t half = none;
    const double qx = points[q].x - points[p].x, qy = points[q].y - points[p].y;
    for (std::size_t r = 0; r < n; ++r) {
      if (r == p || r == q) continue;
      const double rx = points[r].x - points[p].x, ry = points[r].y - points[p].y;
      const double cosine = (qx * rx + qy * ry) / std::sqrt((qx * qx + qy * qy) * (rx * rx + ry * ry));
      if (cosine < cos_limit && (half == none || distance2(p, r) < distance2(p, half))) half = r;
    }
    if (half != none) join(p, half);
  }
  return edges;
}

}  // namespace naive
