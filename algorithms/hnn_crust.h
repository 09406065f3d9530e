// HNN-Crust (Ohrhallinger, Mitchell, Wimmer 2016, "Curve reconstruction with many fewer
// samples", Computer Graphics Forum 35(5); survey, "Feature Size Criteria Reconstruction"):
// every point p chooses its nearest neighbour q and its half neighbour, the nearest point
// strictly closer to p than to q (beyond the bisector of pq, seen from q); an edge is kept
// if both its ends chose it. Reconstructs epsilon < 0.47 (rho < 0.9) samplings.
//
// The rule is the authors' (stefango74/hnn-crust-sgp16, Reconstruct2D.cpp): their half
// neighbour is the first of the 15 nearest points s with |qs| > |ps| (and |qs| > |pq|,
// implied), and only edges chosen from both ends enter the curve. That agreement is how
// open curves end: an end point's half neighbour does not choose it back, so the end point
// keeps one edge (their code exempts the first and last input point instead, which an
// unordered input cannot do). Differences from their code: all points are candidates, not
// only the 15 nearest; distances and the half-plane are decided exactly, ties to the
// smaller index (nearest_and_half_neighbors in nn_crust.h).
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// Canonical edges (i < j, sorted); every point has at most two.
std::vector<Edge> hnn_crust_reconstruction(std::span<const Point> points);
// The registry's entry "hnn-crust", without parameters.
Algorithm hnn_crust_algorithm();

}  // namespace curvebench::algorithms
