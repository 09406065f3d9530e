#include "bench/cli/certify_command.h"

#include <algorithm>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "algorithms/registry.h"
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
  bool json = false, quiet = false;
};

void run(Certify_command_options& o) {
  std::string name = o.algorithm;
  std::ranges::replace(name, '_', '-');  // nn_crust names nn-crust too
  const algorithms::Algorithm* algorithm = algorithms::find_algorithm(name);
  if (!algorithm) throw std::invalid_argument("unknown algorithm '" + o.algorithm + "' (see `curvebench list`)");
  if (o.below_bound) o.certify.below_bound = *o.below_bound;
  std::tie(o.certify.run.shard, o.certify.run.shards) =
      bench::chosen_shard(o.shard, bench::slurm_array_task_from_environment());
  o.certify.run.output = o.output.empty() ? std::filesystem::path("out") / ("certify-" + name) : o.output;
  o.certify.run.progress = !o.quiet && !o.json;
  o.certify.run.pictures = bench::Pictures::failures;
  const bench::Certify_summary s = bench::certify_algorithm(*algorithm, o.certify);

  nlohmann::json counterexamples = nlohmann::json::array();
  for (const bench::Counterexample& c : s.counterexamples)
    counterexamples.push_back({{"input", c.input}, {"points", c.points}, {"epsilon", c.epsilon},
                               {"path", c.directory.string()}, {"replay", (c.directory / "replay.sh").string()}});
  const nlohmann::json summary = {
      {"algorithm", s.algorithm},
      {"bound", s.bound},
      {"requested_epsilon", s.requested_epsilon},
      {"curves", o.certify.curves},
      {"seed", o.certify.seed},
      {"cases", s.cases},
      {"passed", s.passed},
      {"failures", s.failures},
      {"inconclusive", s.inconclusive},
      {"hypothesis_violations", s.hypothesis_violations},
      {"counterexamples", counterexamples},
      {"results", (o.certify.run.output / "results.csv").string()},
  };
  if (o.json) {
    std::cout << summary.dump(2) << '\n';
    return;
  }
  std::cout << s.algorithm << ": epsilon < " << s.bound << ", " << s.cases << " " << o.certify.curves
            << " cases sampled at epsilon " << s.requested_epsilon << ": " << s.passed << " passed, " << s.failures
            << " failures, " << s.inconclusive << " inconclusive, " << s.hypothesis_violations
            << " hypothesis violations\n";
  for (const bench::Counterexample& c : s.counterexamples)
    std::cout << "counterexample: " << c.input << " (" << c.points << " points, measured epsilon " << c.epsilon
              << "): sh " << (c.directory / "replay.sh").string() << '\n';
}

}  // namespace

void add_certify_command(CLI::App& app) {
  auto o = std::make_shared<Certify_command_options>();
  CLI::App* command = app.add_subcommand(
      "certify", "Check an algorithm's sampling-condition theorem on generated curves, shrinking counterexamples");
  command->add_option("-a,--algorithm", o->algorithm, "Algorithm with a proven epsilon bound (see `curvebench list`)")
      ->required();
  command->add_option("--curves", o->certify.curves, "fourier (random smooth closed curves), multi (2 or 3 of them side by side), svg or glyphs")
      ->check(CLI::IsMember({"fourier", "svg", "glyphs"}))
      ->capture_default_str();
  command->add_option("--count", o->certify.count, "Number of cases")->capture_default_str();
  auto* at = command->add_option_group("epsilon", "where to sample");
  at->add_option("--epsilon", o->certify.epsilon, "Sample at this epsilon");
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
