// Algorithms that are programs (issue "Bring your own algorithm"): any program that reads
// a point file and writes an edge file becomes an algorithm of every command, named
//
//   exec:COMMAND   e.g.  exec:python3 my_recon.py {points} {edges}
//
// or by the name a file of named algorithms gives it (algorithm_file.h, `--algorithms FILE`).
//
// COMMAND is a /bin/sh command line with placeholders, each replaced by a quoted path in a
// fresh temporary directory:
//   {points}      the input, written by curvebench: "x y" per line, each number the shortest
//                 decimal that reads back to the same double, exact duplicates merged (as
//                 every built-in algorithm gets them)
//   {edges}       the output the program writes: "i j" per line, 0-based indices
//   {points_out}  optional: points the program writes ("x y" per line) and {edges} indexes,
//                 for an algorithm that moves or drops points
//   {NAME}        a declared parameter's value
// The output is read by the project's own edge and point readers (geometry/io), and the
// edges checked as a ground truth's are: a missing file, a malformed line, an index out of
// range or a self-loop throws Invalid_output naming "edges:LINE" (status `invalid-output`
// in a run). A program killed by a signal (or exiting with 128 + its number, as a shell
// reports a killed child) throws Program_crashed (`crashed`), one past its declared timeout
// Program_timed_out (`timeout`); another non-zero exit status is a plain failure (`failed`)
// with the last line the program wrote to stderr. A program dies with the process that
// runs it, so a run's own timeout stops it too.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::bench {

// The program's output is missing or malformed (status `invalid-output`).
struct Invalid_output : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// The program was killed by a signal (status `crashed`).
struct Program_crashed : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// The program ran past its declared timeout and was killed (status `timeout`).
struct Program_timed_out : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The prefix of an algorithm name that is a command: exec:COMMAND.
inline constexpr std::string_view external_prefix = "exec:";

// A parameter of a program, substituted into its command as {NAME}: its value, or the
// default, as the shortest decimal (an integer parameter as an integer).
struct External_parameter {
  std::string name;      // NAME of its {NAME} placeholder and of name=value
  bool integer = false;  // values must be whole, and are substituted as integers
  // The value when none is set.
  double default_value = 0, minimum = 0, maximum = 0;  // the largest valid value
  // \var minimum
  // The smallest valid value.
  std::string meaning = {};  // one line, for `curvebench list`
};

// What makes a program an algorithm. `exec:COMMAND` declares only `name` (= the whole
// text) and `command`; a file of named algorithms (algorithm_file.h) can say the rest.
struct External_declaration {
  std::string name;        // the name commands find it by; for exec:, the whole text
  std::string title = {};  // default: the name
  std::string command;     // a /bin/sh command line with {points}, {edges}, optionally {points_out} and {PARAMETER}s
  // How {points} is written: xy ("x y" lines) or csv.
  enum class Point_format { xy, csv } input_format = Point_format::xy;  // csv: an `x,y` header, then `x,y` lines
  int index_base = 0;  // the program numbers points from 0 (C, Python) or 1 (MATLAB, Julia, R)
  std::vector<External_parameter> parameters = {};  // each substituted as {NAME}
  std::optional<double> timeout_seconds = {};  // per run of the program, besides the run's own --timeout
  // The claimed sampling condition, which `certify` and `hunt` check like a theorem's.
  std::string condition = "none declared";
  // The claimed bound on epsilon, as algorithms::Sampling_condition states one.
  std::optional<double> epsilon_below = {}, rho_below = {}, uniformity_below = {};  // on local uniformity
  // \var rho_below
  // The claimed bound on rho.
  std::filesystem::path file = {};  // the file that declared it (absolute), if one did
};

// Makes `declaration` an algorithm found by its name, for the life of the process. Throws
// std::invalid_argument for a bad declaration (an unknown placeholder, no {points} or no
// {edges}, a program that does not exist, a bad parameter range or index base) or a name
// that is taken.
const algorithms::Algorithm& declare_external_algorithm(External_declaration declaration);

// The registered algorithm of that name, a declared one, or the external one an exec: name
// declares (made once, kept for the life of the process); nullptr for an unknown name.
// Throws std::invalid_argument for a bad exec: declaration.
const algorithms::Algorithm* find_any_algorithm(std::string_view name);

// The algorithms of those names (find_any_algorithm); with none, every registered algorithm
// and every one declared by name, in the order declared. Throws std::invalid_argument for an
// unknown name or a bad exec: declaration.
std::vector<const algorithms::Algorithm*> find_algorithms(const std::vector<std::string>& names);

// The declaration behind an external algorithm; nullptr for a built-in one.
const External_declaration* external_declaration(const algorithms::Algorithm& algorithm);

// `text` in single quotes for /bin/sh.
std::string shell_quoted(std::string_view text);

// The arguments that name `algorithm` on a replay's command line: -a NAME, and the
// --algorithm-file that declares it, if one does; shell-quoted.
std::string replay_arguments(const algorithms::Algorithm& algorithm);

// The cut, in seconds, of a start-up run (below) of a program without a declared timeout.
inline constexpr double startup_timeout_seconds = 10;
// The program's wall time on an input of no points, in milliseconds: the median of three
// runs, whatever each ends with (a program may refuse an empty input, yet it started), each
// cut at its timeout or startup_timeout_seconds. What a run reports beside the program's
// runtime, so that an interpreter's start-up is seen as such. 0 for a built-in algorithm.
double startup_milliseconds(const algorithms::Algorithm& algorithm);

}  // namespace curvebench::bench
