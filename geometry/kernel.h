// The number types and kernels every layer of curvebench is written against.
//
// Decisions on geometry use `Kernel` (CGAL's Epick: exact predicates through a
// floating-point filter, inexact constructions). Where a decision depends on a
// constructed value, the construction is done in `Exact_kernel` or expressed as a
// polynomial predicate evaluated by `geometry/exact_sign.h`.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace curvebench::geometry {

// CGAL's Epick, on doubles: exact predicates, constructions rounded.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// CGAL's Epeck: exact constructions too, at a cost; for the decisions on constructed values.
using Exact_kernel = CGAL::Exact_predicates_exact_constructions_kernel;
// A point of the plane with double coordinates: input points, samples, curve points.
using Point = Kernel::Point_2;

}  // namespace curvebench::geometry
