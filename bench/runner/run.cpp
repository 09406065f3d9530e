#include "bench/runner/run.h"

#include <sys/wait.h>
#include <unistd.h>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>

#include "algorithms/registry.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/bench_input.h"
#include "bench/runner/evaluation.h"
#include "bench/runner/process_pool.h"
#include "bench/runner/resources.h"
#include "bench/runner/results_table.h"
#include "bench/runner/suite.h"
#include "certify/theorems.h"
#include "geometry/io/svg_picture.h"
#include "geometry/point_set.h"

namespace curvebench::bench {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t max_picture_points = 5000;

struct Job {
  std::size_t number;  // = case * algorithms + algorithm
  std::size_t case_index;
  const algorithms::Algorithm* algorithm;
  bool success_picture = false;  // Pictures::some draws it even if it is exact
};

Result_row job_row(const Job& job, const Suite_case& c) {
  Result_row row;
  row[Column::job] = std::to_string(job.number);
  row[Column::suite] = c.suite;
  row[Column::input] = c.input;
  row[Column::level] = c.level;
  row[Column::algorithm] = std::string(job.algorithm->name);
  return row;  // params: the defaults, written as nothing
}

bool same_job(const Result_row& a, const Result_row& b) {
  for (const Column column : {Column::job, Column::suite, Column::input, Column::level, Column::algorithm, Column::params})
    if (a[column] != b[column]) return false;
  return true;
}

std::string picture_name(std::size_t job) {
  char name[32];
  std::snprintf(name, sizeof name, "pictures/%06zu.svg", job);
  return name;
}

// The reconstruction on its input: the true curve light, ground-truth edges found in blue,
// wrong edges red, missing ones dashed orange; without a ground truth, every edge blue.
void write_picture(const std::filesystem::path& file, const Bench_input& input, std::span<const Point> points,
                   std::span<const Edge> edges, bool on_input_points, const Evaluation& evaluation,
                   std::string_view algorithm) {
  geometry::SvgPicture picture(points);
  std::string title = std::string(algorithm) + " on " + input.name + ": " + std::to_string(points.size()) + " points";
  // A simplifier's output (the only one measured each way) is never the input's edge set: no verdict.
  if (evaluation.exact && !evaluation.to_curve) title += *evaluation.exact ? ", exact" : ", NOT exact";
  if (evaluation.rms && evaluation.diagonal > 0)
    title += ", RMS " + format_number(*evaluation.rms / *evaluation.diagonal) + " x diagonal";
  picture.set_title(title);
  if (input.curve)
    picture.add_edges(input.curve->points, input.curve->edges, {.colour = "#c9d6ea", .width_px = 5, .legend = "curve"});
  if (input.truth && on_input_points) {
    std::vector<Edge> right, wrong, missing;
    std::ranges::set_intersection(edges, *input.truth, std::back_inserter(right));
    std::ranges::set_difference(edges, *input.truth, std::back_inserter(wrong));
    std::ranges::set_difference(*input.truth, edges, std::back_inserter(missing));
    picture.add_edges(missing, {.colour = "#ff9900", .width_px = 2, .dash_px = {5, 4}, .legend = "missing"});
    picture.add_edges(right, {.colour = "#1f4e99", .width_px = 1.5, .legend = "reconstructed"});
    picture.add_edges(wrong, {.colour = "#e00000", .width_px = 2.5, .legend = "wrong"});
  } else {
    picture.add_edges(edges, {.colour = "#1f4e99", .width_px = 1.5, .legend = "reconstructed"});
  }
  picture.add_points({.colour = "#000000", .radius_px = 1.8});
  picture.write(file);
}

// The job's row with what is known of its input before the algorithm runs.
Result_row input_row(const Job& job, const Suite_case& c, const Bench_input& input) {
  Result_row row = job_row(job, c);
  row[Column::n_points] = std::to_string(input.points.size());
  if (input.epsilon) row[Column::epsilon] = format_number(*input.epsilon);
  if (input.rho) row[Column::rho] = format_number(*input.rho);
  if (input.uniformity) row[Column::uniformity] = format_number(*input.uniformity);
  return row;
}

// A permutation of 0 ... n - 1 drawn by Fisher-Yates from std::mt19937_64, whose output the
// standard fixes (std::shuffle's use of it is each library's own): the same order on every
// machine.
std::vector<std::size_t> drawn_order(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937_64 engine(seed);
  for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[engine() % i]);
  return order;
}

