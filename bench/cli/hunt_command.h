// `curvebench hunt -a ALGORITHM [--seconds N] [--seed S] [-o DIR] [--json]`: the defect hunt
// of bench/runner/hunt.h on the command line.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_hunt_command(CLI::App& app);

}  // namespace curvebench::cli
