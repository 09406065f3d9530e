// An edge of a reconstructed or ground-truth curve, as the pair of indices of its two
// points. A plain pair (not a class) so that edge lists sort, compare and hash with the
// standard library, and so that geometry/ need not know about Boost.Graph.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace curvebench::geometry {

// The indices of an edge's two points, into the point list it belongs with.
using Edge = std::pair<std::size_t, std::size_t>;

// The form every edge list takes when it leaves a builder or an algorithm, and in which
// two of them compare equal as sets: each edge as (i, j) with i < j, sorted, no repeats.
inline std::vector<Edge> canonical_edges(std::vector<Edge> edges) {
  for (auto& [i, j] : edges)
    if (i > j) std::swap(i, j);
  std::sort(edges.begin(), edges.end());  // not std::ranges: the clang 14 fuzz build
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace curvebench::geometry