// `algorithm` on the input in the order Run_options::shuffle_seed draws for this job, its
// edges in the input's indices: the registry gives a merged duplicate's edges to the first
// copy it meets, which the shuffle changes, so each end goes to the input's first copy.
algorithms::Reconstruction reconstruct_shuffled(const algorithms::Algorithm& algorithm, std::span<const Point> input,
                                                std::uint64_t seed, std::size_t job) {
  const std::vector<std::size_t> order = drawn_order(input.size(), seed ^ (job * 0x9E3779B97F4A7C15ull));
  std::vector<Point> shuffled;
  shuffled.reserve(input.size());
  for (const std::size_t i : order) shuffled.push_back(input[i]);
  algorithms::Reconstruction result = algorithms::reconstruct(algorithm, shuffled);
  if (!result.points.empty()) return algorithms::reconstruct(algorithm, input);
  const geometry::PointSet merged(std::vector<Point>(input.begin(), input.end()));
  const auto first_copy = [&](std::size_t i) { return merged.input_index(merged.kept_index(i)); };
  for (Edge& edge : result.edges) edge = {first_copy(order[edge.first]), first_copy(order[edge.second])};
  result.edges = geometry::canonical_edges(std::move(result.edges));
  return result;
}

// Runs in a worker process: the job's row, as a CSV line.
std::string run_job(const Job& job, const Suite_case& c, const Bench_input& input, const Run_options& options) {
  Result_row row = input_row(job, c, input);
  try {
    const auto start = Clock::now();
    const algorithms::Reconstruction result =
        options.shuffle_seed ? reconstruct_shuffled(*job.algorithm, input.points, *options.shuffle_seed, job.number)
                             : algorithms::reconstruct(*job.algorithm, input.points);
    const std::chrono::duration<double, std::milli> elapsed = Clock::now() - start;
    const bool on_input_points = result.points.empty();
    const std::span<const Point> points = on_input_points ? std::span<const Point>(input.points) : result.points;
    const geometry::Polyline_view reconstruction{points, result.edges};
    const geometry::Polyline_view truth{input.points, input.truth ? std::span<const Edge>(*input.truth) : std::span<const Edge>()};
    const std::optional<geometry::Polyline_view> curve =
        input.curve ? std::optional(input.curve->view()) : std::nullopt;
    const Evaluation evaluation = evaluate(reconstruction, on_input_points, input.truth ? &truth : nullptr,
                                           curve ? &*curve : nullptr, job.algorithm->simplifies);

    row[Column::status] = "ok";
    row[Column::runtime_ms] = format_number(elapsed.count());
    if (evaluation.exact) row[Column::exact] = *evaluation.exact ? "1" : "0";
    // Distances as fractions of the original's bounding-box diagonal, so that curves of any
    // size average (the survey's uniform noise uses the same unit). A curve of one point
    // has no size: its distances stay absolute.
    const double unit = evaluation.diagonal > 0 ? *evaluation.diagonal : 1;
    if (evaluation.hausdorff) row[Column::hausdorff] = format_number(*evaluation.hausdorff / unit);
    if (evaluation.rms) row[Column::rms] = format_number(*evaluation.rms / unit);
    if (evaluation.to_curve) {
      row[Column::hausdorff_to_curve] = format_number(evaluation.to_curve->hausdorff / unit);
      row[Column::rms_to_curve] = format_number(evaluation.to_curve->rms / unit);
    }
    if (evaluation.from_curve) {
      row[Column::hausdorff_from_curve] = format_number(evaluation.from_curve->hausdorff / unit);
      row[Column::rms_from_curve] = format_number(evaluation.from_curve->rms / unit);
    }
    if (evaluation.normal_deviation) row[Column::normal_deviation] = format_number(*evaluation.normal_deviation);
    const geometry::Curve_topology& t = evaluation.topology;
    row[Column::manifold] = t.manifold ? "1" : "0";
    row[Column::components] = std::to_string(t.components);
    row[Column::open_components] = std::to_string(t.open_components);
    row[Column::closed_components] = std::to_string(t.closed_components);
    row[Column::unconnected] = std::to_string(t.unconnected);
    row[Column::output_points] = std::to_string(points.size());
    // The survey's question for noisy input: one manifold curve per true curve, closed
    // where the truth is closed, whatever the points (denoising algorithms drop some).
    if (input.truth) {
      const geometry::Curve_topology truth = geometry::curve_topology(input.points.size(), *input.truth);
      const bool same = t.manifold && t.components == truth.components && t.closed_components == truth.closed_components &&
                        t.open_components == truth.open_components;
      row[Column::true_topology] = same ? "1" : "0";
    }
    // A picture of more points than a screen has pixels across shows nothing but costs
    // megabytes, and a browser seconds: large inputs (the runtime suite) get none.
    const bool failure = evaluation.exact != true;
    const bool wanted = options.pictures == Pictures::all ||
                        (options.pictures == Pictures::failures && failure) ||
                        (options.pictures == Pictures::some && (failure || job.success_picture));
    if (wanted && input.points.size() <= max_picture_points) {
      row[Column::picture] = picture_name(job.number);
      write_picture(options.output / row[Column::picture], input, points, result.edges, on_input_points, evaluation,
                    job.algorithm->name);
    }
  } catch (const Invalid_output& error) {
    row[Column::status] = "invalid-output";
    row[Column::message] = error.what();
  } catch (const Program_crashed& error) {
    row[Column::status] = "crashed";
    row[Column::message] = error.what();
  } catch (const Program_timed_out& error) {
    row[Column::status] = "timeout";
    row[Column::message] = error.what();
  } catch (const std::exception& error) {
    row[Column::status] = "failed";
    row[Column::message] = error.what();
  }
  return row.csv();
}

