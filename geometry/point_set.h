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

// An input point equal to an earlier one, which it was merged into.
struct Duplicate {
  std::size_t input_index;  // the merged occurrence
  std::size_t first_input_index;  // the occurrence it was merged into
};

// Input points with exact duplicates merged (see above). Indices into points() are
// "kept" indices; indices into the input vector are "input" indices.
class PointSet {
 public:
  PointSet() = default;

  // Throws std::invalid_argument if a coordinate is NaN or infinite.
  explicit PointSet(std::vector<Point> input_points);

  // The distinct points, in order of first occurrence; valid as long as the set is.
  std::span<const Point> points() const { return points_; }
  // The number of distinct points.
  std::size_t size() const { return points_.size(); }
  // Whether there is no point (nor was any input).
  bool empty() const { return points_.empty(); }
  // The distinct point with kept index `kept` (< size(), not checked).
  const Point& operator[](std::size_t kept) const { return points_[kept]; }

  // The number of input points, duplicates included.
  std::size_t input_size() const { return kept_index_.size(); }
  // The input index of the first occurrence of distinct point `kept`.
  std::size_t input_index(std::size_t kept) const { return input_index_[kept]; }
  // The kept index of input point `input` (< input_size()): of the point it was merged
  // into if it is a duplicate.
  std::size_t kept_index(std::size_t input) const { return kept_index_[input]; }
  // Every merged input point, by increasing input index. Equal means equal coordinates:
  // -0.0 and 0.0 are one point.
  std::span<const Duplicate> duplicates() const { return duplicates_; }

 private:
  std::vector<Point> points_;
  std::vector<std::size_t> input_index_;
  std::vector<std::size_t> kept_index_;
  std::vector<Duplicate> duplicates_;
};

}  // namespace curvebench::geometry
