// `curvebench annotate -i POINTS [-e EDGES] -o DIR`: writes DIR/STEM.annotate.html, a
// self-contained page (bench/annotate/annotate.html) in which a person draws a ground truth
// by clicking the points in order, and saves it as an edge file that `evaluate`, `measure`
// and `run` (`truth:` inputs) read.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_annotate_command(CLI::App& app);

}  // namespace curvebench::cli
