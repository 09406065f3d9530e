#include "algorithms/alpha_shape.h"

#include "graphs/alpha_shape_boundary.h"
#include "graphs/proximity_graph.h"

namespace curvebench::algorithms {

std::vector<Edge> alpha_shape_reconstruction(std::span<const Point> points, std::optional<double> alpha) {
  const graphs::Delaunay_triangulation dt(points);
  return graphs::edge_list(graphs::alpha_shape_boundary(dt, alpha ? *alpha : graphs::connecting_alpha(dt)));
}

Algorithm alpha_shape_algorithm() {
  static const Parameter alpha{.name = "alpha", .default_value = 0, .minimum = 0, .maximum = 1e300,
                               .meaning = "squared radius of the eraser disk; 0 = smallest connecting alpha"};
  return {
      .name = "alpha-shape",
      .title = "alpha-Shapes",
      .reference = "Edelsbrunner, Kirkpatrick, Seidel 1983",
      .category = "Graph Based",
      .parameters = {alpha},
      .capabilities = {.manifold = Support::yes, .multiple = Support::yes, .guarantee = true,
                       .time_complexity = "O(n log n)"},
      // Proven for uniform samplings whose spacing is small against the curve's reach
      // (Bernardini, Bajaj 1997); no epsilon bound.
      .condition = {.statement = "uniform sampling denser than alpha"},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        const double value = values[alpha];
        return alpha_shape_reconstruction(points, value > 0 ? std::optional(value) : std::nullopt);
      }),
  };
}

}  // namespace curvebench::algorithms
