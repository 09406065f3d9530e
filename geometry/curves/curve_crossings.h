// Where a curve crosses itself or another component: points of the medial axis' closure
// (survey, "Definitions and Notations"), so lfs is 0 there, as at a sharp corner.
//
// Found on chords: given a fine polyline of each component by its parameters, pairs of
// non-adjacent chords that meet are found by box intersection and decided by CGAL's exact
// do_intersect; each meeting is then refined on the curves by Newton's method. Branches
// that only touch tangentially between two chord vertices can be missed.
#pragma once

#include <span>
#include <vector>

#include "geometry/curves/curve.h"
#include "geometry/curves/curve_location.h"

namespace curvebench::geometry {

// A point where two branches of a curve meet: two places on one component, or one on each
// of two components.
struct Curve_crossing {
  Point point;  // the midpoint of the two branches' points at `first` and `second`
  // Where each branch passes the crossing, a closed component's parameter in
  // [0, piece_count()).
  Curve_location first, second;  // first.component <= second.component
};

// `chord_parameters[c]`: increasing parameters of component c, in [0, piece_count()]
// (a closed component's last chord returns to its first parameter).
std::vector<Curve_crossing> curve_crossings(const Curve& curve,
                                            std::span<const std::vector<double>> chord_parameters);

}  // namespace curvebench::geometry
