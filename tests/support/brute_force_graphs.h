// Brute-force oracles for the proximity graphs, straight from the textbook definitions:
// every pair against every point, in exact rational arithmetic (CGAL::Exact_rational),
// or exact real arithmetic with square roots (CORE::Expr) where the definition has
// circle centres or distances that are irrational. Independent of graphs/: none of the
// polynomial rewritings in proximity_predicates.h is used here.
#pragma once

#include <array>
#include <vector>

#include <CGAL/Exact_rational.h>

#include "geometry/edge.h"
#include "geometry/kernel.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::testing {

using geometry::Edge;
using geometry::Point;

// Pairs through which some circle has no point strictly inside ("weak" Delaunay edges),
// and pairs through which some circle has every other point strictly outside ("strong").
// Every Delaunay triangulation lies between the two.
std::vector<Edge> weak_delaunay_edges(const std::vector<Point>& points);
std::vector<Edge> strong_delaunay_edges(const std::vector<Point>& points);

// The triangles of the Delaunay triangulation where it is unique (strong == weak edges):
// the triples i < j < k of `delaunay` edges, not collinear, whose circumcircle holds no
// point strictly inside. None for collinear input.
std::vector<std::array<std::size_t, 3>> brute_force_delaunay_triangles(const std::vector<Point>& points,
                                                                      const std::vector<Edge>& delaunay);

// Number of points on the boundary of the convex hull (vertices and points on its edges).
std::size_t hull_boundary_size(const std::vector<Point>& points);
// Whether two edges cross at a point interior to both, or one passes through a point.
bool has_crossing_or_overlap(const std::vector<Point>& points, const std::vector<Edge>& edges);

std::vector<Edge> brute_force_beta_skeleton(const std::vector<Point>& points, double beta, graphs::Beta_region region);
std::vector<Edge> brute_force_relative_neighborhood_graph(const std::vector<Point>& points);
std::vector<Edge> brute_force_gabriel_graph(const std::vector<Point>& points);
std::vector<Edge> brute_force_minimum_spanning_tree(const std::vector<Point>& points);  // Prim, exact order
std::vector<Edge> brute_force_sphere_of_influence_graph(const std::vector<Point>& points);
// Each point's k nearest other points, nearest first, equal distances by index.
std::vector<std::vector<std::size_t>> brute_force_k_nearest_neighbors(const std::vector<Point>& points, std::size_t k);
std::vector<Edge> brute_force_k_nearest_neighbor_graph(const std::vector<Point>& points, std::size_t k);
std::vector<Edge> brute_force_alpha_shape_boundary(const std::vector<Point>& points, double alpha);

// |a - b|^2, exactly.
inline CGAL::Exact_rational exact_squared_distance(const Point& a, const Point& b) {
  const CGAL::Exact_rational dx = CGAL::Exact_rational(a.x()) - CGAL::Exact_rational(b.x());
  const CGAL::Exact_rational dy = CGAL::Exact_rational(a.y()) - CGAL::Exact_rational(b.y());
  return dx * dx + dy * dy;
}

// Total Euclidean length of the edges, in double.
double total_length(const std::vector<Point>& points, const std::vector<Edge>& edges);

}  // namespace curvebench::testing
