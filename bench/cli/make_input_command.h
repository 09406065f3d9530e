// `curvebench make-input NAME -o BASE`: writes the input of a benchmark job, named as in
// results.csv's `input` column (bench/runner/bench_input.h), to BASE.xy and, when it has a
// ground truth, BASE.edges: bit for bit the points the job ran on, so that one row of a
// run can be replayed with `reconstruct` and `evaluate` (the explorer's replay command).
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_make_input_command(CLI::App& app);

}  // namespace curvebench::cli
