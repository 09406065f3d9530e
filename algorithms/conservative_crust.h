// Conservative Crust (Dey, Mehlhorn, Ramos 1999/2000, "Curve reconstruction: connecting
// dots with good reason"; survey, "Feature Size Criteria Reconstruction"): keep an edge
// only with good reason, i.e. when it is a Gabriel edge whose dual Voronoi edge reaches
// far from it, so that an empty circle much larger than the edge passes through both ends.
//   keep pq iff pq is a Gabriel edge (no other point in the closed disk on diameter pq)
//   and the Voronoi edge dual to pq leaves the disk centred at the midpoint of pq of
//   radius |pq| sqrt(1/rho^2 - 1) / 2: some circle through p and q with no point inside
//   has radius >= |pq| / (2 rho).
// An outlier's edges are long against their short dual Voronoi edges, so it stays
// isolated; the ends of an open curve keep their edges, so open curves give paths, unless
// the edge between the two ends is on the convex hull (a gap in a convex stretch), whose
// dual Voronoi edge is a ray, or has a large empty circle through both ends: then the gap
// closes at any density. Certifying the open family shows it (docs/certification.md,
// "Finding: our Conservative Crust closes narrow gaps").
//
// Source of this statement. Neither the paper nor Dey's "ccrust" code is in the stored
// corpora this was written from (searched: code, pages, docs), so the definition above is
// our reading of the paper's idea (Gabriel edges filtered by the length of their dual
// Voronoi edges relative to the edge, one parameter), not a transcription: check it
// against the paper before relying on the parameter's scale. rho is a sampling density
// in the paper's sense: a kept edge pq and the arc of its large empty circle between p
// and q form an arc that p and q sample at epsilon about rho. rho = 1 gives the Gabriel
// graph; smaller is more conservative. The default 0.25 keeps every edge of an
// epsilon-sampling with epsilon < 0.0625 (the survey's bound): there the empty circles
// through adjacent samples have radius about lfs / 2 or more and the edges are at most
// 2 epsilon lfs / (1 - epsilon) < 0.134 lfs long; a Gabriel edge across the medial axis
// has both apex angles near 90 degrees (sine near 1).
//
// Computed exactly on the Delaunay triangulation: the Gabriel test on the two apexes
// (graphs::blocks, beta = 1); the Voronoi edge dual to a Gabriel edge runs from one apex
// triangle's circumcentre to the other's through the midpoint, so it reaches radius
// |pq| / (2 rho) iff the edge is a hull edge (an unbounded Voronoi ray) or an apex angle
// theta has sin theta <= rho, i.e. rho^2 |lp|^2 |lq|^2 - cross(p - l, q - l)^2 >= 0 (the
// inscribed angle: circumradius = |pq| / (2 sin theta)), a polynomial sign
// (geometry/exact_sign.h). Collinear points: the chain (every dual Voronoi edge is a
// whole line). Cost: one Delaunay triangulation, O(1) per edge: O(n log n).
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The default rho: it keeps every edge of an epsilon-sampling with epsilon < 0.0625.
inline constexpr double default_conservative_crust_rho = 0.25;

// Canonical edges (i < j, sorted) of distinct points. Throws std::invalid_argument unless
// 0 <= rho <= 1.
std::vector<Edge> conservative_crust_reconstruction(std::span<const Point> points,
                                                    double rho = default_conservative_crust_rho);
// The registry's entry "conservative-crust", with parameter rho (default 0.25, from 0 to 1).
Algorithm conservative_crust_algorithm();

}  // namespace curvebench::algorithms
