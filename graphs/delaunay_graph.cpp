#include "graphs/delaunay_graph.h"

namespace curvebench::graphs {

Graph delaunay_graph(const Delaunay_triangulation& dt) {
  std::vector<Edge> edges;
  edges.reserve(dt.edges().size());
  for (const Delaunay_edge& e : dt.edges()) edges.emplace_back(e.source, e.target);
  return make_graph(dt.points(), edges);
}

}  // namespace curvebench::graphs
