// DISCUR (Zeng, Nguyen, Yan, Li 2008, "A distance-based parameter free algorithm for
// curve reconstruction", Computer-Aided Design 40, 210-222; survey, "Curve Generation
// based on Human Visual System", Table 1 group "HVS Based"):
//   take the Delaunay edges shortest first and grow vertex-disjoint paths: two free
//   points always connect (Gestalt proximity: nearest neighbours join); an edge at a
//   path's end joins only if a statistical criterion finds it no outlier for that path.
//
// Only the paper's abstract could be read here (its full text was not reachable), so
// the steps follow the abstract, the survey, and the paper's structure (Delaunay edges;
// determine connectivity shortest first; update the connectivity of rejected edges),
// with our own exact criterion. Deviations, and why:
//   - the statistical criterion: an edge pq that touches a path end is an outlier unless
//     |pq| <= 2 L, L the longest edge of a path at p or q (an order statistic of the
//     path's edge lengths). The paper tests a real-valued statistic of mean and standard
//     deviation of lengths, which we could not read; ours is a polynomial sign, exact,
//     still parameter free; its factor 2 is our choice (it tolerates spacing that at
//     most doubles along a path, and rejects gaps wider than twice a path's spacing);
//   - "update connectivity" is event driven: a rejected edge is retried, shortest first,
//     whenever the longest edge of a path at one of its ends grows, so the result is the
//     fixpoint of the criterion, not of one extra pass;
//   - a path closes into a cycle only if it has at least four points and its ends are
//     among each other's two nearest Delaunay neighbours (and pass the criterion): the
//     abstract leaves closing open, and without the rank rule three close points
//     along a curve close into a triangle;
//   - ties in length go to the edge with the smaller (source, target) indices, ties in
//     nearness to the smaller index; every comparison is an exact predicate.
// Consequences: closed curves need at least four points; a curve whose consecutive
// spacings jump by more than the factor 2 everywhere along a gap breaks there.
//
// O(n log n) for the triangulation and the sort; each rejected edge is retried only when
// a path at its ends gets a longer longest edge (bounded in practice, quadratic only in
// contrived inputs with unbounded Delaunay degree).
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The rules of the greedy path growth that DISCUR uses with fixed values and VICUR
// (vicur.h) exposes as parameters.
struct Curve_growth_rules {
  double proximity_ratio = 2;  // an edge at a path end joins if |pq| <= ratio * longest edge of the path
  int closing_rank = 2;        // a path closes if its ends are among each other's k nearest
  // Continuation (VICUR only): a turn at a path end sharper than this angle (degrees,
  // 0..180; 180 turns the rule off) joins only if |pq| <= corner_ratio * the end edge.
  double turning_angle_degrees = 180;
  double corner_ratio = 0;  // that factor; must be > 0 unless the angle is 180 (then unread)
};

// The paths and cycles grown by `rules` on distinct points, canonical (i < j, sorted, no
// repeats). Throws std::invalid_argument for equal points, a non-finite coordinate or
// rules out of range (ratios <= 0 or not finite, rank < 1, angle outside [0, 180]).
std::vector<Edge> grow_curves(std::span<const Point> points, const Curve_growth_rules& rules);

// The DISCUR edges on distinct points: grow_curves with the default rules.
std::vector<Edge> discur_reconstruction(std::span<const Point> points);
// The registry's entry "discur", without parameters.
Algorithm discur_algorithm();

}  // namespace curvebench::algorithms
