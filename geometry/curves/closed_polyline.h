// Exact tests on closed polylines, the fine chords through which generators check that the
// curves they draw are simple (a random Fourier curve, a star polygon) or apart (the two
// components of a nested pair). Decided by CGAL's exact predicates; candidate pairs come
// from box intersection of the edges.
#pragma once

#include <span>

#include "geometry/kernel.h"

namespace curvebench::geometry {

// Whether the closed polyline through `points` crosses or touches itself anywhere but at
// the shared vertex of consecutive edges (a consecutive edge folding back counts).
bool closed_polyline_is_simple(std::span<const Point> points);

// Whether the closed polylines through `a` and through `b` cross or touch.
bool closed_polylines_meet(std::span<const Point> a, std::span<const Point> b);

}  // namespace curvebench::geometry
