#include "algorithms/conservative_crust.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using graphs::no_vertex;

// True if the circle through p, q and apex l has radius >= |pq| / (2 rho), for an apex
// angle below 90 degrees: sin(angle plq) <= rho.
bool apex_circle_is_large(const Point& p, const Point& q, const Point& l, double rho) {
  using geometry::cross, geometry::difference, geometry::squared_length;
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
           const auto u = difference<NT>(p, l), v = difference<NT>(q, l);
           const NT r(rho), c = cross(u, v);
           return r * r * squared_length(u) * squared_length(v) - c * c;
         }) != CGAL::NEGATIVE;
}

}  // namespace

std::vector<Edge> conservative_crust_reconstruction(std::span<const Point> points, double rho) {
  if (!(rho >= 0 && rho <= 1)) throw std::invalid_argument("conservative crust: rho must lie in [0, 1]");
  const graphs::Delaunay_triangulation dt(points);
  std::vector<Edge> edges;
  for (const graphs::Delaunay_edge& e : dt.edges()) {
    const Point& p = dt.point(e.source);
    const Point& q = dt.point(e.target);
    bool gabriel = true, reaches_far = false;
    for (const graphs::Vertex apex : {e.left, e.right}) {
      if (apex == no_vertex) {
        reaches_far = true;  // an unbounded Voronoi ray (hull edge, or collinear points)
        continue;
      }
      if (graphs::blocks(p, q, dt.point(apex), 1, graphs::Beta_region::lune)) {
        gabriel = false;
        break;
      }
      reaches_far = reaches_far || apex_circle_is_large(p, q, dt.point(apex), rho);
    }
    if (gabriel && reaches_far) edges.emplace_back(e.source, e.target);
  }
  std::ranges::sort(edges);
  return edges;
}

Algorithm conservative_crust_algorithm() {
  static const Parameter rho{.name = "rho",
                             .default_value = default_conservative_crust_rho,
                             .minimum = 0,
                             .maximum = 1,
                             .meaning = "keep a Gabriel edge pq if an empty circle of radius >= |pq|/(2 rho) passes "
                                        "through p and q: 1 = Gabriel graph, smaller = more conservative"};
  return {
      .name = "conservative-crust",
      .title = "Conservative Crust",
      .reference = "Dey, Mehlhorn, Ramos 1999",
      .category = "Feature Size Criteria",
      .parameters = {rho},
      .capabilities = {.non_uniform = Support::yes, .outliers = Support::yes, .open = Support::yes,
                       .multiple = Support::yes, .guarantee = true, .time_complexity = "O(n log n)"},
      // The one guarantee the survey extends to curves with ends ("Feature Size Criteria
      // Reconstruction": it reconstructs "collections of closed and open curves").
      .condition = {.statement = "epsilon < 0.0625", .epsilon_below = 0.0625,
                    .rho_below = {}, .corner_angle_above = {}, .uniformity_below = {}, .covers_open_curves = true},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        return conservative_crust_reconstruction(points, values[rho]);
      }),
  };
}

}  // namespace curvebench::algorithms
