// `curvebench noise` and `curvebench outliers`: the survey's noise and outlier models
// ("Robustness to Noise", "Outliers") applied to a point file, e.g. one that
// `curvebench sample` wrote; the ground truth beside it (BASE.edges) is carried along.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_noise_command(CLI::App& app);
void add_outliers_command(CLI::App& app);

}  // namespace curvebench::cli
