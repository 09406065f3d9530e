#include "graphs/k_nearest_neighbor_graph.h"

#include <queue>

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

std::vector<std::vector<Vertex>> k_nearest_neighbors(const Delaunay_triangulation& dt, std::size_t k) {
  std::vector<std::vector<Vertex>> ranked(dt.size());
  std::vector<Vertex> seen(dt.size(), no_vertex);  // seen[v] == p: v was reached from p
  for (Vertex p = 0; p < dt.size() && k > 0; ++p) {
    const Point& center = dt.point(p);
    const auto closer_to_p = [&](Vertex a, Vertex b) { return closer(center, dt.point(a), a, dt.point(b), b); };
    const auto farther_from_p = [&](Vertex a, Vertex b) { return closer_to_p(b, a); };
    std::priority_queue<Vertex, std::vector<Vertex>, decltype(farther_from_p)> frontier(farther_from_p);
    std::priority_queue<Vertex, std::vector<Vertex>, decltype(closer_to_p)> nearest(closer_to_p);  // top: k-th

    seen[p] = p;
    for (const Vertex w : dt.neighbors(p)) seen[w] = p, frontier.push(w);
    // Stop once k are held and nothing left can tie with the k-th: the search may meet
    // equidistant points out of index order, and all of them must be compared.
    while (!frontier.empty() &&
           (nearest.size() < k ||
            compare_distances(center, dt.point(frontier.top()), dt.point(nearest.top())) != CGAL::NEGATIVE)) {
      const Vertex v = frontier.top();
      frontier.pop();
      nearest.push(v);
      if (nearest.size() > k) nearest.pop();
      for (const Vertex w : dt.neighbors(v))
        if (seen[w] != p) seen[w] = p, frontier.push(w);
    }
    ranked[p].resize(nearest.size());
    for (auto slot = ranked[p].rbegin(); !nearest.empty(); nearest.pop()) *slot++ = nearest.top();
  }
  return ranked;
}

Graph k_nearest_neighbor_graph(const Delaunay_triangulation& dt, std::size_t k) {
  std::vector<Edge> edges;
  const auto ranked = k_nearest_neighbors(dt, k);
  for (Vertex p = 0; p < dt.size(); ++p)
    for (const Vertex q : ranked[p]) edges.emplace_back(p, q);
  return make_graph(dt.points(), edges);
}

}  // namespace curvebench::graphs
