#include "bench/cli/run_command.h"

#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/cli/algorithm_options.h"
#include "bench/runner/run.h"
#include "bench/runner/slurm_array.h"

namespace curvebench::cli {
namespace {

struct Run_command_options {
  bench::Run_options run;
  std::vector<std::string> algorithms;  // as given: NAME,NAME,... or one exec:COMMAND each
  std::string shard, pictures = "some";
  bool no_report = false, quiet = false;
  std::uint64_t shuffle_seed = 0;
  CLI::Option* shuffle = nullptr;  // given: run.shuffle_seed is shuffle_seed
};

const std::map<std::string, bench::Pictures> picture_modes{{"some", bench::Pictures::some},
                                                          {"all", bench::Pictures::all},
                                                          {"failures", bench::Pictures::failures},
                                                          {"none", bench::Pictures::none}};
constexpr const char* pictures_help =
    "Pictures of reconstructions: some (per algorithm and suite, its first 6 failures and its first 2 jobs), all, "
    "failures (every job not exact) or none";

void run(Run_command_options& o) {
  o.run.algorithms = algorithm_names(o.algorithms);
  std::tie(o.run.shard, o.run.shards) = bench::chosen_shard(o.shard, bench::slurm_array_task_from_environment());
  o.run.pictures = picture_modes.at(o.pictures);
  o.run.report = !o.no_report;
  o.run.progress = !o.quiet;
  if (o.shuffle->count() > 0) o.run.shuffle_seed = o.shuffle_seed;
  const bench::Run_summary s = bench::run_suite(o.run);
  std::cerr << "run " << o.run.suite;
  if (o.run.shards > 1) std::cerr << " shard " << o.run.shard << '/' << o.run.shards;
  std::cerr << ": " << s.jobs << " jobs";
  if (s.resumed) std::cerr << " (" << s.resumed << " done before)";
  std::cerr << "; ran " << s.ok + s.failed + s.invalid_output + s.crashed + s.timed_out << ": " << s.ok << " ok, "
            << s.failed << " failed, ";
  if (s.invalid_output > 0) std::cerr << s.invalid_output << " invalid output, ";
  std::cerr << s.crashed << " crashed, " << s.timed_out << " timed out\n";
  std::cerr << "results: " << (o.run.output / "results.csv").string();
  if (o.run.report) std::cerr << ", report: " << (o.run.output / "report.html").string();
  std::cerr << '\n';
}

}  // namespace

void add_run_commands(CLI::App& app) {
  auto o = std::make_shared<Run_command_options>();
  CLI::App* command = app.add_subcommand("run", "Run a benchmark suite: every algorithm on every input, scored");
  command->add_option("SUITE", o->run.suite, "Suite name (see `curvebench list suites`)")->required();
  command->add_option("-o,--output", o->run.output, "Output directory (results.csv, results.json, pictures, report)")
      ->required();
  command->add_option("-a,--algorithms", o->algorithms,
                      "Algorithms to run (default: all): NAME,NAME,...; repeat -a for each external exec:COMMAND "
                      "(see `curvebench reconstruct --help`) or a name from --algorithm-file");
  add_algorithm_file_option(command);
  command->add_option("-j,--jobs", o->run.jobs, "Worker processes (default: one per core)");
  command->add_option("--shard", o->shard, "Run shard K of N (K/N), for job arrays; combine with `curvebench merge`. Default: the "
                      "Slurm array task's (SLURM_ARRAY_TASK_ID - MIN + 1 of MAX - MIN + 1), else the whole run");
  command->add_flag("--resume", o->run.resume, "Continue an interrupted run in the same directory");
  command->add_option("--timeout", o->run.timeout_seconds, "Time limit per job in seconds (0: none)")
      ->capture_default_str();
  command->add_option("--pictures", o->pictures, pictures_help)
      ->check(CLI::IsMember({"some", "all", "failures", "none"}))
      ->capture_default_str();
  command->add_flag("--no-report", o->no_report, "Do not write report.html and charts");
  command->add_flag("-q,--quiet", o->quiet, "No progress output");
  o->shuffle = command->add_option(
      "--shuffle-points", o->shuffle_seed,
      "Give each algorithm its input points in an order drawn from SEED (and the job), mapping its edges back: the "
      "rows must not change (an algorithm that returns points of its own gets the input as made)");
  command->callback([o] { run(*o); });

  auto merge_inputs = std::make_shared<std::vector<std::filesystem::path>>();
  auto merge_output = std::make_shared<std::filesystem::path>();
  auto merge_no_report = std::make_shared<bool>(false);
  auto merge_pictures = std::make_shared<std::string>("some");
  CLI::App* merge = app.add_subcommand("merge", "Combine the output directories of shard runs into one");
  merge->add_option("SHARD_DIR", *merge_inputs, "Output directories of `curvebench run --shard`")->required();
  merge->add_option("-o,--output", *merge_output, "Directory of the combined results and report")->required();
  merge->add_flag("--no-report", *merge_no_report, "Do not write report.html and charts");
  merge->add_option("--pictures", *merge_pictures, "The --pictures the shards ran with (some: capped again, as one run)")
      ->check(CLI::IsMember({"some", "all", "failures", "none"}))
      ->capture_default_str();
  merge->callback([=] {
    const std::size_t rows = bench::merge_runs(*merge_inputs, *merge_output, picture_modes.at(*merge_pictures), !*merge_no_report);
    std::cerr << "merged " << rows << " jobs into " << (*merge_output / "results.csv").string() << '\n';
  });

  auto report_dir = std::make_shared<std::filesystem::path>();
  CLI::App* report = app.add_subcommand("report", "Write report.html and charts of a run's results.csv again");
  report->add_option("DIR", *report_dir, "Output directory of a run")->required()->check(CLI::ExistingDirectory);
  report->callback([=] {
    if (!bench::make_report(*report_dir)) throw std::runtime_error("no report written");
  });
}

}  // namespace curvebench::cli
