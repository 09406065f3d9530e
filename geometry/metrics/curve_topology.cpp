#include "geometry/metrics/curve_topology.h"

#include <algorithm>
#include <vector>

#include <boost/pending/disjoint_sets.hpp>

namespace curvebench::geometry {

Curve_topology curve_topology(std::size_t point_count, std::span<const Edge> edges) {
  std::vector<std::size_t> degree(point_count, 0), rank(point_count), parent(point_count);
  boost::disjoint_sets<std::size_t*, std::size_t*> components(rank.data(), parent.data());
  for (std::size_t v = 0; v < point_count; ++v) components.make_set(v);
  for (const auto& [i, j] : edges) {
    ++degree[i], ++degree[j];
    components.union_set(i, j);
  }
  const auto root = [&](std::size_t v) { return components.find_set(v); };
  // Per component (by root): vertices, edges, vertices of degree 1 and of degree > 2.
  struct Tally {
    std::size_t vertices = 0, edges = 0, ends = 0, branches = 0;
  };
  std::vector<Tally> tally(point_count);
  for (const auto& [i, j] : edges) ++tally[root(i)].edges;
  Curve_topology result;
  for (std::size_t v = 0; v < point_count; ++v) {
    result.max_degree = std::max(result.max_degree, degree[v]);
    if (degree[v] == 0) {
      ++result.unconnected;
      continue;
    }
    Tally& t = tally[root(v)];
    ++t.vertices;
    t.ends += degree[v] == 1;
    t.branches += degree[v] > 2;
  }
  result.manifold = result.max_degree <= 2;
  for (const Tally& t : tally) {
    if (t.edges == 0) continue;
    ++result.components;
    if (t.branches > 0) continue;
    // Degrees <= 2 and connected: a path (two ends, one edge fewer than vertices) or a cycle.
    if (t.ends == 0 && t.edges == t.vertices) ++result.closed_components;
    if (t.ends == 2 && t.edges + 1 == t.vertices) ++result.open_components;
  }
  return result;
}

}  // namespace curvebench::geometry
