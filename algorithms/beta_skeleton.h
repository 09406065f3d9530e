// The beta-skeleton as a reconstruction (Kirkpatrick, Radke 1985; survey, "Graph-Based
// Reconstruction"): an edge pq is kept iff no other point lies in its lune of parameter
// beta (graphs/beta_skeleton.h). One global beta for the whole sample; beta = 1 is the
// Gabriel graph, beta = 2 the relative neighbourhood graph, and values near 1.7 suit
// curve samples.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The lune-based beta-skeleton's edges, canonical (i < j, sorted). Throws
// std::invalid_argument unless beta is finite and >= 0, and for equal points or a
// non-finite coordinate.
std::vector<Edge> beta_skeleton_reconstruction(std::span<const Point> points, double beta);
// The registry's entry "beta-skeleton", with parameter beta (default 1.7, from 1 to 1e6).
Algorithm beta_skeleton_algorithm();

}  // namespace curvebench::algorithms
