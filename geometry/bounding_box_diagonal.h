// The length of the diagonal of the axis-parallel bounding box of some points: the size
// that relative tolerances are fractions of (the lfs floor and resolution, and the
// survey's uniform noise, "Robustness to Noise": "delta is in terms of the bounding box
// diagonal").
#pragma once

#include <cmath>
#include <span>

#include <CGAL/bounding_box.h>

#include "geometry/kernel.h"

namespace curvebench::geometry {

// The diagonal of the axis-parallel bounding box of `points` (in their units); 0 for none
// or one. Computed in double (a size, not a decision).
inline double bounding_box_diagonal(std::span<const Point> points) {
  if (points.empty()) return 0;
  const auto box = CGAL::bounding_box(points.begin(), points.end());
  return std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
}

}  // namespace curvebench::geometry
