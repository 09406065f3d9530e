// Shape-hull graph (Peethambaran, Muthuganapathy 2015, "Reconstruction of water-tight
// surfaces through Delaunay sculpting", Computer-Aided Design 58, 62-72, which defines the
// planar SHG; survey, "Graph Based"): sculpt the Delaunay triangulation from the convex
// hull inwards, longest boundary edge first, removing a boundary triangle when its
// circumcentre lies beyond its boundary edge and its apex is not yet on the boundary; the
// boundary left, the shape hull, is the curve: one simple closed polygon.
//
// (The survey cites this paper for the SHG; its sibling, "A non-parametric approach to shape
// reconstruction from planar point sets through Delaunay filtering", CAD 62, 164-175, builds
// a relaxed Gabriel graph with holes from area samples, by similar rules.)
// Built from the survey's description and the paper's abstract (the full text was not
// available): "repeatedly removing boundary Delaunay edges subjected to geometric and
// topological properties", the circumcentre criterion and a regularity criterion that keeps
// the polygon "topologically equivalent to a circle"; the abstract adds that the SHG
// "contains all Gabriel edges and a few non-Gabriel edges". As implemented:
//   1. the region is every finite Delaunay triangle; its boundary is the convex hull, every
//      point on the hull (corners and points along its sides) a boundary vertex;
//   2. boundary edges wait in a queue, longest first by exact squared length, ties to the
//      smaller (source, target);
//   3. boundary edge pq, with pqr the region's triangle on it, removes pqr when
//      (geometric) the angle at r is strictly obtuse, (p - r).(q - r) < 0, i.e. the
//      circumcentre lies strictly beyond pq (on pq, a right angle, keeps the triangle), and
//      (regularity) r is not a boundary vertex; pr and qr become boundary edges, r a
//      boundary vertex;
//   4. when no boundary edge qualifies, the output is the region's boundary edges.
// A removed triangle meets the boundary in exactly its edge pq (r is interior, so pr and qr
// are too), so every step keeps the region a triangulated disk and its boundary a simple
// cycle. A triangle with two boundary edges (an ear) or with a boundary apex elsewhere (a
// pinch) is never removed: the first would drop a point off the curve, the second would
// make r a junction. Hence a boundary vertex stays one, every convex-hull point is on the
// output, and points inside the final region stay unconnected. Only non-Gabriel edges
// (obtuse apex) are ever removed, which keeps every Gabriel edge in the SHG, as the
// abstract says. A concave sharp corner is carved only if the pocket opens wider than 90
// degrees there: at exactly 90 the last triangle is right-angled and the corner point stays
// out (tests/algorithms/shape_hull_test.cpp measures the smooth curves it reconstructs).
//
// Each edge is judged once, when it leaves the queue: its remaining triangle cannot change
// while it is a boundary edge (its other triangle is gone, and the one it has can only be
// removed through it), and an apex on the boundary stays there; so an edge that fails once
// fails for good, and the queue process removes, at every step, the longest edge that
// qualifies. Edges whose triangle is not obtuse are not queued at all. O(n log n): the
// triangulation, then a heap of at most 3n edges.
//
// Exact decisions: the obtuse test is the sign of (p - r).(q - r), filtered as a
// comparison of sums of squares; the queue compares rounded squared lengths where the
// filter separates them and the exact squared lengths where it cannot. Collinear input
// gives the chain of consecutive points; two points their edge; fewer, nothing.
#pragma once

#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The shape hull's edges on distinct points, canonical (i < j, sorted, no repeats). Throws
// std::invalid_argument for equal points or a non-finite coordinate.
std::vector<Edge> shape_hull_reconstruction(std::span<const Point> points);
// The registry's entry "shape-hull", without parameters.
Algorithm shape_hull_algorithm();

}  // namespace curvebench::algorithms
