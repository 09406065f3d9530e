#include "graphs/sphere_of_influence_graph.h"

#include "graphs/delaunay_region_search.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

Graph sphere_of_influence_graph(const Delaunay_triangulation& dt) {
  std::vector<Vertex> nearest(dt.size());
  for (Vertex v = 0; v < dt.size(); ++v) nearest[v] = dt.nearest_neighbor(v);

  std::vector<Edge> edges;
  Delaunay_region_search search(dt);
  for (Vertex p = 0; p < dt.size(); ++p) {
    if (nearest[p] == no_vertex) continue;
    const Point& center = dt.point(p);
    const Point& rim = dt.point(nearest[p]);
    search.find_if(
        p, [&](Vertex x) { return within_twice_nearest(center, rim, dt.point(x)); },
        [&](Vertex q) {
          // r_q < r_p, or equal and q < p: each edge is found from exactly one end.
          const auto by_radius = compare_lengths(dt.point(q), dt.point(nearest[q]), center, rim);
          const bool found_from_p = by_radius == CGAL::POSITIVE || (by_radius == CGAL::ZERO && q < p);
          if (found_from_p && spheres_of_influence_meet(center, rim, dt.point(q), dt.point(nearest[q])))
            edges.emplace_back(p, q);
          return false;
        });
  }
  return make_graph(dt.points(), edges);
}

}  // namespace curvebench::graphs
