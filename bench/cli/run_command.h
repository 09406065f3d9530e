// `curvebench run SUITE -o DIR ...`, `curvebench merge -o DIR SHARD_DIR...` and
// `curvebench report DIR`: the benchmark runner (bench/runner/run.h) on the command line.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_run_commands(CLI::App& app);

}  // namespace curvebench::cli
