// libFuzzer target for algorithms/: every registered reconstruction algorithm on a small,
// deliberately degenerate point set with duplicates (cocircular and collinear runs,
// 1-ulp moves, extreme scales; degenerate_point_program.h), through the registry's
// reconstruct() as the command line calls it. Laws: no exception for valid parameters,
// edges canonical and between input points, none at a merged duplicate, and the same
// edges on a second run (for a repeatable algorithm).
//
// Input: one byte choosing the algorithm (index modulo the registry's size), one byte
// per parameter (0: its default; else a value spread over its range), then a point program.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "algorithms/registry.h"
#include "fuzz/degenerate_point_program.h"
#include "fuzz/fuzz_target.h"
#include "geometry/io/point_io.h"

// CGAL 5.5's optimal-transport reconstruction leaks a few allocations (fixed in CGAL
// 5.6); LeakSanitizer reads this list in the fuzz build, and nothing else does.
extern "C" const char* __lsan_default_suppressions() { return "leak:Optimal_transportation_reconstruction_2\n"; }

namespace curvebench::fuzz {
namespace {

using algorithms::Algorithm;
using algorithms::Parameter;
using algorithms::Parameter_values;

constexpr std::size_t max_points = 64;

// b = 0: unset; else from the minimum up to 16 above it (or the maximum), denser near
// the minimum where the algorithms change most.
Parameter_values decode_parameters(const Algorithm& algorithm, Fuzz_input& input) {
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

std::string describe(const Algorithm& algorithm, const Parameter_values& values, const std::vector<Point>& points) {
  std::ostringstream out;
  out << algorithm.name << " (" << values.to_string() << ") on " << points.size() << " points:\n";
  geometry::write_points(out, points);
  return out.str();
}

void check_reconstruction_laws(const Algorithm& algorithm, const Parameter_values& values,
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
  if (!algorithm.repeatable) return;
  const algorithms::Reconstruction second = algorithms::reconstruct(algorithm, points, values);
  FUZZ_CHECK(first.edges == second.edges && first.points == second.points, "the same input gives the same output",
             context());
}

}  // namespace
}  // namespace curvebench::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvebench;
  fuzz::Fuzz_input input(data, size);
  const auto registry = algorithms::registry();
  const algorithms::Algorithm& algorithm = registry[input.byte() % registry.size()];
  const algorithms::Parameter_values values = fuzz::decode_parameters(algorithm, input);
  const std::vector<geometry::Point> points = fuzz::decode_degenerate_points(input, fuzz::max_points);
  fuzz::check_reconstruction_laws(algorithm, values, points);
  return 0;
}
