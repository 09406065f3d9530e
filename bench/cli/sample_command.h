// `curvebench sample --curve SPEC (--epsilon E [--safe] | --rho R | --uniform N | --random N) -o BASE`:
// points with ground truth and lfs from a curve source.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_sample_command(CLI::App& app);

}  // namespace curvebench::cli
