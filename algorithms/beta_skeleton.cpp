#include "algorithms/beta_skeleton.h"

#include "graphs/beta_skeleton.h"

namespace curvebench::algorithms {

std::vector<Edge> beta_skeleton_reconstruction(std::span<const Point> points, double beta) {
  return graphs::edge_list(graphs::beta_skeleton(points, beta, graphs::Beta_region::lune));
}

Algorithm beta_skeleton_algorithm() {
  static const Parameter beta{.name = "beta", .default_value = 1.7, .minimum = 1, .maximum = 1e6,
                              .meaning = "lune size: 1 = Gabriel graph, 2 = relative neighbourhood graph"};
  return {
      .name = "beta-skeleton",
      .title = "beta-skeleton",
      .reference = "Kirkpatrick, Radke 1985",
      .category = "Graph Based",
      .parameters = {beta},
      .capabilities = {.non_uniform = Support::yes, .multiple = Support::yes, .sharp = Support::yes,
                       .time_complexity = "O(n log n)"},
      .condition = {.statement = "none"},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        return beta_skeleton_reconstruction(points, values[beta]);
      }),
  };
}

}  // namespace curvebench::algorithms
