// The largest value of a function along a stretch of curve, as the sampling measures
// (survey, "Definitions and Notations": epsilon is a supremum over the curve, the reach
// of an interval an infimum) and the safe sampler need it. Evaluated on the
// Local_feature_size grid (finer than lfs / density), then every local maximum of the
// grid is polished by golden-section search between its two neighbours, so a maximum at a
// kink (equidistant from two samples) is found to about 1e-7 of a grid step.
#pragma once

#include <functional>

#include "geometry/lfs/local_feature_size.h"

namespace curvebench::geometry {

// The largest value found by maximize_along, and where.
struct Curve_maximum {
  double value;  // the largest value of f found
  double parameter;  // where it is attained (may pass piece_count() on a closed component)
};

// max of f(s) for s in [s0, s1] of the component (see Local_feature_size::grid).
Curve_maximum maximize_along(const Local_feature_size& lfs, std::size_t component, double s0, double s1,
                             const std::function<double(double)>& f);

}  // namespace curvebench::geometry
