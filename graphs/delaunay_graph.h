// The Delaunay graph: the edges of the Delaunay triangulation (survey, "Proximity
// Graphs"). On cocircular points it is the one triangulation CGAL's symbolic
// perturbation selects, the same for every input order.
#pragma once

#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"

namespace curvebench::graphs {

// Every edge of `dt` as a Graph on its points. O(n) after the triangulation.
Graph delaunay_graph(const Delaunay_triangulation& dt);
// The same, triangulating `points` first (throws std::invalid_argument for equal points or
// a non-finite coordinate).
inline Graph delaunay_graph(std::span<const Point> points) { return delaunay_graph(Delaunay_triangulation(points)); }

}  // namespace curvebench::graphs
