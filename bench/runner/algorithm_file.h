// A file of named external algorithms (`--algorithm-file FILE`): what `exec:COMMAND` cannot
// say on a command line, each program's name, formats, parameters, timeout and claimed
// sampling condition (external_algorithm.h), so that `certify` and `hunt` can check the claim.
//
//   {"algorithms": [
//     {"name": "naive-nn-crust",                     required: the name for -a
//      "command": "python3 {dir}/nn.py {points} {edges} {k}",  required: a /bin/sh command
//                                                    line; {dir} is this file's directory
//      "title": "Naive NN-Crust",                    the name in reports (default: name)
//      "input_format": "xy",                         xy ("x y" lines) or csv (an "x,y" header, "x,y" lines)
//      "index_base": 0,                              the program numbers points from 0 or 1
//      "parameters": [{"name": "k", "type": "integer", "default": 2, "min": 1, "max": 8,
//                      "meaning": "neighbours looked at"}],   substituted as {k}
//      "timeout": 30,                                seconds per run of the program
//      "condition": {"statement": "epsilon < 1/3", "epsilon_below": 0.3333,
//                    "uniformity_below": 1.609, "rho_below": 0.9}}
//   ]}
//
// Every key is checked: an unknown one, a wrong type or a missing name or command is an
// error naming the file and the algorithm, before anything runs. No key declares that
// an algorithm may give different output for the same input: every algorithm must not,
// and the key that once said so is refused with that reason.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "algorithms/algorithm.h"
#include "bench/runner/external_algorithm.h"

namespace curvebench::bench {

// The declarations of a file's text; `file` names it in messages. Throws std::invalid_argument.
std::vector<External_declaration> parse_algorithm_file(std::string_view text, std::string_view file);

// Reads the file and declares each of its algorithms (declare_external_algorithm), so that
// every command finds them by name. Throws std::invalid_argument naming the file: unreadable,
// not JSON, a bad declaration.
std::vector<const algorithms::Algorithm*> load_algorithm_file(const std::filesystem::path& file);

}  // namespace curvebench::bench