// Progress on stderr: a bar redrawn in place on a terminal, a line now and then otherwise
// (a log file, CI).
class Progress {
 public:
  Progress(std::size_t total, bool enabled) : total_(total), enabled_(enabled), terminal_(isatty(STDERR_FILENO)) {}

  void job_done(bool ok) {
    ++done_, failures_ += !ok;
    if (!enabled_) return;
    const auto now = Clock::now();
    const bool last = done_ == total_;
    if (!last && now - shown_ < (terminal_ ? std::chrono::milliseconds(100) : std::chrono::seconds(15))) return;
    shown_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double left = done_ > 0 ? seconds * static_cast<double>(total_ - done_) / static_cast<double>(done_) : 0;
    char line[160];
    if (terminal_) {
      const std::size_t width = 30, filled = total_ ? width * done_ / total_ : width;
      std::snprintf(line, sizeof line, "\r[%s%s] %zu/%zu jobs, %zu not ok, %.0f s, ~%.0f s left ",
                    std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), done_, total_, failures_,
                    seconds, left);
      std::cerr << line << (last ? "\n" : "") << std::flush;
    } else {
      std::snprintf(line, sizeof line, "run: %zu/%zu jobs, %zu not ok, %.0f s\n", done_, total_, failures_, seconds);
      std::cerr << line;
    }
  }

 private:
  std::size_t total_, done_ = 0, failures_ = 0;
  bool enabled_, terminal_;
  Clock::time_point start_ = Clock::now(), shown_{};
};

