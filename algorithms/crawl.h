// Crawl (Parakkat, Muthuganapathy 2016, "Crawl through Neighbors: A Simple Curve
// Reconstruction Algorithm"; survey, "Graph Based"): grow a path over the Delaunay
// triangulation from its shortest seed edge, always at the end whose nearest unvisited
// Delaunay neighbour is nearer, and close it when its two ends become near neighbours;
// then start again from the shortest seed left, for the next component.
//
// Following the authors' code (amaldevp/Crawl_through_Neighbors), with one deviation:
//   - seeds are the Delaunay edges from a point to its nearest neighbour, shortest first;
//     a seed starts a component if neither end is visited yet;
//   - a path closes, after at least four growth steps, when each end is among the other's
//     two nearest Delaunay neighbours. Theirs closes when either end is the other's second
//     nearest: one-sided, that closes open curves whose end point has few Delaunay
//     neighbours (the far end is often its second nearest: crawl_test.cpp has a sine
//     arc), and second-only misses the closing edge when it is the nearest one;
//   - a path with no unvisited Delaunay neighbour at either end stays open: that is the
//     open-curve heuristic, and why a curve with fewer than six points is never closed.
// Every "nearer" is an exact comparison of squared distances, ties to the smaller index
// (theirs compares float lengths); a growth tie goes to the end that started at the
// seed's larger index, as theirs goes to its second end.
//
// O(n log n): each point's neighbours are ranked once, and each end keeps a cursor past
// its visited ones, so the crawl reads every Delaunay edge a bounded number of times.
// The authors' code scans a linked list per seed and is quadratic.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The Crawl edges on distinct points, canonical (i < j, sorted, no repeats). Throws
// std::invalid_argument for equal points or a non-finite coordinate.
std::vector<Edge> crawl_reconstruction(std::span<const Point> points);
Algorithm crawl_algorithm();

}  // namespace curvebench::algorithms
