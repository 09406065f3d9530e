// The beta-skeleton of a point set (Kirkpatrick and Radke 1985; survey, "Proximity
// Graphs"): pq is an edge iff no other point lies in the region R_beta(p, q) defined,
// with its boundary conventions, at graphs::blocks in proximity_predicates.h.
//
// Cost: for beta >= 1 every edge is a Gabriel edge, so candidates are the O(n) Delaunay
// edges. The circle-based region on each side of pq is { r : angle prq > theta }, and the
// Delaunay vertex opposite pq maximises that angle on its side, so two tests per edge
// decide it: O(n log n) in all. The lune-based region (beta > 1) is searched through the
// triangulation (Delaunay_region_search), stopping at the first point found: O(n log n)
// on uniform and curve samples, O(n^2) in the worst case (many points crowding a long
// edge's lune hull without entering the lune). For beta < 1 the skeleton is not a
// subgraph of the triangulation and every pair is tested against every point: O(n^3),
// practical up to a few thousand points.
#pragma once

#include <span>

#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

// Throws std::invalid_argument unless beta is finite and >= 0.
Graph beta_skeleton(const Delaunay_triangulation& dt, double beta, Beta_region region);

// The same, triangulating `points` first (which also throws std::invalid_argument for
// equal points or a non-finite coordinate).
inline Graph beta_skeleton(std::span<const Point> points, double beta, Beta_region region) {
  return beta_skeleton(Delaunay_triangulation(points), beta, region);
}

}  // namespace curvebench::graphs