// DIR/algorithms.csv: what the report needs to know of an algorithm beyond its rows. A
// simplifier (Optimal Transport) is scored apart there, by distances both ways, topology and
// size instead of exactness, as the survey leaves it out of its experiments ("The
// Benchmark", "Algorithms"). Written from the registry, as theorems.csv is, and again by
// make_report, so that the report of a run made before this file existed knows too.
void write_algorithm_table(const std::filesystem::path& dir) {
  std::ofstream table(dir / "algorithms.csv");
  table << "algorithm,simplifies\n";
  for (const algorithms::Algorithm& algorithm : algorithms::registry())
    table << algorithm.name << ',' << (algorithm.simplifies ? 1 : 0) << '\n';
}

// Pictures::some: keeps, per algorithm and suite, the first failure_pictures pictures of
// jobs that are not exact, in job order, and deletes the others' (the successes drawn are
// few already). Keeping the first ones makes the result that of one run whatever the
// shards: each of the first k failures overall is among the first k of its own shard.
void cap_pictures(const std::filesystem::path& dir, std::vector<Result_row>& rows) {
  std::map<std::pair<std::string, std::string>, std::size_t> failures;
  for (Result_row& row : rows) {
    std::string& picture = row[Column::picture];
    if (picture.empty() || row[Column::exact] == "1") continue;
    if (++failures[{row[Column::algorithm], row[Column::suite]}] <= failure_pictures) continue;
    std::filesystem::remove(dir / picture);
    picture.clear();
  }
}

void write_outputs(const std::filesystem::path& dir, std::vector<Result_row> rows, bool report, Pictures pictures) {
  std::ranges::sort(rows, {}, &Result_row::job);
  if (pictures == Pictures::some) cap_pictures(dir, rows);
  write_results_csv(dir / "results.csv", rows);
  write_results_json(dir / "results.json", rows);
  // The proven bounds, for the report's breakdown chart (certify/theorems.h).
  std::ofstream theorems(dir / "theorems.csv");
  theorems << "algorithm,epsilon_below\n";
  for (const certify::Theorem& theorem : certify::theorems())
    theorems << theorem.algorithm->name << ',' << format_number(theorem.bound) << '\n';
  theorems.close();
  write_algorithm_table(dir);
  if (report) make_report(dir);
}

// The jobs of this shard. Job c * A + a runs algorithm a on case c: numbers that do not
// depend on the shard, so that shards and resumed runs agree on them.
// Which shard runs a job: a shard makes the input of each case it holds a job of, and
// making an input (sampling, lfs, the dense true curve) costs more than most algorithms
// do, so a case's jobs, and consecutive cases of one source (input_source: the same
// curve), stay in one shard: these units are dealt to the shards in turn. A run of fewer
// units than shards deals its jobs instead, so that every shard has work.
std::vector<Job> planned_jobs(const std::vector<Suite_case>& cases, const std::vector<const algorithms::Algorithm*>& chosen,
                              const Run_options& options) {
  if (options.shards == 0 || options.shard == 0 || options.shard > options.shards)
    throw std::invalid_argument("--shard K/N needs 1 <= K <= N");
  std::vector<std::size_t> unit_of(cases.size());
  std::size_t units = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    if (c == 0 || input_source(cases[c].input) != input_source(cases[c - 1].input)) ++units;
    unit_of[c] = units - 1;
  }
  const bool by_unit = units >= options.shards;
  std::map<std::pair<std::size_t, std::string_view>, std::size_t> seen;  // jobs so far per algorithm and suite
  std::vector<Job> jobs;
  for (std::size_t c = 0; c < cases.size(); ++c)
    for (std::size_t a = 0; a < chosen.size(); ++a) {
      const bool early = seen[{a, cases[c].suite}]++ < success_pictures;
      const std::size_t number = c * chosen.size() + a;
      if ((by_unit ? unit_of[c] : number) % options.shards == options.shard - 1) jobs.push_back({number, c, chosen[a], early});
    }
  return jobs;
}

