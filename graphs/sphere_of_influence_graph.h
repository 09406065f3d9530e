// The sphere-of-influence graph (Toussaint 1988; survey, "Proximity Graphs"): with r_p
// the distance from p to its nearest neighbour, pq is an edge iff |pq| <= r_p + r_q,
// i.e. the closed disks B(p, r_p) and B(q, r_q) meet. Not a subgraph of the Delaunay
// triangulation; it has O(n) edges.
//
// An edge pq with r_q <= r_p has |pq| <= 2 r_p, so each p searches the closed disk
// B(p, 2 r_p) through the triangulation (Delaunay_region_search). Expected O(n log n) on
// uniform and curve samples; O(n^2) in the worst case (a point with a large nearest-
// neighbour distance next to a dense cluster).
#pragma once

#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"

namespace curvebench::graphs {

// The sphere-of-influence graph of dt's points, searched through `dt`.
Graph sphere_of_influence_graph(const Delaunay_triangulation& dt);
// The same, triangulating `points` first (throws std::invalid_argument for equal points or
// a non-finite coordinate).
inline Graph sphere_of_influence_graph(std::span<const Point> points) {
  return sphere_of_influence_graph(Delaunay_triangulation(points));
}

}  // namespace curvebench::graphs
