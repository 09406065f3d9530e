// Point and edge sets between numpy and curvebench: a point set is an (n, 2) float64 array
// (geometry::Point is two doubles, so a C-contiguous float64 array is read in place), an
// edge set an (m, 2) int64 array (a result's edges are handed over, not copied).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::python {

// Points read from any (n, 2) array-like of real numbers: in place when it is a
// C-contiguous float64 array, else from a float64 copy that this object keeps. Throws
// std::invalid_argument, naming `what`, for another shape or type, or a coordinate that is
// NaN or infinite.
class Point_argument {
 public:
  Point_argument(pybind11::handle given, const char* what);
  // The points; valid while this object lives.
  std::span<const geometry::Point> points() const { return points_; }
  // The array they are read from: the given one when it needed no copy.
  const pybind11::array& array() const { return array_; }

 private:
  pybind11::array array_;
  std::span<const geometry::Point> points_;
};

// Edges from any (m, 2) array-like of integers (an empty sequence is no edges), each
// index below `points`. Throws std::invalid_argument naming `what` otherwise.
std::vector<geometry::Edge> edge_argument(pybind11::handle given, std::size_t points, const char* what);

// `edges` as an (m, 2) int64 array that owns their memory (no copy).
pybind11::array_t<std::int64_t> edge_array(std::vector<geometry::Edge> edges);

// `points` as an (n, 2) float64 array that owns their memory (no copy).
pybind11::array_t<double> point_array(std::vector<geometry::Point> points);

}  // namespace curvebench::python
