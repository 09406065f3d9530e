// `curvebench ambiguity [--count N] [--points N] [--seed S] [--out DIR] [--json]`: the
// ambiguity hunt (certify/ambiguity_search.h): point sets that are epsilon-samplings of two
// smooth simple closed curves with different polygons, the smallest max epsilon found
// written as a self-contained directory (points, both ground truths, both curves as SVG,
// a picture, summary.json and a replay script for `curvebench measure`).
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_ambiguity_command(CLI::App& app);

}  // namespace curvebench::cli
