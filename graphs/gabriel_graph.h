// The Gabriel graph (Gabriel and Sokal 1969; survey, "Proximity Graphs"): pq is an edge
// iff no other point lies in the closed disk with diameter pq. It is the 1-skeleton, and
// a subgraph of every Delaunay triangulation of the points, cocircular or not.
#pragma once

#include "graphs/beta_skeleton.h"

namespace curvebench::graphs {

inline Graph gabriel_graph(const Delaunay_triangulation& dt) { return beta_skeleton(dt, 1, Beta_region::lune); }
inline Graph gabriel_graph(std::span<const Point> points) { return gabriel_graph(Delaunay_triangulation(points)); }

}  // namespace curvebench::graphs
