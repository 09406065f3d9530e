// Crust (Amenta, Bern, Eppstein 1998, "The crust and the beta-skeleton: combinatorial
// curve reconstruction"; survey, "Feature Size Criteria Reconstruction"):
//   let V be the Voronoi vertices of the sample S and triangulate S ∪ V (Delaunay);
//   the crust is the set of the Delaunay edges of S ∪ V that join two points of S.
//
// Tie rule. When S ∪ V has four cocircular points the Delaunay triangulation of S ∪ V is
// not unique. We keep pq iff it is an edge of EVERY Delaunay triangulation of S ∪ V:
// some circle through p and q has every other point of S ∪ V strictly outside (and no
// point lies strictly inside segment pq). On points in general position this is the
// definition; on degenerate input it is its deterministic, order-independent core (a
// regular polygon gives its cycle: the circumcentres coincide at the centre).
//
// Formulation (exact, and S ∪ V is never triangulated). The circles through p and q are
// centred at m + t n (m the midpoint, n = q - p turned +90 degrees). A point y left of
// pq is strictly inside circle t iff t > t_y, a point right of pq iff t < t_y, where
//     t_y = A / B,  A = |y - p|^2 - (y - p).(q - p),  B = 2 cross(q - p, y - p),
// so pq is kept iff max over right points t_y < min over left points t_y. Then:
//  1. Points of S: in a Delaunay triangulation of S the apexes l (left) and r (right) of
//     pq bind, t in (t_r, t_l); a hull edge has no r.
//  2. If an apex angle is >= 90 degrees, its triangle's circumcentre lies on segment pq
//     or in every circle left: drop pq. The crust is a subgraph of the Gabriel graph.
//  3. Gold and Snoeyink's one-step test ("A one-step crust and skeleton extraction
//     algorithm", 2001) on the dual Voronoi edge c_r c_l: drop pq unless c_r lies strictly
//     outside the circle through p, q, c_l, i.e. t_{c_r} < t_{c_l}.
//     The one-step crust stops here, and it is NOT the crust: another Voronoi vertex can
//     lie in every circle that steps 1-3 leave (a circumcentre of a triangle around p or
//     q, or for a hull edge one far outside the hull). A brute force of the definition
//     finds such edges in about 5% of random sets of 4 to 16 points (one Delaunay edge in
//     400); tests/algorithms/crust_test.cpp keeps three of them as regression cases.
//  4. So pq is certified: pick a circle t^ strictly between the current bounds (the
//     diametral circle t^ = 0 when it fits, which is almost always on curve samples) and
//     find every Voronoi vertex in its closed disk. If there is none, the circle is a
//     witness: keep pq. Otherwise each one found tightens a bound; drop pq once the bounds
//     cross, else repeat with a new circle (the bounds move strictly, so this ends).
//     Finding them: a Voronoi vertex y in a closed disk of centre x and radius R through p
//     and q has an empty circle of radius <= min(|yp|, |yq|) <= sqrt(h^2 + (|s| + R)^2)
//     (h = |pq| / 2, s = |x - m|), so its triangle lies in the disk around x of radius^2
//     <= 8 h^2 + 10 s^2 = |pq|^2 (2 + 10 t^2); and the Delaunay graph induced by the
//     points in any closed disk is connected (an empty disk through two of them inside it
//     exists, and shrinks onto any point inside it). A breadth-first search from p over
//     Delaunay neighbours in that disk therefore reaches every such triangle. If no
//     rounded t^ verifies (bounds too close for doubles), every Voronoi vertex is scanned.
// Exactness: circumcentres are never rounded. With y - p = Y / D (Y of degree 3, D of
// degree 2 in the coordinates), the signs of B, of A - t^ B (inside circle t^, t^ a
// double), of A1 B2 - A2 B1 (t_1 vs t_2, degree 12) and the search-disk test are
// polynomial signs evaluated by geometry::exact_sign. Rounded values only choose which
// circle t^ to try: keeping and dropping are both certified exactly, so the output is the
// definition's on every machine.
// Cost: one Delaunay triangulation of S (not of S ∪ V), then O(1) exact predicates per
// edge on curve samples: O(n log n).
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The crust of distinct points, canonical edges (i < j, sorted). 0 or 1 point: no edge;
// collinear points: the chain of consecutive points (no Voronoi vertex exists).
std::vector<Edge> crust_reconstruction(std::span<const Point> points);
// The registry's entry "crust", without parameters.
Algorithm crust_algorithm();

}  // namespace curvebench::algorithms
