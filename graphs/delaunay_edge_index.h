// Edge uv of a Delaunay triangulation by its end points: the position of uv in
// dt.edges(), found in O(log degree) among the edges whose smaller end is min(u, v),
// sorted by the larger one. Algorithms that keep per-edge state (a sculpting's boundary,
// a labelling's dual edges) look edges up by their triangles' corners with it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "graphs/delaunay_triangulation.h"

namespace curvebench::graphs {

// The index of one triangulation's edges by their end points. It keeps no reference to the
// triangulation.
class Delaunay_edge_index {
 public:
  using Edge_id = graphs::Edge_id;  // a position in dt.edges()

  // Indexes every edge of `dt` under its smaller end (its source): each edge once, and
  // three a vertex on average, so half the memory of listing both ends.
  explicit Delaunay_edge_index(const Delaunay_triangulation& dt) : first_(dt.size() + 1, 0) {
    const auto edges = dt.edges();
    for (const Delaunay_edge& e : edges) ++first_[e.source + 1];
    std::partial_sum(first_.begin(), first_.end(), first_.begin());
    upward_.resize(edges.size());
    std::vector<Edge_id> next(first_.begin(), first_.end() - 1);
    for (Edge_id id = 0; id < edges.size(); ++id) upward_[next[edges[id].source]++] = {edges[id].target, id};
    for (Vertex v = 0; v < dt.size(); ++v) std::sort(upward_.begin() + first_[v], upward_.begin() + first_[v + 1]);
  }

  // The id of edge uv, which must exist.
  Edge_id find(Vertex u, Vertex v) const {
    if (u > v) std::swap(u, v);
    const auto begin = upward_.begin() + first_[u], end = upward_.begin() + first_[u + 1];
    return std::lower_bound(begin, end, std::pair<Vertex, Edge_id>{v, 0})->second;
  }

 private:
  std::vector<Edge_id> first_;                       // where each vertex's upward edges start
  std::vector<std::pair<Vertex, Edge_id>> upward_;  // (larger end, id), by smaller end, then larger
};

}  // namespace curvebench::graphs
