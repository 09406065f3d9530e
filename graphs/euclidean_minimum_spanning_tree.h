// The Euclidean minimum spanning tree (survey, "Proximity Graphs"; a reconstruction of
// open curves by de Figueiredo and Gomes 1994), as a forest if the input is empty.
//
// Kruskal's algorithm over the Delaunay edges, which contain the EMST. Edges are ordered
// exactly by squared length, ties by (smaller index, larger index): with this total
// order the tree is unique, so every machine and input order gives the same one.
// Written by hand rather than with boost::kruskal_minimum_spanning_tree because Boost
// orders edges by a weight value, and a rounded length cannot order them exactly.
#pragma once

#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"

namespace curvebench::graphs {

// The EMST of dt's points: n - 1 edges (none for no point). O(n log n) after the
// triangulation.
Graph euclidean_minimum_spanning_tree(const Delaunay_triangulation& dt);
// The same, triangulating `points` first (throws std::invalid_argument for equal points or
// a non-finite coordinate).
inline Graph euclidean_minimum_spanning_tree(std::span<const Point> points) {
  return euclidean_minimum_spanning_tree(Delaunay_triangulation(points));
}

}  // namespace curvebench::graphs
