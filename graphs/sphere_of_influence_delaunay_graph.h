// SIGDT (Marin, Ohrhallinger, Wimmer 2022, "SIGDT: 2D Curve Reconstruction"): the
// sphere-of-influence graph intersected with the Delaunay triangulation, the Delaunay
// edges pq with |pq| <= r_p + r_q (r_p: the distance from p to its nearest neighbour).
// The paper proves that it contains the reconstruction under its own sampling condition,
// and SIG-Connect2D thins it to a curve. The sphere-of-influence test is the closed one,
// as in sphere_of_influence_graph.h, so SIGDT is a subgraph of both.
//
// Reading the intersection off the triangulation's edges costs O(n) after it, where
// computing SIG first costs a region search per point. On cocircular points the
// triangulation, and so SIGDT, is the one CGAL's symbolic perturbation picks.
#pragma once

#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"

namespace curvebench::graphs {

// SIGDT of dt's points. O(n) after the triangulation.
Graph sphere_of_influence_delaunay_graph(const Delaunay_triangulation& dt);
// The same, triangulating `points` first (throws std::invalid_argument for equal points or
// a non-finite coordinate).
inline Graph sphere_of_influence_delaunay_graph(std::span<const Point> points) {
  return sphere_of_influence_delaunay_graph(Delaunay_triangulation(points));
}

}  // namespace curvebench::graphs
