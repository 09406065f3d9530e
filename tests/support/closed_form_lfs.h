// Independent oracles for lfs: curves whose medial axis is a known segment, so lfs(p) is
// the distance from p to that segment, computed here by projection (no Voronoi diagram).
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/kernel.h"

namespace curvebench::testing {

using geometry::Point;

inline double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double t = std::clamp(((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x() - (a.x() + t * dx), p.y() - (a.y() + t * dy));
}

// The ellipse x²/a² + y²/b² = 1, a > b: its medial axis is the segment between the
// centers of curvature of its two ends of the major axis, (±(a² - b²)/a, 0).
inline double ellipse_lfs(double a, double b, const Point& p) {
  const double c = (a * a - b * b) / a;
  return distance_to_segment(p, Point(-c, 0), Point(c, 0));
}

// geometry::sharp_corner_curve(angle): the unit circle about the origin with two tangent
// lines meeting at (1 / sin(angle / 2), 0). Convex, so its medial axis is the inner one:
// the segment from the apex to the circle's center.
inline double sharp_corner_lfs(double opening_angle_degrees, const Point& p) {
  const double half = opening_angle_degrees * M_PI / 360;
  return distance_to_segment(p, Point(0, 0), Point(1 / std::sin(half), 0));
}

}  // namespace curvebench::testing
