// EMST reconstruction (de Figueiredo, Gomes 1994; survey, "Graph-Based
// Reconstruction"): the Euclidean minimum spanning tree of a dense enough sample of an
// open curve is the curve's polygon. One tree: it can never close a curve or separate two.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The EMST's edges, canonical (i < j, sorted). Throws std::invalid_argument for equal
// points or a non-finite coordinate.
std::vector<Edge> emst_reconstruction(std::span<const Point> points);
// The registry's entry "emst", without parameters.
Algorithm emst_algorithm();

}  // namespace curvebench::algorithms
