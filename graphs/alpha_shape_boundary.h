// The boundary of the alpha-shape (Edelsbrunner, Kirkpatrick and Seidel 1983; survey,
// "Graph-Based Reconstruction"): the edges of the alpha-complex that bound it, i.e. the
// regular and singular edges of CGAL's Alpha_shape_2 in GENERAL mode. Singular edges
// matter here: a sparse curve sample has no triangle in its alpha-complex at all.
//
// `alpha` is CGAL's parameter, the *squared* radius of the eraser disk, so that it is
// compared exactly (ExactAlphaComparisonTag) with the squared circumradii; a radius
// would have to be squared in floating point first. O(n log n).
#pragma once

#include "graphs/graph.h"

namespace curvebench::graphs {

// Throws std::invalid_argument unless alpha is finite and >= 0, or if points repeat.
Graph alpha_shape_boundary(std::span<const Point> points, double alpha);

}  // namespace curvebench::graphs
