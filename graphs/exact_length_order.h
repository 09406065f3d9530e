// Edges in exact order of length, fast: the order Kruskal's EMST and Crawl's seeds need.
//
// Sorting with an exact comparator costs more than the triangulation at 10^6 edges. So
// sort by the rounded squared lengths (plain doubles), then put in exact order each run
// of consecutive keys that the floating-point filter cannot tell apart. Where it can, the
// keys' error intervals k (1 +- 2^-48) are disjoint, and since both ends grow with k,
// every key before that point is certainly shorter than every key after it: the result
// is the exact order. (Keys below 2^-900 may carry subnormal error: never split after one.)
#pragma once

#include <span>
#include <vector>

#include "graphs/delaunay_triangulation.h"

namespace curvebench::graphs {

// An edge with the sort key that sort_by_exact_length reads first.
struct Edge_with_length {
  double squared_length;  // rounded: settles almost every comparison without GMP
  // The end points, as in the Delaunay_edge it was made from (source < target).
  Vertex source, target;  // the other end point
};

// The edges (source, target) of `points` with their rounded squared lengths.
std::vector<Edge_with_length> with_lengths(std::span<const Point> points, std::span<const Delaunay_edge> edges);

// Sorts by exact squared length, ties by (source, target): a total order, so the result
// does not depend on the input order.
void sort_by_exact_length(std::span<const Point> points, std::vector<Edge_with_length>& edges);

}  // namespace curvebench::graphs
