#include "geometry/point_set.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace curvebench::geometry {

PointSet::PointSet(std::vector<Point> input_points) {
  const std::size_t n = input_points.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(input_points[i].x()) || !std::isfinite(input_points[i].y())) {
      throw std::invalid_argument("PointSet: input point " + std::to_string(i) +
                                  " has a non-finite coordinate");
    }
  }

  // Equal points end up adjacent, each run in input order, so a run's first element is
  // the first occurrence. Comparing with < (not by bits) makes -0.0 and 0.0 one point.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::ranges::stable_sort(order, [&](std::size_t a, std::size_t b) {
    const Point& p = input_points[a];
    const Point& q = input_points[b];
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  std::vector<std::size_t> first_occurrence(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    const bool starts_run = k == 0 || input_points[order[k - 1]] != input_points[i];
    first_occurrence[i] = starts_run ? i : first_occurrence[order[k - 1]];
  }

  // First occurrences precede their duplicates, so one pass in input order numbers the
  // kept points by first occurrence and lists duplicates sorted by input index.
  kept_index_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t first = first_occurrence[i];
    if (first == i) {
      kept_index_[i] = points_.size();
      points_.push_back(input_points[i]);
      input_index_.push_back(i);
    } else {
      kept_index_[i] = kept_index_[first];
      duplicates_.push_back({.input_index = i, .first_input_index = first});
    }
  }
}

}  // namespace curvebench::geometry
