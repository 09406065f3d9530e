// How every command that runs algorithms names them: registered names, exec:COMMAND, and
// the names a file of external algorithms declares (--algorithm-file FILE).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "algorithms/algorithm.h"

namespace curvebench::cli {

// --algorithm-file FILE (given once or more): its algorithms are declared as the option is parsed,
// so that -a finds them by name wherever it stands on the line.
void add_algorithm_file_option(CLI::App* command);

// NAME,NAME,... split at commas, but an exec:COMMAND whole: a command line may hold commas.
std::vector<std::string> algorithm_names(const std::vector<std::string>& given);

// One algorithm, `-a NAME` (nn_crust names nn-crust too).
const algorithms::Algorithm& chosen_algorithm(const std::string& name);

}  // namespace curvebench::cli
