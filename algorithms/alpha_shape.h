// The alpha-shape boundary as a reconstruction (Edelsbrunner, Kirkpatrick, Seidel 1983;
// survey, "Graph-Based Reconstruction"): the boundary edges of the alpha-complex, for one
// global alpha (a squared radius, graphs/alpha_shape_boundary.h). By default alpha is the
// smallest that keeps the complex connected (graphs::connecting_alpha), which needs no
// knowledge of the sampling density.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// alpha unset: graphs::connecting_alpha of the points.
std::vector<Edge> alpha_shape_reconstruction(std::span<const Point> points, std::optional<double> alpha);
// The registry's entry "alpha-shape", with parameter alpha (0: graphs::connecting_alpha).
Algorithm alpha_shape_algorithm();

}  // namespace curvebench::algorithms
