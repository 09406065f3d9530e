#include "algorithms/vicur.h"

#include "algorithms/discur.h"

namespace curvebench::algorithms {

std::vector<Edge> vicur_reconstruction(std::span<const Point> points, double proximity_ratio, double turning_angle,
                                       double corner_ratio, int closing_rank) {
  return grow_curves(points, {.proximity_ratio = proximity_ratio,
                              .closing_rank = closing_rank,
                              .turning_angle_degrees = turning_angle,
                              .corner_ratio = corner_ratio});
}

Algorithm vicur_algorithm() {
  static const Parameter proximity_ratio{
      .name = "proximity_ratio", .default_value = default_vicur_proximity_ratio, .minimum = 1, .maximum = 100,
      .meaning = "an edge at a path end joins if at most this times the path's longest edge"};
  static const Parameter turning_angle{
      .name = "turning_angle", .default_value = default_vicur_turning_angle, .minimum = 0, .maximum = 180,
      .meaning = "degrees; a sharper turn at a path end is a corner (180: no continuation rule)"};
  static const Parameter corner_ratio{
      .name = "corner_ratio", .default_value = default_vicur_corner_ratio, .minimum = 0.01, .maximum = 100,
      .meaning = "a corner edge joins only if at most this times the path's end edge"};
  static const Parameter closing_rank{
      .name = "closing_rank", .type = Parameter_type::integer, .default_value = default_vicur_closing_rank,
      .minimum = 1, .maximum = 64, .meaning = "a path closes if its ends are among each other's k nearest"};
  return {
      .name = "vicur",
      .title = "VICUR",
      .reference = "Nguyen, Zeng 2008",
      .category = "HVS Based",
      .parameters = {proximity_ratio, turning_angle, corner_ratio, closing_rank},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::yes, .open = Support::yes,
                       .multiple = Support::yes, .sharp = Support::yes, .guarantee = false,
                       .time_complexity = "O(n log n)"},
      .condition = {.statement = "none"},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        return vicur_reconstruction(points, values[proximity_ratio], values[turning_angle], values[corner_ratio],
                                    static_cast<int>(values[closing_rank]));
      }),
  };
}

}  // namespace curvebench::algorithms
