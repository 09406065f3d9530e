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

std::vector<Edge> beta_skeleton_reconstruction(std::span<const Point> points, double beta);
Algorithm beta_skeleton_algorithm();

}  // namespace curvebench::algorithms
