#include "bench/runner/external_algorithm.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/syscall.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "bench/runner/results_table.h"

namespace curvebench::bench {
namespace {

namespace fs = std::filesystem;
using algorithms::Point;

// Every {word} of the command, checked against the placeholders: the files and the
// declared parameters.
void check_placeholders(std::string_view command, const std::vector<External_parameter>& parameters) {
  std::vector<std::string> known{"{points}", "{edges}", "{points_out}"};
  for (const External_parameter& parameter : parameters) known.push_back("{" + parameter.name + "}");
  for (std::size_t open = command.find('{'); open != std::string_view::npos; open = command.find('{', open + 1)) {
    const std::size_t close = command.find('}', open);
    if (close == std::string_view::npos) break;
    const std::string_view word = command.substr(open, close - open + 1);
    const bool is_word = std::all_of(word.begin() + 1, word.end() - 1, [](char c) { return std::isalnum(c) || c == '_' || c == '-'; });
    if (is_word && word.size() > 2 && std::ranges::find(known, word) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw std::invalid_argument("exec: unknown placeholder " + std::string(word) + " (there are " + list + ")");
    }
  }
  for (const std::string_view needed : {"{points}", "{edges}"})
    if (command.find(needed) == std::string_view::npos)
      throw std::invalid_argument("exec: the command needs " + std::string(needed));
}

// The program a command line starts: its first word (single quotes as the shell reads them),
// found as the shell would.
void check_program(std::string_view command) {
  std::string program;
  std::size_t at = command.find_first_not_of(" \t");
  for (bool quoted = false; at < command.size() && (quoted || (command[at] != ' ' && command[at] != '\t')); ++at)
    if (command[at] == '\'') quoted = !quoted;
    else program.push_back(command[at]);
  if (program.empty()) throw std::invalid_argument("exec: no command");
  const auto runnable = [](const fs::path& path) { return fs::is_regular_file(path) && access(path.c_str(), X_OK) == 0; };
  if (program.find('/') != std::string::npos) {
    if (runnable(program)) return;
  } else if (const char* path = std::getenv("PATH")) {
    std::stringstream directories(path);
    for (std::string directory; std::getline(directories, directory, ':');)
      if (runnable(fs::path(directory.empty() ? "." : directory) / program)) return;
  }
  throw std::invalid_argument("exec: no program '" + program + "' (not an executable file, nor on PATH)");
}

// In single quotes for the shell (the scratch directory's name has none).
std::string quoted(const fs::path& path) {
  std::string text(1, '\'');
  text.append(path.native()).push_back('\'');
  return text;
}

std::string replaced(std::string command, std::string_view placeholder, const std::string& value) {
  for (std::size_t at; (at = command.find(placeholder)) != std::string::npos;) command.replace(at, placeholder.size(), value);
  return command;
}

// A temporary directory, removed with everything in it.
class Scratch {
 public:
  Scratch() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = (fs::path(base && *base ? base : "/tmp") / "curvebench-exec-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("exec: cannot make a temporary directory");
    path_ = pattern;
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Waits for the child `pid`; past `timeout` (if any) kills it and throws Program_timed_out.
// A pidfd makes the wait a poll with a time limit, without signals in a threaded process.
int wait_for(pid_t pid, std::optional<double> timeout) {
  if (timeout) {
    const int pidfd = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));  // glibc 2.36 declares it without extern "C"
    if (pidfd >= 0) {
      pollfd ready{pidfd, POLLIN, 0};
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(*timeout);
      int polled = 0;
      do {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        polled = poll(&ready, 1, static_cast<int>(std::max<std::int64_t>(0, left.count())));
      } while (polled < 0 && errno == EINTR);
      close(pidfd);
      if (polled == 0) {
        kill(-pid, SIGKILL);  // the shell's group: the program it started too
        waitpid(pid, nullptr, 0);
        throw Program_timed_out("program ran past its timeout of " + format_number(*timeout) + " s");
      }
    }
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("exec: cannot wait for the program");
  return status;
}

// Runs `command` under /bin/sh, stdout and stderr to files in `scratch`. The program dies
// with its caller (a worker killed at its timeout takes the program with it). The shell
// leads a process group of its own, so that a timeout kills whatever it started.
void run_program(const std::string& command, const fs::path& scratch, std::optional<double> timeout) {
  const std::string out = (scratch / "stdout").string(), err = (scratch / "stderr").string();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("exec: cannot fork");
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    setpgid(0, 0);
    const int in = open("/dev/null", O_RDONLY), o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600),
              e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || o < 0 || e < 0 || dup2(in, 0) < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0) _exit(127);
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const int status = wait_for(pid, timeout);
  // The last line a program wrote to stderr says what went wrong (a Python traceback ends
  // with the exception; a C program's one line is its last).
  std::ifstream errors(err);
  std::string last_line;
  for (std::string line; std::getline(errors, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) last_line = line;
  // Killed by a signal: the shell itself, or the program it ran, which the shell reports
  // as the exit status 128 + the signal's number.
  const int signal = WIFSIGNALED(status) ? WTERMSIG(status)
                     : WEXITSTATUS(status) > 128 && WEXITSTATUS(status) < 128 + NSIG ? WEXITSTATUS(status) - 128
                                                                                     : 0;
  if (signal != 0)
    throw Program_crashed("program killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")");
  if (WEXITSTATUS(status) != 0)
    throw std::runtime_error("program exit status " + std::to_string(WEXITSTATUS(status)) +
                             (last_line.empty() ? "" : ": " + last_line));
}

// An output file the program had to write, parsed by the project's own readers (the
// same grammar as every point and edge file): any fault is Invalid_output, named "NAME:LINE".
template <class Parse>
auto parsed_output(const fs::path& file, std::string_view name, Parse parse) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Invalid_output("the program wrote no " + std::string(name) + " file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  try {
    return parse(text, name);
  } catch (const geometry::ParseError& error) {
    throw Invalid_output(error.what());
  }
}

// The edges, checked against the points they index as a ground truth's are, renumbered
// from the program's `base` to 0.
std::vector<algorithms::Edge> read_edges(const fs::path& file, std::size_t point_count, int base) {
  geometry::EdgeFile edges = parsed_output(file, "edges", geometry::parse_edge_file);
  for (std::size_t k = 0; k < edges.edges.size(); ++k) {
    auto& [i, j] = edges.edges[k];
    const std::string where = "edges:" + std::to_string(edges.lines[k]) + ": ";
    const std::size_t first = static_cast<std::size_t>(base), last = point_count - 1 + first;
    if (std::min(i, j) < first || std::max(i, j) > last || point_count == 0)
      throw Invalid_output(where + "index " + std::to_string(std::min(i, j) < first ? std::min(i, j) : std::max(i, j)) +
                           " out of range (" + std::to_string(point_count) + " points" +
                           (base == 1 ? ", numbered from 1)" : ")"));
    if (i == j) throw Invalid_output(where + "a self-loop at " + std::to_string(i));
    i -= first, j -= first;
  }
  return geometry::canonical_edges(edges.edges);
}

void write_input(const fs::path& file, std::span<const Point> points, External_declaration::Point_format format) {
  if (format == External_declaration::Point_format::xy) return geometry::write_points(file, points);
  // The plain writer's lines with a comma for the blank (numbers hold none), under the
  // header pandas and spreadsheets write.
  std::ostringstream plain;
  geometry::write_points(plain, points);
  std::string text = "x,y\n" + plain.str();
  std::ranges::replace(text, ' ', ',');
  std::ofstream(file, std::ios::binary) << text;
}

std::string parameter_text(const External_parameter& parameter, double value) {
  return parameter.integer ? std::to_string(static_cast<long long>(value)) : format_number(value);
}

algorithms::Reconstruction run_external(const External_declaration& d, std::span<const algorithms::Parameter> parameters,
                                        std::span<const Point> points, const algorithms::Parameter_values& values) {
  const Scratch scratch;
  const fs::path input = scratch.path() / (d.input_format == External_declaration::Point_format::csv ? "points.csv" : "points.xy"),
                 edges = scratch.path() / "edges.txt", points_out = scratch.path() / "points_out.xy";
  write_input(input, points, d.input_format);
  std::string line = replaced(d.command, "{points_out}", quoted(points_out));
  line = replaced(replaced(line, "{points}", quoted(input)), "{edges}", quoted(edges));
  for (std::size_t k = 0; k < d.parameters.size(); ++k)
    line = replaced(line, "{" + d.parameters[k].name + "}", parameter_text(d.parameters[k], values[parameters[k]]));
  run_program(line, scratch.path(), d.timeout_seconds);
  if (d.command.find("{points_out}") == std::string::npos) return {read_edges(edges, points.size(), d.index_base), {}};
  std::vector<Point> moved = parsed_output(points_out, "points_out", geometry::parse_point_file).points;
  std::vector<algorithms::Edge> found = read_edges(edges, moved.size(), d.index_base);
  return {std::move(found), std::move(moved)};
}

// A declaration and the algorithm made of it, whose views point into the declaration.
struct Declared {
  External_declaration declaration;
  algorithms::Algorithm algorithm;
};

struct Declared_table {
  std::mutex mutex;
  std::map<std::string, std::unique_ptr<Declared>, std::less<>> by_name;
  std::vector<const algorithms::Algorithm*> named;  // declared by name (not exec:), in order
};

Declared_table& declared() {
  static Declared_table table;
  return table;
}

void check_declaration(const External_declaration& d) {
  if (d.name.empty()) throw std::invalid_argument("an external algorithm needs a name");
  if (algorithms::find_algorithm(d.name)) throw std::invalid_argument("'" + d.name + "' is a built-in algorithm's name");
  if (d.index_base != 0 && d.index_base != 1)
    throw std::invalid_argument(d.name + ": index_base is 0 or 1, not " + std::to_string(d.index_base));
  if (d.timeout_seconds && !(*d.timeout_seconds > 0))
    throw std::invalid_argument(d.name + ": the timeout must be positive");
  for (const External_parameter& p : d.parameters) {
    if (p.name.empty() || !std::ranges::all_of(p.name, [](char c) { return std::isalnum(c) || c == '_' || c == '-'; }))
      throw std::invalid_argument(d.name + ": a parameter's name is letters, digits, _ and - ('" + p.name + "' is not)");
    if (!(p.minimum <= p.default_value && p.default_value <= p.maximum))
      throw std::invalid_argument(d.name + ": parameter " + p.name + "'s default is not in [minimum, maximum]");
  }
  check_placeholders(d.command, d.parameters);
  check_program(d.command);
}

}  // namespace

