// SIG-Connect2D (Marin, Ohrhallinger, Wimmer 2022, "SIGDT: 2D Curve Reconstruction",
// Computer Graphics Forum 41(7), Pacific Graphics; later than the survey, so placed here
// in Table 1's group "Graph Based" beside Connect2D, survey "Graph-Based Reconstruction"):
// start from SIGDT, the sphere-of-influence graph within the Delaunay triangulation,
// which the paper proves contains the curve; thin it longest edge first down to valence
// two (the dual of Connect2D's valence >= 2 boundary complex); repair what is left.
//
// Only the paper's abstract could be read here (the full text and the authors' code were
// not in the index), so the extraction is our own, built on what the abstract says (a
// dual of Connect2D's boundary adjustment that removes SIGDT's redundant edges):
//  S1 SIGDT (graphs/sphere_of_influence_delaunay_graph.h).
//  S2 Thinning, the dual of Connect2D's boundary complex (which adds EMST-completing
//     edges shortest first until every valence is >= 2): remove SIGDT edges longest
//     first, an edge only if both its ends have valence > 2 at that moment. Every vertex
//     keeps valence min(its SIGDT valence, 2) or more, and every edge left has an end of
//     valence <= 2.
//  S3 Junctions: a vertex still of valence > 2 keeps its two shortest edges. (Its
//     neighbours all have valence <= 2 after S2, so vertices are independent here.)
//  S4 Closing: vertices of valence 0 or 1 are joined by Delaunay edges, shortest first,
//     an edge only if both its ends still have valence < 2. This closes paths into
//     cycles (also an open curve whose ends are Delaunay neighbours) and bridges gaps
//     where SIGDT or S3 lost a curve edge, e.g. between two far pairs of points.
// Deviations from the paper, since its steps could not be read: S2-S4 replace its
// (unknown) adjustment steps; Connect2D's inflation and sculpting work on triangles and
// a manifold boundary, these work on edges and valences only. Open paths and isolated
// points that S4 cannot join are returned as they are, so the output is always manifold
// (valence <= 2) but not always a set of closed cycles. No proof: the paper's theorem
// is SIGDT's containment of the curve, not this extraction (which can lose a curve edge
// when both its ends have a shorter skip edge, a sampling of local uniformity about 2).
//
// Registry row (Table 1 has none; ours, from the tests): non-uniform yes, manifold yes,
// several components and holes yes, sharp corners yes (the survey's corner family exact
// from 30 degrees), open curves no (kept open only if their ends are not Delaunay
// neighbours), no noise or outliers, no guarantee.
//
// Exact: every length comparison is graphs::sort_by_exact_length (exact squared lengths,
// ties by the index pair, (source, target) with source < target): "longest first" visits
// equal lengths from the larger pair down, "shortest first" from the smaller pair up.
// O(n log n): the triangulation and two sorts of O(n) edges.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The SIG-Connect2D edges on distinct points, canonical (i < j, sorted, no repeats), a
// subset of the Delaunay triangulation with every valence <= 2. Throws
// std::invalid_argument for equal points or a non-finite coordinate.
std::vector<Edge> sig_connect2d_reconstruction(std::span<const Point> points);
// The registry's entry "sig-connect2d", without parameters.
Algorithm sig_connect2d_algorithm();

}  // namespace curvebench::algorithms
