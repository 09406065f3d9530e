#include "geometry/curves/corner_curve.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/curves/curve_name.h"

namespace curvebench::geometry {

Curve sharp_corner_curve(double opening_angle_degrees) {
  if (!(opening_angle_degrees > 0 && opening_angle_degrees < 180))
    throw std::invalid_argument("corner: angle must be between 0 and 180 degrees, not " +
                                format_number(opening_angle_degrees));
  const double opening = opening_angle_degrees * std::numbers::pi / 180;
  const Point apex(1 / std::sin(opening / 2), 0);
  // The radius to a tangent point is perpendicular to the tangent line: it makes the
  // angle 90° - opening / 2 with the axis through the apex.
  const double tangent_angle = std::numbers::pi / 2 - opening / 2;
  const auto arc = std::make_shared<Circular_arc>(CGAL::ORIGIN, 1, tangent_angle, 2 * std::numbers::pi - 2 * tangent_angle);
  std::vector<std::shared_ptr<const Curve_piece>> pieces{std::make_shared<Line_segment>(apex, arc->point(0)), arc,
                                                         std::make_shared<Line_segment>(arc->point(1), apex)};
  Curve curve{"corner:angle=" + format_number(opening_angle_degrees), {}};
  curve.components.emplace_back(std::move(pieces), true);
  return curve;
}

}  // namespace curvebench::geometry
