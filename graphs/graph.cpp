#include "graphs/graph.h"

#include <algorithm>

namespace curvebench::graphs {

Graph make_graph(std::span<const Point> points, std::vector<Edge> edges) {
  for (auto& [i, j] : edges)
    if (i > j) std::swap(i, j);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  Graph graph(points.size());
  for (const auto& [i, j] : edges)
    boost::add_edge(i, j, CGAL::to_double(CGAL::squared_distance(points[i], points[j])), graph);
  return graph;
}

std::vector<Edge> edge_list(const Graph& graph) {
  std::vector<Edge> edges;
  edges.reserve(boost::num_edges(graph));
  for (const auto e : boost::make_iterator_range(boost::edges(graph))) {
    auto i = boost::source(e, graph), j = boost::target(e, graph);
    edges.emplace_back(std::min(i, j), std::max(i, j));
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace curvebench::graphs
