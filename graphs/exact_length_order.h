// Edges in exact order of length, fast: the order Kruskal's EMST and Crawl's seeds need.
//
// Sorting with an exact comparator costs more than the triangulation at 10^6 edges. So
// sort by the rounded squared lengths (plain doubles), then put in exact order each run
// of consecutive keys that the floating-point filter cannot tell apart. Where it can, the
// keys' error intervals k (1 +- 2^-48) are disjoint, and since both ends grow with k,
// every key before that point is certainly shorter than every key after it: the result
// is the exact order. (Keys whose sum is below 2^-900 may carry subnormal error: never
// split between two of them. This is geometry::certain_sign_of_difference.)
#pragma once

#include <cstdint>
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

// Sorts only the shortest of edges[begin...]: afterwards edges[begin, end) holds at least
// `count` of them (all, if fewer are left) in the order sort_by_exact_length gives, and
// each edge after `end` is longer than each before. Returns end. For greedy algorithms
// that go on from `end` later, or never: DISCUR, having dropped the edges it can no
// longer take, sorts a fraction of the Delaunay edges.
std::size_t sort_shortest_by_exact_length(std::span<const Point> points, std::vector<Edge_with_length>& edges,
                                          std::size_t begin, std::size_t count);

// The positions in `edges` in the same order: the r-th shortest is edges[result[r]]. For
// algorithms that keep per-edge state by position, which looking each sorted edge up by its
// ends would reach through a cache miss per edge.
std::vector<std::uint32_t> edge_ids_by_exact_length(std::span<const Point> points, std::span<const Delaunay_edge> edges);

}  // namespace curvebench::graphs
