#include "graphs/k_nearest_neighbor_graph.h"

#include <algorithm>

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

std::vector<std::vector<Vertex>> k_nearest_neighbors(const Delaunay_triangulation& dt, std::size_t k) {
  std::vector<std::vector<Vertex>> ranked(dt.size());
  std::vector<Vertex> seen(dt.size(), no_vertex);  // seen[v] == p: v was reached from p
  // A point met in the search and its rounded squared distance from p. The frontier is
  // ordered by that alone: the order of the search does not decide the answer, which the
  // exact `nearest` heap does, only when it may stop. Both heaps keep their storage from
  // one point to the next.
  struct Candidate {
    double squared_distance;
    Vertex vertex;
  };
  const auto farther = [](const Candidate& a, const Candidate& b) { return a.squared_distance > b.squared_distance; };
  std::vector<Candidate> frontier, nearest;  // heaps; tops: the nearest (rounded), the k-th (exact)
  for (Vertex p = 0; p < dt.size() && k > 0; ++p) {
    const Point& center = dt.point(p);
    const auto closer_to_p = [&](const Candidate& a, const Candidate& b) {
      const CGAL::Sign s =
          compare_distances(center, dt.point(a.vertex), a.squared_distance, dt.point(b.vertex), b.squared_distance);
      return s == CGAL::POSITIVE || (s == CGAL::ZERO && a.vertex < b.vertex);
    };
    const auto reach = [&](Vertex w) {
      seen[w] = p;
      frontier.push_back({geometry::squared_distance_approximation(center, dt.point(w)), w});
      std::push_heap(frontier.begin(), frontier.end(), farther);
    };

    frontier.clear();
    nearest.clear();
    seen[p] = p;
    for (const Vertex w : dt.neighbors(p)) reach(w);
    // Stop once k are held and the rounded distances certainly put every point left
    // beyond the k-th. Every point nearer than the k-th, or as near, is joined to p
    // through points no farther (see delaunay_region_search.h), one of which is then in
    // the frontier: no nearer than the k-th, so not certainly beyond it. Near ties go on
    // searching, and the exact heap settles them, equidistant points by index.
    while (!frontier.empty() &&
           (nearest.size() < k ||
            geometry::certain_sign_of_difference(nearest.front().squared_distance,
                                                 frontier.front().squared_distance) != CGAL::POSITIVE)) {
      std::pop_heap(frontier.begin(), frontier.end(), farther);
      const Candidate c = frontier.back();
      frontier.pop_back();
      nearest.push_back(c);
      std::push_heap(nearest.begin(), nearest.end(), closer_to_p);
      if (nearest.size() > k) {
        std::pop_heap(nearest.begin(), nearest.end(), closer_to_p);
        nearest.pop_back();
      }
      for (const Vertex w : dt.neighbors(c.vertex))
        if (seen[w] != p) reach(w);
    }
    std::sort_heap(nearest.begin(), nearest.end(), closer_to_p);  // nearest first
    ranked[p].reserve(nearest.size());
    for (const Candidate& c : nearest) ranked[p].push_back(c.vertex);
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
