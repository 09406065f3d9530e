// `curvebench list [algorithms|graphs|suites] [--names]`: what the tool can run, as a table for
// people or one name per line for scripts.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_list_command(CLI::App& app);

}  // namespace curvebench::cli
