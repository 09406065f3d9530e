// `curvebench rate`: the exact-reconstruction rate of every registered algorithm over
// many curves, each safe-epsilon-sampled at several epsilons (issue "Reconstruction
// algorithms I": the glyph table). A sample counts as reconstructed exactly when the
// algorithm's edge set equals the sampler's ground truth.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_rate_command(CLI::App& app);

}  // namespace curvebench::cli
