// The oracle for NN-Crust and HNN-Crust (algorithms/nn_crust.h): each point's nearest
// neighbour and half neighbour by the definition over ALL pairs of points, in rationals
// (CGAL::Gmpq), ties to the smaller index. It knows nothing of Delaunay triangulations.
#pragma once

#include <CGAL/Gmpq.h>

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/nn_crust.h"

namespace curvebench::testing {

namespace brute_force_detail {

struct Q_point {
  CGAL::Gmpq x, y;
};

inline CGAL::Gmpq squared_distance(const Q_point& a, const Q_point& b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

// The first point by (squared distance to p, index) among those `eligible`.
template <class Eligible>
std::uint32_t nearest(const std::vector<Q_point>& points, std::size_t p, Eligible eligible) {
  std::uint32_t best = algorithms::no_neighbor;
  CGAL::Gmpq best_distance;
  for (std::size_t s = 0; s < points.size(); ++s) {
    if (s == p || !eligible(s)) continue;
    const CGAL::Gmpq d = squared_distance(points[p], points[s]);
    if (best == algorithms::no_neighbor || d < best_distance) {  // ascending s: equal keeps the smaller index
      best = std::uint32_t(s);
      best_distance = d;
    }
  }
  return best;
}

}  // namespace brute_force_detail

inline std::vector<algorithms::Nearest_and_half_neighbor> brute_force_nearest_and_half_neighbors(
    std::span<const geometry::Point> input, algorithms::Half_plane half_plane) {
  using namespace brute_force_detail;
  std::vector<Q_point> points;
  for (const geometry::Point& p : input) points.push_back({CGAL::Gmpq(p.x()), CGAL::Gmpq(p.y())});
  std::vector<algorithms::Nearest_and_half_neighbor> result(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const std::uint32_t q = nearest(points, p, [](std::size_t) { return true; });
    result[p].nearest = q;
    if (q == algorithms::no_neighbor) continue;
    result[p].half = nearest(points, p, [&](std::size_t s) {
      const Q_point &a = points[p], &b = points[q], &c = points[s];
      if (half_plane == algorithms::Half_plane::behind_p)
        return (c.x - a.x) * (b.x - a.x) + (c.y - a.y) * (b.y - a.y) < 0;
      return squared_distance(c, a) < squared_distance(c, b);
    });
  }
  return result;
}

// The first point where nearest_and_half_neighbors, in either search structure, differs
// from the brute force, described; nothing if they agree everywhere.
inline std::optional<std::string> neighbor_mismatch(std::span<const geometry::Point> points,
                                                    algorithms::Half_plane half_plane) {
  using algorithms::Search_structure;
  const auto expected = brute_force_nearest_and_half_neighbors(points, half_plane);
  for (const Search_structure structure : {Search_structure::kd_tree, Search_structure::delaunay_triangulation}) {
    const auto found = algorithms::nearest_and_half_neighbors(points, half_plane, structure);
    const std::string where = structure == Search_structure::kd_tree ? "kd-tree" : "triangulation";
    if (found.size() != expected.size()) return where + ": " + std::to_string(found.size()) + " results";
    for (std::size_t p = 0; p < points.size(); ++p)
      if (found[p].nearest != expected[p].nearest || found[p].half != expected[p].half)
        return where + ", point " + std::to_string(p) + ": found " + std::to_string(found[p].nearest) + ", " +
               std::to_string(found[p].half) + ", expected " + std::to_string(expected[p].nearest) + ", " +
               std::to_string(expected[p].half);
  }
  return std::nullopt;
}

}  // namespace curvebench::testing
