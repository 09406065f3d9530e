// The `curvebench` command line, every verb of it, as one call: the `curvebench` program
// is this and nothing else, and so is a program built on the installed library around
// one's own algorithms (curvebench_add_program; docs/own-algorithm.md), where they stand
// beside the built-ins.
#pragma once

namespace curvebench::cli {

// Parses `argv` as `curvebench` does and runs the verb it names; returns the exit status
// (0 success, 1 a failed check, 2 a usage or input error). Prints errors to stderr.
int run_command_line(int argc, char** argv);

}  // namespace curvebench::cli
