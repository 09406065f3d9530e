// The naive NN-Crust of ../cpp/naive_nn_crust.h, registered in-process: the same code that
// ../cpp/naive_nn_crust.cpp runs behind `exec:`, here called with the points in memory, so
// that every verb (run, certify, tightness, hunt, ...) calls it without a process start.
// Its rows in results.csv equal the exec: program's, runtimes aside.
#include <span>
#include <vector>

#include "../cpp/naive_nn_crust.h"
#include "algorithms/registry.h"

namespace {

using namespace curvebench;

const algorithms::Parameter half_angle{
    .name = "half_angle", .default_value = 90, .minimum = 0, .maximum = 180,
    .meaning = "degrees between the nearest neighbour and the half neighbour (90 in the paper)"};

// The registry has merged exact duplicates already, and checked the parameter's range.
std::vector<geometry::Edge> naive_nn_crust(std::span<const geometry::Point> points,
                                           const algorithms::Parameter_values& values) {
  std::vector<naive::Point> xy;
  xy.reserve(points.size());
  for (const geometry::Point& p : points) xy.push_back({p.x(), p.y()});
  std::vector<geometry::Edge> edges;
  for (const auto& [i, j] : naive::nn_crust(xy, values[half_angle])) edges.emplace_back(i, j);
  return edges;
}

const algorithms::Registration registration{{
    .name = "naive-nn-crust",
    .title = "naive NN-Crust (C++, in-process)",
    .reference = "Dey and Kumar 1999",
    .category = "Feature Size Criteria",
    .parameters = {half_angle},
    .capabilities = {.manifold = algorithms::Support::yes, .guarantee = true, .time_complexity = "O(n^2)"},
    .condition = {.statement = "epsilon < 1/3, as NN-Crust's theorem", .epsilon_below = 1.0 / 3},
    .reconstruct = algorithms::edges_on_input(naive_nn_crust),
}};

}  // namespace
