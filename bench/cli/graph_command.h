// `curvebench graph KIND -i POINTS -o EDGES [--beta B] [--k K] [--alpha A] [--svg PICTURE]`:
// one proximity graph of a point file.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_graph_command(CLI::App& app);

}  // namespace curvebench::cli
