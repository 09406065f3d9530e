#include "algorithms/registry.h"

#include <algorithm>
#include <vector>

#include "algorithms/alpha_shape.h"
#include "algorithms/beta_skeleton.h"
#include "algorithms/conservative_crust.h"
#include "algorithms/crust.h"
#include "algorithms/emst.h"
#include "algorithms/gathan.h"
#include "algorithms/gathang.h"
#include "algorithms/hnn_crust.h"
#include "algorithms/nn_crust.h"
#include "geometry/point_set.h"

namespace curvebench::algorithms {

std::span<const Algorithm> registry() {
  static const std::vector<Algorithm> algorithms{
      alpha_shape_algorithm(),
      beta_skeleton_algorithm(),
      emst_algorithm(),
      crust_algorithm(),
      nn_crust_algorithm(),
      conservative_crust_algorithm(),
      hnn_crust_algorithm(),
      gathan_algorithm(),
      gathang_algorithm(),
  };
  return algorithms;
}

const Algorithm* find_algorithm(std::string_view name) {
  const auto all = registry();
  const auto found = std::ranges::find(all, name, &Algorithm::name);
  return found == all.end() ? nullptr : &*found;
}

Reconstruction reconstruct(const Algorithm& algorithm, std::span<const Point> points, const Parameter_values& values) {
  values.check(algorithm.parameters, algorithm.name);
  const geometry::PointSet distinct(std::vector<Point>(points.begin(), points.end()));
  Reconstruction result = algorithm.reconstruct(distinct.points(), values);
  const bool own_points = !result.points.empty();
  for (Edge& edge : result.edges) {
    if (!own_points) edge = {distinct.input_index(edge.first), distinct.input_index(edge.second)};
    if (edge.first > edge.second) std::swap(edge.first, edge.second);
  }
  // Iterator algorithms, not std::ranges: clang 14 (the fuzz build) cannot compile
  // libstdc++ 12's ranges over these.
  std::sort(result.edges.begin(), result.edges.end());
  result.edges.erase(std::unique(result.edges.begin(), result.edges.end()), result.edges.end());
  return result;
}

}  // namespace curvebench::algorithms