// The rows an earlier, interrupted run of the same jobs left in `csv`; none if there is
// no such file. Throws if there is one and `resume` is off, or if it holds another run.
std::vector<Result_row> earlier_rows(const std::filesystem::path& csv, const std::vector<Job>& jobs,
                                     const std::vector<Suite_case>& cases, bool resume) {
  if (!std::filesystem::exists(csv)) return {};
  if (!resume) throw std::invalid_argument(csv.string() + " exists: add --resume to continue that run, or choose another -o");
  std::vector<Result_row> rows = read_results_csv(csv);
  std::map<std::size_t, const Job*> by_number;
  for (const Job& job : jobs) by_number[job.number] = &job;
  for (const Result_row& row : rows) {
    const auto it = by_number.find(row.job());
    if (it == by_number.end() || !same_job(row, job_row(*it->second, cases[it->second->case_index])))
      throw std::invalid_argument(csv.string() + ": job " + row[Column::job] +
                                  " is not this run's (another suite, algorithm list or shard?)");
  }
  return rows;
}

// The cases of `pending` jobs, in runs of one source: each run's curve is analysed once.
std::vector<std::vector<std::size_t>> cases_by_source(const std::vector<Job>& pending,
                                                      const std::vector<Suite_case>& cases) {
  std::vector<std::vector<std::size_t>> groups;
  for (const Job& job : pending) {
    const std::size_t c = job.case_index;
    if (!groups.empty() && groups.back().back() == c) continue;
    if (groups.empty() || input_source(cases[groups.back().back()].input) != input_source(cases[c].input))
      groups.emplace_back();
    groups.back().push_back(c);
  }
  return groups;
}

// The inputs of the cases in `groups`, made in parallel, or why one could not be made.
struct Batch_inputs {
  std::map<std::size_t, Bench_input> inputs;
  std::map<std::size_t, std::string> errors;
  bool has(std::size_t c) const { return inputs.contains(c) || errors.contains(c); }
};

Batch_inputs make_inputs(std::span<const std::vector<std::size_t>> groups, const std::vector<Suite_case>& cases,
                         std::size_t threads) {
  std::vector<std::vector<Bench_input>> made(groups.size());
  std::vector<std::string> failure(groups.size());
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    tbb::parallel_for(std::size_t{0}, groups.size(), [&](std::size_t g) {
      std::vector<std::string> names;
      for (const std::size_t c : groups[g]) names.push_back(cases[c].input);
      try {
        made[g] = make_bench_inputs(names);
      } catch (const std::exception& error) {
        failure[g] = std::string("input: ") + error.what();
      }
    });
  }
  Batch_inputs batch;
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t k = 0; k < groups[g].size(); ++k)
      if (failure[g].empty()) batch.inputs.emplace(groups[g][k], std::move(made[g][k]));
      else batch.errors.emplace(groups[g][k], failure[g]);
  return batch;
}

// The row of a job whose worker sent none (or nonsense): it crashed or timed out.
Result_row lost_job_row(const Job& job, const Suite_case& c, const Bench_input& input, const Task_outcome& outcome) {
  Result_row row = input_row(job, c, input);
  row[Column::status] = outcome.kind == Task_outcome::Kind::timed_out ? "timeout" : "crashed";
  row[Column::message] = outcome.reason.empty() ? "garbled result from the worker" : outcome.reason;
  return row;
}

// DIR/run.json: which run a directory holds and which shard of it, so that `merge` can
// refuse shards of different runs and name the missing or unfinished ones. A run is its
// plan: the cases and algorithms, whose fingerprint `plan` is the same for every shard.
struct Run_manifest {
  std::string plan, suite;
  std::size_t algorithms = 0, cases = 0, shard = 1, shards = 1, jobs = 0;
  bool operator==(const Run_manifest&) const = default;
};

constexpr const char* manifest_name = "run.json";

