#include "graphs/sphere_of_influence_delaunay_graph.h"

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

Graph sphere_of_influence_delaunay_graph(const Delaunay_triangulation& dt) {
  std::vector<Vertex> nearest(dt.size());
  for (Vertex v = 0; v < dt.size(); ++v) nearest[v] = dt.nearest_neighbor(v);

  std::vector<Edge> edges;
  for (const Delaunay_edge& e : dt.edges()) {
    const Point &p = dt.point(e.source), &q = dt.point(e.target);
    if (spheres_of_influence_meet(p, dt.point(nearest[e.source]), q, dt.point(nearest[e.target])))
      edges.emplace_back(e.source, e.target);
  }
  return make_graph(dt.points(), edges);
}

}  // namespace curvebench::graphs
