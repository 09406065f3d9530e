#include "geometry/lfs/curve_search.h"

#include <cmath>

namespace curvebench::geometry {
namespace {

constexpr int grid_subdivisions = 4;
constexpr int golden_iterations = 36;  // 0.618^36 < 1e-7

// Golden-section search for a maximum of f in [low, high], given f at the best grid point.
Curve_maximum golden_section(const std::function<double(double)>& f, double low, double high, Curve_maximum best) {
  const double ratio = (std::sqrt(5.0) - 1) / 2;
  double a = high - ratio * (high - low), b = low + ratio * (high - low);
  double fa = f(a), fb = f(b);
  for (int iteration = 0; iteration < golden_iterations; ++iteration) {
    if (fa < fb) {
      low = a, a = b, fa = fb;
      b = low + ratio * (high - low), fb = f(b);
    } else {
      high = b, b = a, fb = fa;
      a = high - ratio * (high - low), fa = f(a);
    }
  }
  if (fa > best.value) best = {fa, a};
  if (fb > best.value) best = {fb, b};
  return best;
}

}  // namespace

Curve_maximum maximize_along(const Local_feature_size& lfs, std::size_t component, double s0, double s1,
                             const std::function<double(double)>& f) {
  const std::vector<double> grid = lfs.grid(component, s0, s1, grid_subdivisions);
  std::vector<double> values(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) values[i] = f(grid[i]);
  Curve_maximum best{values[0], grid[0]};
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const std::size_t left = i == 0 ? 0 : i - 1, right = i + 1 < grid.size() ? i + 1 : i;
    const bool peak = values[i] >= values[left] && values[i] >= values[right] &&
                      (values[i] > values[left] || values[i] > values[right]);  // not on a plateau
    if (!peak) continue;
    best = golden_section(f, grid[left], grid[right], values[i] > best.value ? Curve_maximum{values[i], grid[i]} : best);
  }
  return best;
}

}  // namespace curvebench::geometry
