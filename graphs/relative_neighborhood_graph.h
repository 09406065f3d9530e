// The relative neighbourhood graph (Toussaint 1980; survey, "Proximity Graphs"): pq is
// an edge iff no other point r has max(|pr|, |qr|) < |pq|, i.e. the open lune of pq is
// empty. It is the lune-based 2-skeleton; EMST <= RNG <= Gabriel <= Delaunay.
#pragma once

#include "graphs/beta_skeleton.h"

namespace curvebench::graphs {

// The relative neighbourhood graph of dt's points: the lune-based beta-skeleton at beta = 2.
inline Graph relative_neighborhood_graph(const Delaunay_triangulation& dt) {
  return beta_skeleton(dt, 2, Beta_region::lune);
}
// The same, triangulating `points` first (throws std::invalid_argument for equal points or
// a non-finite coordinate).
inline Graph relative_neighborhood_graph(std::span<const Point> points) {
  return relative_neighborhood_graph(Delaunay_triangulation(points));
}

}  // namespace curvebench::graphs
