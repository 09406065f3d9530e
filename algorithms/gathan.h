// Gathan (Dey, Wenger 2001, "Reconstructing curves with sharp corners", Computational
// Geometry 19(2-3): 89-99; survey, "Reconstructing Sharp Features"): NN-Crust restricted to
// the Delaunay edges whose dual Voronoi edge runs along the estimated normal, kept where both
// ends agree; vertices left short of degree 2 (corners, ends) are then joined by the edges
// only one end chose, longest dual Voronoi edge relative to edge length first.
//
// Source. The survey names the three ingredients (angle between an edge's dual Voronoi edge
// and the estimated normal, ratio of dual Voronoi edge length to edge length, vertex
// degrees) and one parameter. The papers' full texts and Dey's released code were not
// reachable from this workplace, so the rules below are our reading of that description,
// not a transcription of the paper; the paper proves nothing for curves with corners
// (survey table: "none"), and neither do we.
//
// Rules, each decided by an exact predicate (polynomial signs in the input coordinates,
// geometry/exact_sign.h; the one rounded quantity is cos^2 of the parameter, a double, and
// the decision is exact for that double):
//  G1 normal line at p: towards its pole, the farthest finite vertex of p's Voronoi cell,
//     i.e. the circumcentre of the incident Delaunay triangle (p, a, b) of largest
//     circumradius (compare_circumradii, after a double estimate with a proven error bound;
//     ties to the triangle met first in the triangulation's fixed edge order).
//     Its direction from p, N = |u|^2 Jv - |v|^2 Ju with u = a - p, v = b - p (J a quarter
//     turn), needs no division. The unbounded side of a hull vertex's cell is not used:
//     next to a hull edge that bridges two components it points anywhere, while the finite
//     pole still lies on the bisector of p and a curve neighbour.
//  G2 pq is a candidate at p if its dual Voronoi edge (on the bisector of pq, direction Jw,
//     w = q - p) makes an angle of at most theta with the normal line:
//     (Jw . N)^2 - cos^2(theta) |w|^2 |N|^2 >= 0 (dual_edge_along_normal).
//  G3 p chooses its shortest candidate pq1 and its shortest candidate pq2 with
//     (q2 - p).(q1 - p) <= 0 (NN-Crust's "angle at least 90 degrees"); lengths compared
//     exactly, ties to the smaller index (graphs/proximity_predicates.h, closer).
//  G4 an edge chosen at both ends is kept.
//  G5 vertices left with degree < 2 (corners, ends) are joined: first by the edges chosen at
//     one end only, then by any other Delaunay edge whose dual Voronoi edge is longer than
//     itself (dual_longer_than_edge: a curve edge's dual runs from the inner to the outer
//     medial axis; a coarse polygon's sides are hull edges, with infinite duals). Within
//     each tier, decreasing |dual Voronoi edge| / |edge| (= (cot A + cot B) / 2 for the
//     angles A, B at the two apexes, infinite on the hull; larger_dual_ratio; ties to the
//     shorter edge, then to the lexicographically smaller ends, never to the input's
//     order); an edge is added while both its ends have degree < 2.
// Every vertex ends with degree <= 2. Fewer than 2 points give no edge; collinear input
// (a Delaunay triangulation of dimension 1) gives the chain of consecutive points.
//
// Measured (gathan_test.cpp, theta = 30): the survey's sharp-corner family, 10 to 170
// degrees, exact at 16 and 20 samples per unit circle and at 10 except 55 degrees; smooth
// random curves exact on all fixed cases up to epsilon 0.4, 8 and 6 of 12 at 0.45 and 0.49:
// the pole (G1) needs Voronoi cells long along the normal, which coarse sampling, and gaps
// between components narrower than a few spacings, cut short.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/algorithm.h"
#include "geometry/exact_sign.h"

namespace curvebench::algorithms {

// The exact predicates of Gathan and GathanG, shared by both and tested against a
// brute-force rational re-implementation.
namespace gathan_rules {

// The line of an estimated normal at p (G1): towards the circumcentre of (p, a, b) for
// `pole`; `none` accepts every direction.
struct Normal_line {
  // pole: the line runs towards the circumcentre of (p, a, b); none: no estimate (p lies in
  // no Delaunay triangle, as on collinear input), every direction passes.
  enum class Kind : std::uint8_t { none, pole };
  Kind kind = Kind::none;  // none unless a pole was found
  // The point the line passes through.
  Point p, a, b;  // with p and a, the triangle whose circumcentre is the pole (pole only)
  // \var a
  // With p and b, the triangle whose circumcentre is the pole (pole only).
};

// A direction vector of the normal line, as a polynomial in the coordinates.
template <class NT>
geometry::Vector2<NT> normal_direction(const Normal_line& normal) {
  using geometry::difference, geometry::squared_length;
  const auto u = difference<NT>(normal.a, normal.p), v = difference<NT>(normal.b, normal.p);
  const NT uu = squared_length(u), vv = squared_length(v);
  return {v.y * uu - u.y * vv, u.x * vv - v.x * uu};
}

// G2: true if the dual Voronoi edge of pq makes an angle of at most theta with `normal`,
// given cos2 = cos^2(theta).
bool dual_edge_along_normal(const Point& p, const Point& q, const Normal_line& normal, double cos2);

// The sign of R2^2 - R1^2 for the circumradii of the triangles (p, a1, b1) and (p, a2, b2)
// (both non-degenerate): POSITIVE if the second circle is larger. With u = a - p, v = b - p:
// R^2 = |u|^2 |v|^2 |u - v|^2 / (4 (u x v)^2).
CGAL::Sign compare_circumradii(const Point& p, const Point& a1, const Point& b1, const Point& a2, const Point& b2);

// A Delaunay edge pq with the apexes of its two triangles, when they exist.
struct Edge_with_apexes {
  // The edge's first end; `left` and `right` are seen from p towards q.
  Point p, q;  // the edge's second end
  const Point* left = nullptr;   // apex left of p -> q
  const Point* right = nullptr;  // apex right of p -> q
};

// True if |e*| / |e| of `e` is strictly larger than that of `f` (G5). A hull edge's dual is a
// ray: its ratio is infinite, and two infinite ratios are equal.
bool larger_dual_ratio(const Edge_with_apexes& e, const Edge_with_apexes& f);

// True if |e*| > |e| (G5's second tier): cot A + cot B > 2, i.e. N - 2 D > 0 for the
// fraction N / D above.
bool dual_longer_than_edge(const Edge_with_apexes& e);

// True if the angle a c x is at least 90 degrees: (a - c).(x - c) <= 0 (a, x != c).
bool at_least_right_angle(const Point& c, const Point& a, const Point& x);

// True if the angle a c x is at least alpha, given cos_alpha = cos(alpha) (a, x != c):
// (a - c).(x - c) <= cos_alpha |a - c| |x - c|, squared where both sides' signs are known.
bool angle_at_least(const Point& c, const Point& a, const Point& x, double cos_alpha);

}  // namespace gathan_rules

// theta_degrees in (0, 90): G2's largest angle between dual Voronoi edge and normal.
std::vector<Edge> gathan_reconstruction(std::span<const Point> points, double theta_degrees);
// The registry's entry "gathan", with parameter theta (degrees, default 30, from 1 to 89).
Algorithm gathan_algorithm();

}  // namespace curvebench::algorithms
