// Distance from a query point to the nearest of a fixed set of points, through a CGAL
// Kd-tree (built once; queries are then thread-safe): the distance to the sampled medial
// axis that is lfs, and to a point sampling that epsilon divides by lfs (survey,
// "Definitions and Notations").
#pragma once

#include <memory>
#include <span>

#include "geometry/kernel.h"

namespace curvebench::geometry {

class Nearest_point_index {
 public:
  explicit Nearest_point_index(std::span<const Point> points);
  Nearest_point_index(Nearest_point_index&&) noexcept;
  Nearest_point_index& operator=(Nearest_point_index&&) noexcept;
  ~Nearest_point_index();

  // +infinity if the set is empty.
  double distance(const Point& query) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace curvebench::geometry
