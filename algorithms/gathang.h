// GathanG (Dey, Wenger 2002, "Fast reconstruction of curves with sharp corners", Int. J.
// Comput. Geom. Appl. 12(5): 353-400; survey, "Reconstructing Sharp Features"): the
// guaranteed, structured variant of Gathan. Every sample proposes its nearest and its
// "half" neighbour and edges proposed at both ends are kept; a sample that has no neighbour
// at 90 degrees or more from its nearest one is a corner, joined to its nearest neighbour and
// to its nearest neighbour at least the corner angle away, replacing the chord between them.
//
// Source. The survey says GathanG structures Gathan to obtain a guarantee, with one
// parameter, the minimum angle of the sharp corners, by which corners are sampled locally,
// and lists its condition as "epsilon < 0.5, alpha > 150 degrees". The paper's full text and
// Dey's code were not reachable from this workplace (searched: code, pages, docs), so what
// the paper proves, and for which sampling condition, could not be checked: the rules below
// are our own, written to the survey's description, not a transcription of the paper.
//
// Guarantee. On a smooth curve every sample has a neighbour at 90 degrees or more from its
// nearest one, so rule C never fires and GathanG is rule S: HNN-Crust's nearest and half
// neighbours (Ohrhallinger, Mitchell, Wimmer 2016), proven to be the two curve neighbours of
// every sample of an epsilon-sampling with epsilon < 0.47 (rho < 0.9); the curve edges are
// Delaunay edges there, so restricting h(p) to Delaunay neighbours changes nothing, and each
// curve edge is proposed at both ends. The registry keeps the survey's bound, epsilon < 0.5
// with corner angles > 150 degrees; between 0.47 and 0.5 it rests on measurement:
// tests/algorithms/proven_conditions_test.cpp passed 1900 random smooth curves (one to three
// components) safe-sampled at measured epsilon < 0.5. For corners no bound is proven here;
// gathan_test.cpp's sharp-corner family measures what rule C covers.
//
// Rules, each decided by an exact predicate (geometry/exact_sign.h; the one rounded quantity
// is cos(alpha), a double, and the decision is exact for that double):
//  S  smooth edges. n(p): p's nearest neighbour; h(p): its nearest Delaunay neighbour x with
//     (x - p).(n(p) - p) <= 0 (angle n(p) p x at least 90 degrees), if any. Distances are
//     compared exactly, ties to the smaller index (graphs/proximity_predicates.h, closer).
//     Edge pq is kept if q in {n(p), h(p)} and p in {n(q), h(q)}.
//  C  corners, nearest-neighbour distance |c n(c)| first (ties: the lexicographically
//     smaller sample; never the input's order).
//     A sample c with no h(c) and degree < 2 is a
//     corner: all its Delaunay neighbours lie within 90 degrees of n(c) (a sharp corner, an
//     end of an open curve, or a vertex of an acute triangle). Let b(c) be its nearest
//     Delaunay neighbour x with angle n(c) c x >= alpha (gathan_rules::angle_at_least).
//     C1 if c has degree 0 and the chord n(c)-b(c) is an edge, it is replaced by
//        n(c)-c and c-b(c) (the corner was cut off by the chord of its two neighbours);
//     C3 then, from (x, y) = (n(c), b(c)) while x and y proposed each other: with x', y'
//        the other proposals of x and y, if x'-y' is an edge (the next rung of a ladder
//        across a sharp corner, where each side's sample is nearer to the other side than
//        to its own), it is replaced by x-x' and y-y' and (x, y) = (x', y');
//     C2 otherwise c-n(c) is added, and c-b(c) if b(c) proposed c or n(c) in S (it looks
//        towards the corner; an end of an open curve is not joined to another end), each
//        where missing while both ends have degree < 2.
// Every vertex ends with degree <= 2. Fewer than 2 points give no edge; collinear points
// give their chain (each point's nearest and half neighbours are its neighbours on the line).
//
// Measured (gathan_test.cpp): the survey's sharp-corner family at every opening angle from
// 10 to 170 degrees in steps of 5, sampled uniformly by arc length at 10, 16 and 20 points
// per unit circle with a sample at the corner, corner_angle = 0.8 x the opening: all exact.
// Without the sample at the corner (measured outside the tests) openings of 30 degrees and
// more stay exact, but 10 and 20 fail: a sample on one side nearer to the other side than to
// its own neighbours makes a ladder of chords, and no corner sample starts C1-C3 on it.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// alpha_degrees in (0, 180): the minimum opening angle of the sharp corners.
std::vector<Edge> gathang_reconstruction(std::span<const Point> points, double alpha_degrees);
// The registry's entry "gathang", with parameter corner_angle (alpha_degrees: default 30,
// from 1 to 179).
Algorithm gathang_algorithm();

}  // namespace curvebench::algorithms
