// The Gabriel graph (Gabriel and Sokal 1969; survey, "Proximity Graphs"): pq is an edge
// iff no other point lies in the closed disk with diameter pq. It is the 1-skeleton, and
// a subgraph of every Delaunay triangulation of the points, cocircular or not.
#pragma once

#include "graphs/beta_skeleton.h"

namespace curvebench::graphs {

// The Gabriel graph of dt's points: the beta-skeleton at beta = 1.
inline Graph gabriel_graph(const Delaunay_triangulation& dt) { return beta_skeleton(dt, 1, Beta_region::lune); }
// The same, triangulating `points` first (throws std::invalid_argument for equal points or
// a non-finite coordinate).
inline Graph gabriel_graph(std::span<const Point> points) { return gabriel_graph(Delaunay_triangulation(points)); }

}  // namespace curvebench::graphs
