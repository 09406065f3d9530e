// A planar point set as the rest of curvebench sees it: distinct points, with the
// bookkeeping that lets every output still name the points of the input.
//
// Policy for exact duplicates (same x and same y): the first occurrence is kept, later
// ones are merged into it. `points()` lists the kept points in order of first
// occurrence; `input_index(k)` and `kept_index(i)` translate between the two numberings.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "geometry/kernel.h"

namespace curvebench::geometry {

struct Duplicate {
  std::size_t input_index;  // the merged occurrence
  std::size_t first_input_index;  // the occurrence it was merged into
};

class PointSet {
 public:
  PointSet() = default;

  // Throws std::invalid_argument if a coordinate is NaN or infinite.
  explicit PointSet(std::vector<Point> input_points);

  std::span<const Point> points() const { return points_; }
  std::size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }
  const Point& operator[](std::size_t kept) const { return points_[kept]; }

  std::size_t input_size() const { return kept_index_.size(); }
  std::size_t input_index(std::size_t kept) const { return input_index_[kept]; }
  std::size_t kept_index(std::size_t input) const { return kept_index_[input]; }
  std::span<const Duplicate> duplicates() const { return duplicates_; }

 private:
  std::vector<Point> points_;
  std::vector<std::size_t> input_index_;
  std::vector<std::size_t> kept_index_;
  std::vector<Duplicate> duplicates_;
};

}  // namespace curvebench::geometry
