// The k-nearest-neighbour graph: pq is an edge iff q is among the k nearest points of p
// or p among those of q (survey, "Proximity Graphs"). Distances are compared exactly and
// equal distances go to the smaller index, so "the k nearest" is always well defined.
//
// Best-first search through the Delaunay triangulation from p: the points within any
// distance of p are connected in it (see delaunay_region_search.h), so the search meets
// them in order of distance. O(n k log k) after the triangulation.
#pragma once

#include <vector>

#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"

namespace curvebench::graphs {

// Each point's k nearest other points (all of them if there are fewer), nearest first.
std::vector<std::vector<Vertex>> k_nearest_neighbors(const Delaunay_triangulation& dt, std::size_t k);

// The k-nearest-neighbour graph of dt's points (the symmetric one: an edge if either end
// ranks the other). k = 0 gives no edge.
Graph k_nearest_neighbor_graph(const Delaunay_triangulation& dt, std::size_t k);
// The same, triangulating `points` first (throws std::invalid_argument for equal points or
// a non-finite coordinate).
inline Graph k_nearest_neighbor_graph(std::span<const Point> points, std::size_t k) {
  return k_nearest_neighbor_graph(Delaunay_triangulation(points), k);
}

}  // namespace curvebench::graphs
