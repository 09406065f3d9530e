#include "geometry/lfs/curve_projection.h"

#include <cmath>

#include "geometry/lfs/curve_search.h"

namespace curvebench::geometry {

Curve_location nearest_curve_location(const Local_feature_size& lfs, const Point& p) {
  Curve_location nearest;
  double best = -std::numeric_limits<double>::infinity();
  const auto& components = lfs.curve().components;
  for (std::size_t c = 0; c < components.size(); ++c) {
    const auto& component = components[c];
    const double end = static_cast<double>(component.piece_count());
    const Curve_maximum found = maximize_along(
        lfs, c, 0, end, [&](double s) { return -CGAL::squared_distance(component.point(s), p); });
    if (found.value > best) {
      best = found.value;
      nearest = {c, component.closed() ? std::fmod(found.parameter, end) : found.parameter};
    }
  }
  return nearest;
}

}  // namespace curvebench::geometry
