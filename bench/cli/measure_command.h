// `curvebench measure --curve SPEC -i POINTS [-e EDGES]`: how well a point set samples a
// curve, as JSON: epsilon, rho and local uniformity, each with where it is attained.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_measure_command(CLI::App& app);

}  // namespace curvebench::cli