// FNV-1a, 64 bits, over every case and algorithm name: stable across machines and
// builds (std::hash is not), and a different suite, level or algorithm list changes it.
std::string plan_fingerprint(const std::vector<Suite_case>& cases, const std::vector<const algorithms::Algorithm*>& chosen) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&](std::string_view text) {
    for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    hash = (hash ^ 0xffu) * 1099511628211ull;  // a separator no name holds
  };
  for (const Suite_case& c : cases) add(c.suite), add(c.input), add(c.level);
  for (const algorithms::Algorithm* algorithm : chosen) add(algorithm->name);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

Run_manifest manifest_of(const std::vector<Suite_case>& cases, const std::vector<const algorithms::Algorithm*>& chosen,
                         const Run_options& options, std::size_t jobs) {
  return {.plan = plan_fingerprint(cases, chosen),
          .suite = !options.suite.empty() ? options.suite : cases.empty() ? "" : cases.front().suite,
          .algorithms = chosen.size(),
          .cases = cases.size(),
          .shard = options.shard,
          .shards = options.shards,
          .jobs = jobs};
}

std::string describe(const Run_manifest& m) {
  return "suite " + m.suite + ", " + std::to_string(m.cases) + " cases x " + std::to_string(m.algorithms) +
         " algorithms, shard " + std::to_string(m.shard) + "/" + std::to_string(m.shards);
}

void write_manifest(const std::filesystem::path& dir, const Run_manifest& m) {
  const nlohmann::json json = {{"plan", m.plan},   {"suite", m.suite},   {"algorithms", m.algorithms},
                               {"cases", m.cases}, {"shard", m.shard},   {"shards", m.shards},
                               {"jobs", m.jobs}};
  std::ofstream(dir / manifest_name) << json.dump(2) << '\n';
}

std::optional<Run_manifest> read_manifest(const std::filesystem::path& dir) {
  std::ifstream in(dir / manifest_name);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    return Run_manifest{.plan = json.at("plan"), .suite = json.at("suite"), .algorithms = json.at("algorithms"),
                        .cases = json.at("cases"), .shard = json.at("shard"), .shards = json.at("shards"),
                        .jobs = json.at("jobs")};
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument((dir / manifest_name).string() + ": " + error.what());
  }
}

// "2, 5 and 7"
std::string number_list(const std::vector<std::size_t>& numbers) {
  std::string text;
  for (std::size_t i = 0; i < numbers.size(); ++i)
    text += (i == 0 ? "" : i + 1 == numbers.size() ? " and " : ", ") + std::to_string(numbers[i]);
  return text;
}

}  // namespace

Run_summary run_suite(const Run_options& options) {
  const Suite* suite = find_suite(options.suite);
  if (!suite) throw std::invalid_argument("unknown suite '" + options.suite + "' (see `curvebench list suites`)");
  return run_cases(suite_cases(*suite), find_algorithms(options.algorithms), options);
}

