// Lenz (Lenz 2006, "How to sample and reconstruct curves with unusual features", EWCG
// 2006; survey, "Feature Size Criteria"): seed an edge between the two closest points and
// trace it on at both ends with a probe, a cone of half-angle alpha around the last edge's
// direction, to the nearest point inside it; then seed again from the closest unused pair.
//
// The paper's text was not available; this follows the survey's description, which gives
// the seed, the tracing probe, sharp corners and self-intersections, but not the probe's
// exact shape or reach. So, as our own choices:
//   - the probe is the closed cone { q : angle(p - o, q - p) <= alpha } at the end p of the
//     last edge op, cut to p's k nearest points (ranked exactly, ties to the smaller
//     index); the trace steps to the first of those inside the cone. The k nearest give
//     the probe a reach that adapts to the local density (a fixed reach times |op| would
//     stop at every tightly clustered pair of a random sampling) and make each step O(k);
//   - a trace may step onto a point that already has edges and goes on through it: that is
//     how a branch crosses another (a sample at the crossing gets degree 4; crossing
//     samples between get two crossing edges, which no planar graph would hold). A trace
//     stops where the probe is empty (an open end, or a sharp corner: a turn wider than
//     alpha) or where its next edge exists already (a closed curve meeting its seed, or a
//     trace joining another);
//   - seeds are the nearest-neighbour pairs, shortest first (exact, ties by indices), used
//     only if neither point has an edge yet; a point skipped by every trace whose nearest
//     neighbour was traced stays isolated. The seed is traced first beyond its larger-index
//     end, then beyond the other;
//   - a seed that neither trace extended is dropped at the end if both its points got
//     other edges meanwhile: the closest pairs include the short sides of the quadrilateral
//     round a crossing sampled between samples, joining the two branches (the survey does
//     not say how the paper avoids them).
// The output is not a manifold in general (survey: "reconstructs a non-manifold").
//
// Exact: the cone test is two polynomial signs, (p - o).(q - p) > 0 and
// ((p - o).(q - p))^2 >= c^2 |p - o|^2 |q - p|^2 with c = cos(alpha) rounded to a double,
// so the probe's half-angle is acos(c), within 1e-16 of alpha, and every decision about
// that cone is exact (geometry/exact_sign.h). The survey reports epsilon < 0.4 (and up to
// 0.48 depending on alpha) as the paper's unproven claim.
//
// O(n log n): the triangulation; then every step adds a new edge of the
// k-nearest-neighbour graph, so there are at most n k steps, each drawing at most k of
// the nearest points by best-first search in the triangulation (O(k log k), exact tests).
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The Lenz edges on distinct points for a probe of half-angle `alpha_degrees` in (0, 90)
// that sees each end's `k` >= 1 nearest points, canonical (i < j, sorted, no repeats).
// Throws std::invalid_argument for equal points, a non-finite coordinate or a parameter
// out of range.
std::vector<Edge> lenz_reconstruction(std::span<const Point> points, double alpha_degrees = 40, std::size_t k = 8);
// The registry's entry "lenz", with parameters alpha (alpha_degrees) and k.
Algorithm lenz_algorithm();

}  // namespace curvebench::algorithms
