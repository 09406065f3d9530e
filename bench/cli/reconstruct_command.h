// `curvebench reconstruct`: run one registered algorithm on a point file.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_reconstruct_command(CLI::App& app);

}  // namespace curvebench::cli
