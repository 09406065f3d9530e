// `curvebench evaluate -i POINTS -e EDGES -g GROUND_TRUTH_EDGES [--curve SPEC]`: the
// benchmark's metrics (bench/runner/evaluation.h) of one reconstruction, as JSON.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_evaluate_command(CLI::App& app);

}  // namespace curvebench::cli
