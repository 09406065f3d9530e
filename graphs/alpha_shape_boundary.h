// The boundary of the alpha-shape (Edelsbrunner, Kirkpatrick and Seidel 1983; survey,
// "Graph-Based Reconstruction"): the edges of the alpha-complex that bound it, i.e. the
// regular and singular edges of CGAL's Alpha_shape_2 in GENERAL mode. Singular edges
// matter here: a sparse curve sample has no triangle in its alpha-complex at all.
//
// `alpha` is CGAL's parameter, the *squared* radius of the eraser disk, so that it is
// compared exactly with the squared circumradii; a radius would have to be squared in
// floating point first.
//
// Read off the Delaunay triangulation edge by edge, with CGAL's classification and
// conventions: a triangle is in the complex iff its squared circumradius is <= alpha; an
// edge with a triangle of the complex on exactly one side is regular; an edge with none
// is singular iff no point lies strictly inside its diametral circle (only its two
// apexes can, on a Delaunay edge) and |pq|^2 / 4 <= alpha. Each test is one exact
// polynomial sign. O(n) after the triangulation (CGAL's Alpha_shape_2 with exact alpha
// comparisons, which this replaced, took 30x the triangulation).
#pragma once

#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"

namespace curvebench::graphs {

// Throws std::invalid_argument unless alpha is finite and >= 0, or if points repeat.
Graph alpha_shape_boundary(std::span<const Point> points, double alpha);
// The same on a triangulation built beforehand. Throws std::invalid_argument unless alpha
// is finite and >= 0.
Graph alpha_shape_boundary(const Delaunay_triangulation& dt, double alpha);

}  // namespace curvebench::graphs
