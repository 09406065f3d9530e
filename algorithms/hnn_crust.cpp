#include "algorithms/hnn_crust.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "algorithms/nn_crust.h"

namespace curvebench::algorithms {

std::vector<Edge> hnn_crust_reconstruction(std::span<const Point> points) {
  const std::vector<Nearest_and_half_neighbor> neighbors =
      nearest_and_half_neighbors(points, Half_plane::beyond_bisector);
  const auto chose = [&](std::uint32_t i, std::uint32_t j) {
    return neighbors[i].nearest == j || neighbors[i].half == j;
  };
  // Emitted at the smaller end, in increasing order of both ends: already canonical.
  std::vector<Edge> edges;
  edges.reserve(points.size());
  for (std::uint32_t i = 0; i < neighbors.size(); ++i) {
    std::uint32_t a = neighbors[i].nearest, b = neighbors[i].half;
    if (a > b) std::swap(a, b);
    for (const std::uint32_t j : {a, b})
      if (j != no_neighbor && i < j && chose(j, i)) edges.emplace_back(i, j);
  }
  return edges;
}

Algorithm hnn_crust_algorithm() {
  return {
      .name = "hnn-crust",
      .title = "HNN-Crust",
      .reference = "Ohrhallinger, Mitchell, Wimmer 2016",
      .category = "Feature Size Criteria",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::yes, .open = Support::yes,
                       .multiple = Support::yes, .guarantee = true, .time_complexity = "O(n log n)"},
      .condition = {.statement = "epsilon < 0.47 (rho < 0.9)", .epsilon_below = 0.47, .rho_below = 0.9,
                    .corner_angle_above = {}},
      .reconstruct = edges_on_input(hnn_crust_reconstruction),
  };
}

}  // namespace curvebench::algorithms
