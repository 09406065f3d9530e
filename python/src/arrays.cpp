#include "arrays.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace curvebench::python {
namespace py = pybind11;
namespace {

// A Point is read as two doubles in place: CGAL's Epick point holds exactly that.
static_assert(sizeof(geometry::Point) == 2 * sizeof(double) && alignof(geometry::Point) == alignof(double));
// An Edge is handed to numpy as two int64.
static_assert(sizeof(geometry::Edge) == 2 * sizeof(std::int64_t) && sizeof(std::size_t) == sizeof(std::int64_t));

std::string shape_of(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) text += (d ? ", " : "") + std::to_string(array.shape(d));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// np.asarray(given), or std::invalid_argument naming `what`.
py::array as_array(py::handle given, const char* what) {
  py::array array = py::array::ensure(given);
  if (!array) throw std::invalid_argument(std::string(what) + ": not an array of numbers");
  return array;
}

}  // namespace

Point_argument::Point_argument(py::handle given, const char* what) {
  py::array array = as_array(given, what);
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw std::invalid_argument(std::string(what) + ": real coordinates, not dtype " +
                                std::string(py::str(array.dtype())));
  if (array.ndim() != 2 || array.shape(1) != 2)
    throw std::invalid_argument(std::string(what) + ": an (n, 2) array of coordinates, not shape " + shape_of(array));
  // No copy for a C-contiguous float64 array: forcecast copies only what must change.
  array_ = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!array_) throw py::error_already_set();
  const auto* data = static_cast<const double*>(array_.data());
  const auto n = static_cast<std::size_t>(array_.shape(0));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(data[2 * i]) || !std::isfinite(data[2 * i + 1]))
      throw std::invalid_argument(std::string(what) + ": point " + std::to_string(i) + " has a non-finite coordinate");
  points_ = {reinterpret_cast<const geometry::Point*>(data), n};
}

std::vector<geometry::Edge> edge_argument(py::handle given, std::size_t points, const char* what) {
  py::array array = as_array(given, what);
  if (array.size() == 0) return {};
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw std::invalid_argument(std::string(what) + ": integer indices, not dtype " + std::string(py::str(array.dtype())));
  if (array.ndim() != 2 || array.shape(1) != 2)
    throw std::invalid_argument(std::string(what) + ": an (m, 2) array of indices, not shape " + shape_of(array));
  const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!indices) throw py::error_already_set();
  const std::int64_t* data = indices.data();
  std::vector<geometry::Edge> edges;
  for (py::ssize_t k = 0; k < indices.shape(0); ++k) {
    const std::int64_t i = data[2 * k], j = data[2 * k + 1];
    for (const std::int64_t index : {i, j})
      if (index < 0 || static_cast<std::uint64_t>(index) >= points)
        throw std::invalid_argument(std::string(what) + "[" + std::to_string(k) + "]: index " + std::to_string(index) +
                                    " out of range (" + std::to_string(points) + " points)");
    edges.emplace_back(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
  }
  return edges;
}

py::array_t<std::int64_t> edge_array(std::vector<geometry::Edge> edges) {
  auto* owned = new std::vector<geometry::Edge>(std::move(edges));
  const py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<geometry::Edge>*>(p); });
  return py::array_t<std::int64_t>({static_cast<py::ssize_t>(owned->size()), py::ssize_t{2}},
                                   reinterpret_cast<const std::int64_t*>(owned->data()), owner);
}

py::array_t<double> point_array(std::vector<geometry::Point> points) {
  auto* owned = new std::vector<geometry::Point>(std::move(points));
  const py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<geometry::Point>*>(p); });
  return py::array_t<double>({static_cast<py::ssize_t>(owned->size()), py::ssize_t{2}},
                             reinterpret_cast<const double*>(owned->data()), owner);
}

}  // namespace curvebench::python
