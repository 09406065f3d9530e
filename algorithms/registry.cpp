#include "algorithms/registry.h"

#include <algorithm>
#include <vector>

#include "algorithms/alpha_shape.h"
#include "algorithms/beta_skeleton.h"
#include "algorithms/conservative_crust.h"
#include "algorithms/crawl.h"
#include "algorithms/crust.h"
#include "algorithms/emst.h"
#include "algorithms/gathan.h"
#include "algorithms/gathang.h"
#include "algorithms/hnn_crust.h"
#include "algorithms/nn_crust.h"
#include "algorithms/peel.h"
#include "algorithms/shape_hull.h"
#include "geometry/point_set.h"

namespace curvebench::algorithms {

std::span<const Algorithm> registry() {
  static const std::vector<Algorithm> algorithms{
      alpha_shape_algorithm(),
      beta_skeleton_algorithm(),
      emst_algorithm(),
      shape_hull_algorithm(),
      crawl_algorithm(),
      crust_algorithm(),
      nn_crust_algorithm(),
      conservative_crust_algorithm(),
      hnn_crust_algorithm(),
      gathan_algorithm(),
      gathang_algorithm(),
      peel_algorithm(),
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
  if (result.points.empty())  // the edges index the distinct points: name the input's
    for (Edge& edge : result.edges) edge = {distinct.input_index(edge.first), distinct.input_index(edge.second)};
  result.edges = geometry::canonical_edges(std::move(result.edges));
  return result;
}

}  // namespace curvebench::algorithms
