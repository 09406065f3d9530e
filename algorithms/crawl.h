// Crawl (Parakkat, Muthuganapathy 2016, "Crawl through Neighbors: A Simple Curve
// Reconstruction Algorithm"; survey, "Graph Based"): grow a path over the Delaunay
// triangulation from its shortest seed edge, always at the end whose nearest unvisited
// Delaunay neighbour is nearer, and close it when its two ends become near neighbours;
// then start again from the shortest seed left, for the next component.
//
// Following the authors' code (amaldevp/Crawl_through_Neighbors, Crawl.cpp; its output on the
// paper's own figures is this file's first test, tests/algorithms/conformance_test.cpp):
//   - seeds are the Delaunay edges from a point to its nearest neighbour, shortest first;
//     a seed starts a component if neither end is visited yet;
//   - before each growth step, after at least four, the path closes when either end is the
//     other's second nearest Delaunay neighbour (visited or not). That is theirs, and the
//     default. It closes an open curve whose end has few Delaunay neighbours, the far end
//     then being its second nearest, and it misses a closing edge that is an end's nearest;
//     Crawl_closing::mutual (registry: mutual_closing = 1) closes only when each end is
//     among the other's two nearest, which keeps such curves open;
//   - a path with no unvisited Delaunay neighbour at either end stays open: that is the
//     open-curve heuristic, and why a curve with fewer than six points is never closed.
// Deviations: every "nearer" is an exact comparison of squared distances, ties to the
// smaller index (theirs compares float lengths, ties to the triangulation's circulation
// order); a growth tie goes to the end that started at the seed's larger index, as theirs
// goes to its second end; their neighbour scans also see CGAL's infinite vertex, at an
// unset point ((0, 0) in a build here), which ours never does: it ranks last for points far
// from the origin, as on all their figures, but can be a hull point's nearest near it.
//
// On the 38 figures of the paper (../shared/data/crawl/) ours gives the authors' program's
// very edges on 35; the other three each meet a tie, exact or in float, that the two break
// differently (the test lists them). The authors' closing rule breaks an open curve whose
// ends' Delaunay neighbours reach across a bay (crawl_test.cpp's sine arc); mutual closing
// keeps it, but on 13 of the figures leaves a closed curve open.
//
// O(n log n): each point's neighbours are ranked once, and each end keeps a cursor past
// its visited ones, so the crawl reads every Delaunay edge a bounded number of times.
// The authors' code scans a linked list per seed and is quadratic.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// When a path of at least four growth steps closes, its ends being a and b.
enum class Crawl_closing {
  authors,  // a is b's second nearest Delaunay neighbour, or b is a's
  mutual,   // each is among the other's two nearest
};

// The Crawl edges on distinct points, canonical (i < j, sorted, no repeats). Throws
// std::invalid_argument for equal points or a non-finite coordinate.
std::vector<Edge> crawl_reconstruction(std::span<const Point> points, Crawl_closing closing = Crawl_closing::authors);
// The registry's entry "crawl", with parameter mutual_closing (0: Crawl_closing::authors,
// 1: Crawl_closing::mutual).
Algorithm crawl_algorithm();

}  // namespace curvebench::algorithms
