#include "bench/cli/certify_command.h"

#include <algorithm>
#include <iostream>
#include <memory>

#include "algorithms/registry.h"
#include "bench/cli/algorithm_options.h"
#include "bench/runner/certification.h"
#include "bench/runner/slurm_array.h"

namespace curvebench::cli {
namespace {

struct Certify_command_options {
  std::string algorithm;
  bench::Certify_options certify;
  std::optional<double> below_bound;
  std::filesystem::path output;
  std::string shard;
  bool rho = false, json = false, quiet = false;
};

void run(Certify_command_options& o) {
  const algorithms::Algorithm* algorithm = &chosen_algorithm(o.algorithm);
  std::string name(algorithm->name);
  if (o.below_bound) o.certify.below_bound = *o.below_bound;
  if (o.rho) o.certify.measure = certify::Measure::rho;
  std::tie(o.certify.run.shard, o.certify.run.shards) =
      bench::chosen_shard(o.shard, bench::slurm_array_task_from_environment());
  o.certify.run.output = o.output.empty() ? std::filesystem::path("out") / ("certify-" + name) : o.output;
  o.certify.run.progress = !o.quiet && !o.json;
  o.certify.run.pictures = bench::Pictures::failures;
  const bench::Certify_summary s = bench::certify_algorithm(*algorithm, o.certify);

  if (o.json) {
    std::cout << bench::certify_summary_json(s, o.certify) << '\n';
    return;
  }
  const std::string measure(certify::measure_name(s.measure));
  std::cout << s.algorithm << ": " << measure << " < " << s.bound << ", " << s.cases << " " << o.certify.curves
            << " cases sampled at " << measure << " " << s.requested_level << ": " << s.passed << " passed, " << s.failures
            << " failures, " << s.inconclusive << " inconclusive, " << s.hypothesis_violations
            << " hypothesis violations\n";
  for (const bench::Counterexample& c : s.counterexamples)
    std::cout << "counterexample: " << c.input << " (" << c.points << " points, measured " << measure << " " << c.measured
              << "): sh " << (c.directory / "replay.sh").string() << '\n';
}

}  // namespace

void add_certify_command(CLI::App& app) {
  auto o = std::make_shared<Certify_command_options>();
  CLI::App* command = app.add_subcommand(
      "certify", "Check an algorithm's sampling-condition theorem (on epsilon, or with --rho on rho) on generated "
                 "curves, shrinking counterexamples");
  command->add_option("-a,--algorithm", o->algorithm,
                      "Algorithm with a proven epsilon bound (see `curvebench list`), or an external one from "
                      "--algorithm-file with a claimed one")
      ->required();
  add_algorithm_file_option(command);
  command->add_option("--curves", o->certify.curves,
                      "fourier (random smooth closed curves), multi (2 or 3 of them side by side), nested (one inside "
                      "another), rounded (stars with rounded corners), open (curves with ends, for a theorem that "
                      "covers them), mixed (those the theorem is stated for, in turn), svg or glyphs")
      ->check(CLI::IsMember({"fourier", "multi", "nested", "rounded", "open", "mixed", "svg", "glyphs"}))
      ->capture_default_str();
  command->add_option("--count", o->certify.count, "Number of cases")->capture_default_str();
  command->add_flag("--rho", o->rho, "Certify the theorem on rho (HNN-Crust's rho < 0.9), not on epsilon");
  auto* at = command->add_option_group("level", "where to sample");
  at->add_option("--epsilon", o->certify.level, "Sample at this epsilon (with --rho: this rho)");
  at->add_option("--below-bound", o->below_bound, "Sample at this fraction of the proven bound (default 0.95)");
  at->require_option(0, 1);
  command->add_option("--seed", o->certify.seed, "Seed of the generated curves")->capture_default_str();
  command->add_option("-o,--output", o->output, "Output directory (default out/certify-ALGORITHM), written anew");
  command->add_option("-j,--jobs", o->certify.run.jobs, "Worker processes (default: one per core)");
  command->add_option("--shard", o->shard, "Run shard K of N (K/N); combine with `curvebench merge`. Default: the Slurm array task's, else all");
  command->add_flag("--resume", o->certify.run.resume, "Continue an interrupted certification");
  command->add_option("--timeout", o->certify.run.timeout_seconds, "Time limit per case in seconds")->capture_default_str();
  command->add_flag("--json", o->json, "Print the summary as JSON");
  command->add_flag("-q,--quiet", o->quiet, "No progress output");
  command->callback([o] { run(*o); });
}

}  // namespace curvebench::cli