const algorithms::Algorithm& declare_external_algorithm(External_declaration declaration) {
  check_declaration(declaration);
  Declared_table& table = declared();
  const std::lock_guard lock(table.mutex);
  if (table.by_name.contains(declaration.name))
    throw std::invalid_argument("two external algorithms are named '" + declaration.name + "'");
  auto made = std::make_unique<Declared>();
  made->declaration = std::move(declaration);
  const External_declaration& d = made->declaration;
  algorithms::Algorithm& a = made->algorithm;
  a.name = d.name;
  a.title = d.title.empty() ? d.name : d.title;
  a.reference = "an external program";
  a.category = "External";
  for (const External_parameter& p : d.parameters)
    a.parameters.push_back({p.name, p.integer ? algorithms::Parameter_type::integer : algorithms::Parameter_type::real,
                            p.default_value, p.minimum, p.maximum, p.meaning});
  a.condition = {d.condition, d.epsilon_below, d.rho_below, {}, d.uniformity_below};
  a.reconstruct = [&d, parameters = std::span<const algorithms::Parameter>(a.parameters)](
                      std::span<const Point> points, const algorithms::Parameter_values& values) {
    return run_external(d, parameters, points, values);
  };
  const algorithms::Algorithm& result = a;
  if (!d.name.starts_with(external_prefix)) table.named.push_back(&result);
  table.by_name.emplace(d.name, std::move(made));
  return result;
}