Run_summary run_cases(const std::vector<Suite_case>& cases, const std::vector<const algorithms::Algorithm*>& chosen,
                      const Run_options& options) {
  const std::vector<Job> jobs = planned_jobs(cases, chosen, options);

  const std::filesystem::path csv = options.output / "results.csv";
  std::filesystem::create_directories(options.output / "pictures");
  std::vector<Result_row> rows = earlier_rows(csv, jobs, cases, options.resume);
  const Run_manifest manifest = manifest_of(cases, chosen, options, jobs.size());
  if (const auto earlier = read_manifest(options.output); earlier && options.resume && *earlier != manifest)
    throw std::invalid_argument(options.output.string() + " holds another run (" + describe(*earlier) +
                                "), not this one (" + describe(manifest) + ")");
  write_manifest(options.output, manifest);
  write_results_csv(csv, rows);  // drops a line cut off by an interrupted run
  std::vector<bool> done(cases.size() * chosen.size(), false);
  for (const Result_row& row : rows) done[row.job()] = true;
  std::vector<Job> pending;
  for (const Job& job : jobs)
    if (!done[job.number]) pending.push_back(job);

  // A program's start-up, measured once, goes beside each of its runtimes: what an
  // interpreter costs before the algorithm does anything.
  std::map<std::string, std::string, std::less<>> startup;
  if (!pending.empty())
    for (const algorithms::Algorithm* algorithm : chosen)
      if (external_declaration(*algorithm)) startup[std::string(algorithm->name)] = format_number(startup_milliseconds(*algorithm));

  Run_summary summary{.jobs = jobs.size(), .resumed = jobs.size() - pending.size()};
  Progress progress(pending.size(), options.progress);
  std::ofstream out(csv, std::ios::binary | std::ios::app);
  const auto record = [&](Result_row row) {
    if (const auto found = startup.find(row[Column::algorithm]); found != startup.end()) row[Column::startup_ms] = found->second;
    out << row.csv() << '\n' << std::flush;
    rows.push_back(row);
    const std::string& status = row[Column::status];
    ++(status == "ok"               ? summary.ok
       : status == "failed"         ? summary.failed
       : status == "invalid-output" ? summary.invalid_output
       : status == "crashed"        ? summary.crashed
                                    : summary.timed_out);
    progress.job_done(status == "ok");
  };

  // Inputs are made in this process, a batch of sources at a time, and reach the worker
  // processes by fork.
  const std::size_t workers = options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  const std::vector<std::vector<std::size_t>> groups = cases_by_source(pending, cases);
  std::size_t next = 0;  // the first pending job not yet run
  for (std::size_t first = 0; first < groups.size(); first += 8 * workers) {
    const auto batch_groups = std::span(groups).subspan(first, std::min(8 * workers, groups.size() - first));
    const Batch_inputs batch = make_inputs(batch_groups, cases, workers);
    std::vector<Job> runnable;
    for (; next < pending.size() && batch.has(pending[next].case_index); ++next) {
      const Job& job = pending[next];
      if (const auto error = batch.errors.find(job.case_index); error != batch.errors.end()) {
        Result_row row = job_row(job, cases[job.case_index]);
        row[Column::status] = "failed";
        row[Column::message] = error->second;
        record(row);
      } else {
        runnable.push_back(job);
      }
    }
    run_in_processes(
        runnable.size(), {.workers = workers, .timeout_seconds = options.timeout_seconds, .memory_limit_bytes = 8ull << 30},
        [&](std::size_t k) {
          const Job& job = runnable[k];
          return run_job(job, cases[job.case_index], batch.inputs.at(job.case_index), options);
        },
        [&](std::size_t k, const Task_outcome& outcome) {
          const Job& job = runnable[k];
          const Suite_case& c = cases[job.case_index];
          std::optional<Result_row> row;
          if (outcome.kind == Task_outcome::Kind::finished) row = Result_row::parse_csv(outcome.output);
          if (!row || !same_job(*row, job_row(job, c)))
            row = lost_job_row(job, c, batch.inputs.at(job.case_index), outcome);
          record(*row);
        });
  }
  out.close();
  write_outputs(options.output, std::move(rows), options.report, options.pictures);
  return summary;
}

