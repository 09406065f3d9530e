// Every reconstruction algorithm by name: the table that the command line, the
// benchmarks, the fuzzer and the certifier iterate. Adding an algorithm is one file
// pair (its function and its Algorithm description) and one entry in registry.cpp.
#pragma once

#include <span>
#include <string_view>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// In the survey's order of Table 1.
std::span<const Algorithm> registry();

// A registered algorithm behind the outlier pre-filter: "nn-crust+outlier-filter".
inline constexpr std::string_view outlier_filter_suffix = "+outlier-filter";

// nullptr if no algorithm has that name. NAME+outlier-filter is NAME behind the outlier
// pre-filter (outlier_filter.h), for any registered NAME.
const Algorithm* find_algorithm(std::string_view name);

// Runs `algorithm` on any point list: checks the parameters, merges exact duplicates
// into their first occurrence (which alone gets edges; geometry::PointSet) and returns
// edges between input indices, sorted. Throws std::invalid_argument for a bad parameter
// or a non-finite coordinate.
Reconstruction reconstruct(const Algorithm& algorithm, std::span<const Point> points,
                           const Parameter_values& values = {});

}  // namespace curvebench::algorithms
