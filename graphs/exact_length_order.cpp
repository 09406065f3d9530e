#include "graphs/exact_length_order.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <tuple>

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

std::vector<Edge_with_length> with_lengths(std::span<const Point> points, std::span<const Delaunay_edge> edges) {
  std::vector<Edge_with_length> result;
  result.reserve(edges.size());
  for (const Delaunay_edge& e : edges)
    result.push_back(
        {geometry::squared_distance_approximation(points[e.source], points[e.target]), e.source, e.target});
  return result;
}

void sort_by_exact_length(std::span<const Point> points, std::vector<Edge_with_length>& edges) {
  const auto shorter = [&](const Edge_with_length& a, const Edge_with_length& b) {
    const CGAL::Sign s = compare_lengths(points[a.source], points[a.target], a.squared_length, points[b.source],
                                         points[b.target], b.squared_length);
    return s == CGAL::POSITIVE ||
           (s == CGAL::ZERO && std::tie(a.source, a.target) < std::tie(b.source, b.target));
  };
  std::sort(edges.begin(), edges.end(),
            [](const Edge_with_length& a, const Edge_with_length& b) { return a.squared_length < b.squared_length; });
  const auto separated = [](double shorter_key, double longer_key) {
    return shorter_key >= 0x1p-900 && std::isfinite(longer_key) &&
           longer_key - shorter_key > (shorter_key + longer_key) * 0x1p-48;
  };
  for (auto run = edges.begin(); run != edges.end();) {
    auto end = std::next(run);
    while (end != edges.end() && !separated(std::prev(end)->squared_length, end->squared_length)) ++end;
    if (std::distance(run, end) > 1) std::sort(run, end, shorter);
    run = end;
  }
}

}  // namespace curvebench::graphs
