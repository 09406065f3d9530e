// Edge uv of a Delaunay triangulation by its end points: the position of uv in
// dt.edges(), found in O(log degree) through each vertex's incident edges sorted by
// neighbour. Algorithms that keep per-edge state (a sculpting's boundary, a labelling's
// dual edges) look edges up by their triangles' corners with it.
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
  // A position in dt.edges().
  using Edge_id = std::uint32_t;

  // Indexes every edge of `dt`, sorting each vertex's incident edges by neighbour.
  explicit Delaunay_edge_index(const Delaunay_triangulation& dt) : first_(dt.size() + 1, 0) {
    const auto edges = dt.edges();
    for (const Delaunay_edge& e : edges) ++first_[e.source + 1], ++first_[e.target + 1];
    std::partial_sum(first_.begin(), first_.end(), first_.begin());
    incident_.resize(first_.back());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (Edge_id id = 0; id < edges.size(); ++id) {
      incident_[next[edges[id].source]++] = {edges[id].target, id};
      incident_[next[edges[id].target]++] = {edges[id].source, id};
    }
    for (Vertex v = 0; v < dt.size(); ++v) std::sort(incident_.begin() + first_[v], incident_.begin() + first_[v + 1]);
  }

  // The id of edge uv, which must exist.
  Edge_id find(Vertex u, Vertex v) const {
    if (first_[u + 1] - first_[u] > first_[v + 1] - first_[v]) std::swap(u, v);
    const auto begin = incident_.begin() + first_[u], end = incident_.begin() + first_[u + 1];
    return std::lower_bound(begin, end, std::pair<Vertex, Edge_id>{v, 0})->second;
  }

 private:
  std::vector<std::size_t> first_;
  std::vector<std::pair<Vertex, Edge_id>> incident_;
};

}  // namespace curvebench::graphs