const algorithms::Algorithm* find_any_algorithm(std::string_view name) {
  if (const algorithms::Algorithm* builtin = algorithms::find_algorithm(name)) return builtin;
  Declared_table& table = declared();
  {
    const std::lock_guard lock(table.mutex);
    if (const auto found = table.by_name.find(name); found != table.by_name.end()) return &found->second->algorithm;
  }
  if (!name.starts_with(external_prefix)) return nullptr;
  return &declare_external_algorithm({.name = std::string(name), .command = std::string(name.substr(external_prefix.size()))});
}

std::vector<const algorithms::Algorithm*> find_algorithms(const std::vector<std::string>& names) {
  std::vector<const algorithms::Algorithm*> found;
  if (names.empty()) {
    for (const algorithms::Algorithm& algorithm : algorithms::registry()) found.push_back(&algorithm);
    const std::lock_guard lock(declared().mutex);
    found.insert(found.end(), declared().named.begin(), declared().named.end());
  }
  for (const std::string& name : names) {
    const algorithms::Algorithm* algorithm = find_any_algorithm(name);
    if (!algorithm) throw std::invalid_argument("unknown algorithm '" + name + "' (see `curvebench list`)");
    found.push_back(algorithm);
  }
  return found;
}

const External_declaration* external_declaration(const algorithms::Algorithm& algorithm) {
  Declared_table& table = declared();
  const std::lock_guard lock(table.mutex);
  const auto found = table.by_name.find(algorithm.name);
  return found != table.by_name.end() && &found->second->algorithm == &algorithm ? &found->second->declaration : nullptr;
}

std::string shell_quoted(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string replay_arguments(const algorithms::Algorithm& algorithm) {
  std::string arguments = "-a " + shell_quoted(algorithm.name);
  if (const External_declaration* declared = external_declaration(algorithm); declared && !declared->file.empty())
    arguments += " --algorithm-file " + shell_quoted(declared->file.string());
  return arguments;
}

double startup_milliseconds(const algorithms::Algorithm& algorithm) {
  const External_declaration* declared = external_declaration(algorithm);
  if (!declared) return 0;
  // A program that waits forever on no points must not stall the run that measures it.
  External_declaration bounded = *declared;
  bounded.timeout_seconds = std::min(declared->timeout_seconds.value_or(startup_timeout_seconds), startup_timeout_seconds);
  std::vector<double> times;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    try {
      run_external(bounded, algorithm.parameters, {}, {});
    } catch (const std::exception&) {
      // refused, crashed, timed out or wrote nothing: it started all the same
    }
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::ranges::sort(times);
  return times[1];
}

}  // namespace curvebench::bench
