// `curvebench rasterize` and `curvebench image-sample`: the survey's discrete sampling
// tool ("Sampling Tools": boundary pixels of a white-on-black image, thinned by erasing
// discs of radius r around randomly picked ones), on netpbm images or on curves
// rasterized here, with a ground truth in the order the boundary passes the samples.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_rasterize_command(CLI::App& app);
void add_image_sample_command(CLI::App& app);

}  // namespace curvebench::cli
