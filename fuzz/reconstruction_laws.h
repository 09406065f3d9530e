// The laws every reconstruction algorithm must keep on any input, as the fuzz targets
// check them: the built-ins' (reconstruction_fuzz.cpp) and those a program registers
// itself (registered_algorithms_fuzz.cpp, the fuzz target of curvebench_add_program).
// An input's bytes choose the parameter values; FUZZ_CHECK traps on a broken law.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "fuzz/degenerate_point_program.h"
#include "fuzz/fuzz_target.h"
#include "geometry/io/point_io.h"

namespace curvebench::fuzz {

using algorithms::Algorithm;
using algorithms::Parameter;
using algorithms::Parameter_values;

// Few enough for the quadratic algorithms to run thousands of inputs a second.
inline constexpr std::size_t max_reconstruction_points = 64;

// b = 0: unset; else from the minimum up to 16 above it (or the maximum), denser near
// the minimum where the algorithms change most.
inline Parameter_values decode_parameters(const Algorithm& algorithm, Fuzz_input& input) {
  Parameter_values values;
  for (const Parameter& parameter : algorithm.parameters) {
    const std::uint8_t b = input.byte();
    if (b == 0) continue;
    const double t = std::pow(b / 255.0, 4);
    double value = parameter.minimum + t * std::min(parameter.maximum - parameter.minimum, 16.0);
    if (parameter.type == algorithms::Parameter_type::integer) value = std::round(value);
    values.set(std::string(parameter.name), std::clamp(value, parameter.minimum, parameter.maximum));
  }
  return values;
}

inline std::string describe(const Algorithm& algorithm, const Parameter_values& values, const std::vector<Point>& points) {
  std::ostringstream out;
  out << algorithm.name << " (" << values.to_string() << ") on " << points.size() << " points:\n";
  geometry::write_points(out, points);
  return out.str();
}

inline void check_reconstruction_laws(const Algorithm& algorithm, const Parameter_values& values,
                               const std::vector<Point>& points) {
  const auto context = [&] { return describe(algorithm, values, points); };
  algorithms::Reconstruction first;
  try {
    first = algorithms::reconstruct(algorithm, points, values);
  } catch (const std::exception& error) {
    FUZZ_CHECK(false, "valid input never throws", context() + error.what() + "\n");
  }
  const std::size_t n = first.points.empty() ? points.size() : first.points.size();
  for (std::size_t k = 0; k < first.edges.size(); ++k) {
    const auto [i, j] = first.edges[k];
    FUZZ_CHECK(i < j && j < n, "every edge is a pair i < j of point indices", context());
    FUZZ_CHECK(k == 0 || first.edges[k - 1] < first.edges[k], "edges are sorted and unique", context());
    if (first.points.empty())
      for (const std::size_t end : {i, j})
        FUZZ_CHECK(std::find(points.begin(), points.end(), points[end]) == points.begin() + end,
                   "a merged duplicate gets no edge", context());
  }
  const algorithms::Reconstruction second = algorithms::reconstruct(algorithm, points, values);
  FUZZ_CHECK(first.edges == second.edges && first.points == second.points, "the same input gives the same output",
             context());
}

// Runs one fuzz input against one of `algorithms` (the first byte chooses it): decodes
// its parameter values and a degenerate point set, and checks the laws.
inline void check_reconstruction_input(std::span<const Algorithm> algorithms, Fuzz_input& input) {
  const Algorithm& algorithm = algorithms[input.byte() % algorithms.size()];
  const Parameter_values values = decode_parameters(algorithm, input);
  const std::vector<Point> points = decode_degenerate_points(input, max_reconstruction_points);
  check_reconstruction_laws(algorithm, values, points);
}

}  // namespace curvebench::fuzz