std::size_t merge_runs(std::span<const std::filesystem::path> shards, const std::filesystem::path& output,
                       Pictures pictures, bool report) {
  if (shards.empty()) throw std::invalid_argument("no shard directories to merge");
  // First the shards' manifests: one run, every shard there once and finished.
  std::vector<Run_manifest> manifests;
  std::map<std::size_t, std::filesystem::path> shard_dirs;
  for (const std::filesystem::path& shard : shards) {
    if (!std::filesystem::exists(shard / "results.csv"))
      throw std::invalid_argument(shard.string() + ": no results.csv");
    const std::optional<Run_manifest> m = read_manifest(shard);
    if (!m) throw std::invalid_argument(shard.string() + ": no " + manifest_name + " (not written by `curvebench run`?)");
    if (!manifests.empty() && (m->plan != manifests.front().plan || m->shards != manifests.front().shards))
      throw std::invalid_argument(shard.string() + " is of another run (" + describe(*m) + ") than " +
                                  shards.front().string() + " (" + describe(manifests.front()) + ")");
    if (const auto [it, added] = shard_dirs.emplace(m->shard, shard); !added)
      throw std::invalid_argument("shard " + std::to_string(m->shard) + " twice: " + it->second.string() + " and " +
                                  shard.string());
    manifests.push_back(*m);
  }
  const std::size_t shard_count = manifests.front().shards;
  std::vector<std::size_t> missing;
  for (std::size_t k = 1; k <= shard_count; ++k)
    if (!shard_dirs.contains(k)) missing.push_back(k);

  std::vector<std::vector<Result_row>> shard_rows;
  std::vector<std::string> unfinished;
  for (std::size_t s = 0; s < shards.size(); ++s) {
    shard_rows.push_back(read_results_csv(shards[s] / "results.csv"));
    if (shard_rows.back().size() < manifests[s].jobs)
      unfinished.push_back("shard " + std::to_string(manifests[s].shard) + " has " +
                           std::to_string(shard_rows.back().size()) + " of its " + std::to_string(manifests[s].jobs) +
                           " jobs (" + shards[s].string() + ")");
  }
  if (!missing.empty() || !unfinished.empty()) {
    std::string problem;
    if (!missing.empty())
      problem = "missing shard" + std::string(missing.size() > 1 ? "s " : " ") + number_list(missing) + " of " +
                std::to_string(shard_count);
    for (const std::string& line : unfinished) problem += (problem.empty() ? "" : "; ") + line;
    throw std::invalid_argument(problem + ": run them (with --resume) before merging");
  }

  std::map<std::size_t, Result_row> by_job;
  std::filesystem::create_directories(output / "pictures");
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const std::filesystem::path& shard = shards[s];
    for (const Result_row& row : shard_rows[s]) {
      const auto [it, added] = by_job.emplace(row.job(), row);
      if (!added && !same_job(it->second, row))
        throw std::invalid_argument("job " + row[Column::job] + " differs between shards (" + shard.string() + ")");
      const std::string& picture = row[Column::picture];
      if (!picture.empty() && std::filesystem::exists(shard / picture) &&
          !std::filesystem::equivalent(shard, output))
        std::filesystem::copy_file(shard / picture, output / picture, std::filesystem::copy_options::overwrite_existing);
    }
  }
  std::vector<Result_row> rows;
  for (auto& [job, row] : by_job) rows.push_back(std::move(row));
  const std::size_t count = rows.size();
  // The merged directory is the whole run, as if it had run on one machine.
  Run_manifest whole = manifests.front();
  whole.shard = whole.shards = 1, whole.jobs = count;
  write_manifest(output, whole);
  write_outputs(output, std::move(rows), report, pictures);
  return count;
}

std::pair<std::size_t, std::size_t> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  try {
    if (slash != std::string::npos) {
      std::size_t used_k = 0, used_n = 0;
      const std::size_t k = std::stoul(text.substr(0, slash), &used_k), n = std::stoul(text.substr(slash + 1), &used_n);
      if (used_k == slash && used_n == text.size() - slash - 1) return {k, n};
    }
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("--shard '" + text + "': expected K/N, e.g. 3/16");
}

bool make_report(const std::filesystem::path& dir) {
  write_algorithm_table(dir);
  const std::string script = (resource_root() / "bench/report/make_report.py").string();
  const std::string python = "/usr/bin/python3";
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    execl(python.c_str(), python.c_str(), script.c_str(), dir.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::cerr << "curvebench: the report failed (" << python << " " << script
              << "; needs Debian's python3-matplotlib: scripts/setup.sh installs it); results.csv is complete\n";
    return false;
  }
  return true;
}

}  // namespace curvebench::bench
