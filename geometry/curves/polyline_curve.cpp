#include "geometry/curves/polyline_curve.h"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "geometry/curves/path_builder.h"

namespace curvebench::geometry {

Curve polyline_curve(const GroundTruth& truth, std::string name) {
  const std::size_t n = truth.points.size();
  const auto fail = [&](const Edge& e, const std::string& why) {
    throw std::invalid_argument(name + ": edge " + std::to_string(e.first) + " " + std::to_string(e.second) + ": " + why);
  };
  std::vector<std::vector<std::size_t>> neighbours(n);
  std::set<Edge> edges;
  for (const auto& e : truth.edges) {
    const auto [i, j] = e;
    if (i >= n || j >= n) fail(e, "index outside the " + std::to_string(n) + " points");
    if (i == j) fail(e, "joins a point to itself");
    if (!edges.insert(std::minmax(i, j)).second) fail(e, "listed twice");
    for (const std::size_t v : {i, j}) {
      neighbours[v].push_back(i + j - v);
      if (neighbours[v].size() > 2) fail(e, "point " + std::to_string(v) + " gets a third edge");
    }
  }
  for (auto& list : neighbours) std::sort(list.begin(), list.end());

  Path_builder builder;
  std::vector<bool> visited(n, false);
  // Follows the chain from `start` (an end, or any point of a cycle) to its other end or back.
  const auto walk = [&](std::size_t start) {
    builder.move_to(truth.points[start]);
    visited[start] = true;
    for (std::size_t previous = n, current = start;;) {
      const auto& next = neighbours[current];
      const auto step = std::find_if(next.begin(), next.end(), [&](std::size_t v) { return v != previous; });
      if (step == next.end()) return;  // the other end of an open chain
      builder.line_to(truth.points[*step]);
      if (*step == start) return builder.close();
      visited[*step] = true;
      previous = std::exchange(current, *step);
    }
  };
  for (const std::size_t degree : {1, 2})
    for (std::size_t v = 0; v < n; ++v)
      if (!visited[v] && neighbours[v].size() == degree) walk(v);
  return Curve{std::move(name), builder.finish()};
}

}  // namespace curvebench::geometry
