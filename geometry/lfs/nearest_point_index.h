// Distance from a query point to the nearest of a fixed set of points: the distance to the
// sampled medial axis that is lfs, and to a point sampling that epsilon divides by lfs
// (survey, "Definitions and Notations").
//
// A static 2-d tree (built once; queries only read it and are thread-safe): median
// splits across the wider side of each node's points, leaves of a few points. The answer
// is exactly sqrt of the smallest CGAL::squared_distance to a point of the set, whatever
// the tree's shape: a subtree is skipped only when a lower bound on the squared distance
// of all its points, rounded the same way, provably exceeds the best found.
//
// Queries usually come in order along a curve, so the previous answer's point is a close
// guess: a thread-local record of it (per index, checked, never trusted) starts each
// search with a tight bound.
//
// Measured against the CGAL Orthogonal_k_neighbor_search it replaced (same answers, bit
// for bit): lfs at 8 points per gap of the dense sample, in order along the curve /
// shuffled, ns per query on a loaded 2-core machine:
//
//   curve           | medial points | CGAL Kd-tree | this index
//   ----------------+---------------+--------------+-----------
//   glyph 'A'       |        22176  | 2100 / 2700  |  240 / 750
//   glyph '@'       |        50646  |  610 / 1100  |  150 / 560
//   fourier:seed=7  |          539  |  180 / 225   |   80 / 165
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/kernel.h"

namespace curvebench::geometry {

// Exact nearest-point distances to a fixed point set (see above).
class Nearest_point_index {
 public:
  // Builds the tree on a copy of `points`; points with a NaN coordinate are left out.
  // Throws std::length_error for 2^32 - 1 points or more.
  explicit Nearest_point_index(std::span<const Point> points);

  // +infinity if the set is empty.
  double distance(const Point& query) const;

 private:
  struct Node {
    double min_x, min_y, max_x, max_y;  // the bounding box of its points
    std::uint32_t begin, end;           // its points, [begin, end) in tree order
    std::uint32_t right;                // the right child (the left one is the next node); 0 for a leaf
  };

  struct Coordinates {
    double x, y;
  };
  std::uint32_t build(std::vector<Coordinates>& points, std::uint32_t begin, std::uint32_t end);
  // The smallest squared distance from (x, y) to a point; `nearest` holds a guess (any
  // value) on entry and the point attaining it on exit.
  double nearest_squared_distance(double x, double y, std::uint32_t& nearest) const;

  std::vector<double> x_, y_;  // the points, in tree order
  std::vector<Node> nodes_;    // nodes_[0] is the root
  std::uint64_t id_ = 0;       // tells indexes apart for the thread-local guess
};

}  // namespace curvebench::geometry
