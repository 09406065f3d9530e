// Algorithms that are programs (issue "Bring your own algorithm"): any program that reads
// a point file and writes an edge file becomes an algorithm of every command, named
//
//   exec:COMMAND   e.g.  exec:python3 my_recon.py {points} {edges}
//
// COMMAND is a /bin/sh command line with placeholders, each replaced by a quoted path in a
// fresh temporary directory:
//   {points}      the input, written by curvebench: "x y" per line, each number the shortest
//                 decimal that reads back to the same double, exact duplicates merged (as
//                 every built-in algorithm gets them)
//   {edges}       the output the program writes: "i j" per line, 0-based indices
//   {points_out}  optional: points the program writes ("x y" per line) and {edges} indexes,
//                 for an algorithm that moves or drops points
// The output is read by the project's own edge and point readers (geometry/io), and the
// edges checked as a ground truth's are: a missing file, a malformed line, an index out of
// range or a self-loop throws Invalid_output naming "edges:LINE" (status `invalid-output`
// in a run). A
// program killed by a signal (or exiting with 128 + its number, as a shell reports a killed
// child) throws Program_crashed (`crashed`); another non-zero exit status is a plain failure
// (`failed`) with the first line the program wrote to stderr. A program dies with the
// process that runs it, so a run's timeout stops it too.
#pragma once

#include <stdexcept>
#include <string_view>

#include "algorithms/algorithm.h"

namespace curvebench::bench {

struct Invalid_output : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct Program_crashed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr std::string_view external_prefix = "exec:";

// The registered algorithm of that name, or the external one an exec: name declares (made
// once, kept for the life of the process); nullptr for an unknown registered name. Throws
// std::invalid_argument for a bad declaration: an unknown placeholder, no {points} or no
// {edges}, or a program that does not exist.
const algorithms::Algorithm* find_any_algorithm(std::string_view name);

}  // namespace curvebench::bench
