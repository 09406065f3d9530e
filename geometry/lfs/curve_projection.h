// The curve point nearest to a given point: where a point of a plain point file lies on
// its curve, so that a sampling read back from disk can be measured (rho needs the
// interval between two samples) or given lfs noise along the normal.
#pragma once

#include "geometry/curves/curve_location.h"
#include "geometry/lfs/local_feature_size.h"

namespace curvebench::geometry {

// Searched over every component on the lfs grid, then polished (curve_search.h): exact
// to about 1e-7 of a grid step for a point near the curve.
Curve_location nearest_curve_location(const Local_feature_size& lfs, const Point& p);

}  // namespace curvebench::geometry
