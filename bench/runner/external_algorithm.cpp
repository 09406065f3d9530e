#include "bench/runner/external_algorithm.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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

namespace curvebench::bench {
namespace {

namespace fs = std::filesystem;
using algorithms::Point;

constexpr std::string_view placeholders[] = {"{points}", "{edges}", "{points_out}"};

// Every {word} of the command, checked against the placeholders.
void check_placeholders(std::string_view command) {
  for (std::size_t open = command.find('{'); open != std::string_view::npos; open = command.find('{', open + 1)) {
    const std::size_t close = command.find('}', open);
    if (close == std::string_view::npos) break;
    const std::string_view word = command.substr(open, close - open + 1);
    const bool is_word = std::all_of(word.begin() + 1, word.end() - 1, [](char c) { return std::islower(c) || c == '_'; });
    if (is_word && word.size() > 2 && std::ranges::find(placeholders, word) == std::end(placeholders))
      throw std::invalid_argument("exec: unknown placeholder " + std::string(word) +
                                  " (there are {points}, {edges} and {points_out})");
  }
  for (const std::string_view needed : {"{points}", "{edges}"})
    if (command.find(needed) == std::string_view::npos)
      throw std::invalid_argument("exec: the command needs " + std::string(needed));
}

// The program a command line starts: its first word, found as the shell would.
void check_program(std::string_view command) {
  const std::size_t start = command.find_first_not_of(" \t");
  if (start == std::string_view::npos) throw std::invalid_argument("exec: no command");
  const std::string program(command.substr(start, command.find_first_of(" \t", start) - start));
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

// Runs `command` under /bin/sh, stdout and stderr to files in `scratch`. The program dies
// with its caller (a worker killed at its timeout takes the program with it).
void run_program(const std::string& command, const fs::path& scratch) {
  const std::string out = (scratch / "stdout").string(), err = (scratch / "stderr").string();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("exec: cannot fork");
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int in = open("/dev/null", O_RDONLY), o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600),
              e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || o < 0 || e < 0 || dup2(in, 0) < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0) _exit(127);
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("exec: cannot wait for the program");
  std::ifstream errors(err);
  std::string first_line;
  std::getline(errors, first_line);
  // Killed by a signal: the shell itself, or the program it ran, which the shell reports
  // as the exit status 128 + the signal's number.
  const int signal = WIFSIGNALED(status) ? WTERMSIG(status)
                     : WEXITSTATUS(status) > 128 && WEXITSTATUS(status) < 128 + NSIG ? WEXITSTATUS(status) - 128
                                                                                     : 0;
  if (signal != 0)
    throw Program_crashed("program killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")");
  if (WEXITSTATUS(status) != 0)
    throw std::runtime_error("program exit status " + std::to_string(WEXITSTATUS(status)) +
                             (first_line.empty() ? "" : ": " + first_line));
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

// The edges, checked against the points they index as a ground truth's are.
std::vector<algorithms::Edge> read_edges(const fs::path& file, std::size_t point_count) {
  const geometry::EdgeFile edges = parsed_output(file, "edges", geometry::parse_edge_file);
  for (std::size_t k = 0; k < edges.edges.size(); ++k) {
    const auto [i, j] = edges.edges[k];
    const std::string where = "edges:" + std::to_string(edges.lines[k]) + ": ";
    if (std::max(i, j) >= point_count)
      throw Invalid_output(where + "index " + std::to_string(std::max(i, j)) + " out of range (" +
                           std::to_string(point_count) + " points)");
    if (i == j) throw Invalid_output(where + "a self-loop at " + std::to_string(i));
  }
  return geometry::canonical_edges(edges.edges);
}

algorithms::Reconstruction run_external(const std::string& command, std::span<const Point> points) {
  const Scratch scratch;
  const fs::path input = scratch.path() / "points.xy", edges = scratch.path() / "edges.txt",
                 points_out = scratch.path() / "points_out.xy";
  geometry::write_points(input, points);
  std::string line = replaced(command, "{points_out}", quoted(points_out));
  line = replaced(replaced(line, "{points}", quoted(input)), "{edges}", quoted(edges));
  run_program(line, scratch.path());
  if (command.find("{points_out}") == std::string::npos) return {read_edges(edges, points.size()), {}};
  std::vector<Point> moved = parsed_output(points_out, "points_out", geometry::parse_point_file).points;
  std::vector<algorithms::Edge> found = read_edges(edges, moved.size());
  return {std::move(found), std::move(moved)};
}

}  // namespace

const algorithms::Algorithm* find_any_algorithm(std::string_view name) {
  if (!name.starts_with(external_prefix)) return algorithms::find_algorithm(name);
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<algorithms::Algorithm>, std::less<>> made;
  const std::lock_guard lock(mutex);
  if (const auto found = made.find(name); found != made.end()) return found->second.get();
  const std::string command(name.substr(external_prefix.size()));
  check_placeholders(command);
  check_program(command);
  auto algorithm = std::make_unique<algorithms::Algorithm>();
  const std::string& key = made.emplace(std::string(name), nullptr).first->first;  // the views below point here
  algorithm->name = key;
  algorithm->title = key;
  algorithm->reference = "an external program";
  algorithm->category = "External";
  algorithm->condition.statement = "none declared";
  algorithm->reconstruct = [command](std::span<const Point> points, const algorithms::Parameter_values&) {
    return run_external(command, points);
  };
  return (made[key] = std::move(algorithm)).get();
}

}  // namespace curvebench::bench
