// `curvebench certify -a ALGORITHM ...`: a sampling-condition theorem checked on generated
// curves, with shrunk counterexamples (bench/runner/certification.h).
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench::cli {

void add_certify_command(CLI::App& app);

}  // namespace curvebench::cli
