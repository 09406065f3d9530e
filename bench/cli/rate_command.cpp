#include "bench/cli/rate_command.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <map>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "bench/cli/algorithm_options.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/results_table.h"
#include "bench/runner/run.h"
#include "bench/runner/slurm_array.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::cli {
namespace {

struct Rate_options {
  std::vector<std::string> curves{"glyph:*"};
  std::vector<double> epsilons{0.2, 0.4, 0.6};
  std::vector<std::string> algorithms;
  std::size_t stride = 1;
  std::size_t jobs = 0;
  // With an output directory the curves run as jobs of the benchmark runner (run.h), so a
  // rating can be sharded (a Slurm array), resumed and merged like a run.
  std::filesystem::path output;
  std::string shard;
  bool resume = false, quiet = false;
};

// exact[a][e]: curves that algorithm a reconstructs exactly at epsilon e; sampled[e]:
// curves sampled at epsilon e (a curve the sampler rejects is left out and reported).
struct Tally {
  std::vector<std::vector<std::atomic<std::size_t>>> exact;
  std::vector<std::atomic<std::size_t>> sampled;
  std::atomic<std::size_t> done{0};
  std::mutex errors_guard;
  std::vector<std::string> errors;

  Tally(std::size_t algorithms, std::size_t epsilons) : exact(algorithms), sampled(epsilons) {
    for (auto& row : exact) row = std::vector<std::atomic<std::size_t>>(epsilons);
  }
  void error(std::string what) {
    const std::lock_guard lock(errors_guard);
    errors.push_back(std::move(what));
  }
};

void rate_curve(const std::string& spec, const Rate_options& options,
                const std::vector<const algorithms::Algorithm*>& chosen, Tally& tally) {
  try {
    const geometry::Local_feature_size lfs(geometry::make_curve(spec));
    const double minimum_lfs = geometry::default_minimum_lfs(lfs);
    for (std::size_t e = 0; e < options.epsilons.size(); ++e) {
      const geometry::Sample sample = geometry::safe_epsilon_sampling(lfs, options.epsilons[e], minimum_lfs);
      const std::vector<geometry::Edge> truth = geometry::canonical_edges(sample.edges);
      ++tally.sampled[e];
      for (std::size_t a = 0; a < chosen.size(); ++a) {
        try {
          if (algorithms::reconstruct(*chosen[a], sample.points).edges == truth) ++tally.exact[a][e];
        } catch (const std::exception& error) {
          tally.error(spec + ": " + std::string(chosen[a]->name) + " threw: " + error.what());
        }
      }
    }
  } catch (const std::exception& error) {
    tally.error(spec + ": " + error.what());
  }
}

// exact[a][e] of sampled[a][e] curves, per algorithm a and epsilon e, as a table on
// stdout; "-" where an algorithm had none (a shard may hold no job of it), and no rate
// for a simplifier, whose output is never the interpolating truth (as in the report).
void print_table(std::size_t curves, const Rate_options& options, const std::vector<const algorithms::Algorithm*>& chosen,
                 const std::vector<std::vector<std::size_t>>& exact, const std::vector<std::vector<std::size_t>>& sampled) {
  std::cout << "Exact reconstructions of " << curves << " curves (" << options.curves.front()
            << (options.curves.size() > 1 ? ", ..." : "") << "), safe epsilon-sampling\n";
  std::cout << std::left << std::setw(20) << "algorithm";
  for (const double epsilon : options.epsilons) std::cout << std::setw(18) << ("epsilon " + std::to_string(epsilon).substr(0, 4));
  std::cout << '\n';
  for (std::size_t a = 0; a < chosen.size(); ++a) {
    std::cout << std::setw(20) << chosen[a]->name;
    for (std::size_t e = 0; e < options.epsilons.size(); ++e) {
      std::ostringstream cell;
      if (sampled[a][e] == 0) cell << "-";
      else if (chosen[a]->simplifies) cell << "n/a (simplifies)";
      else cell << std::fixed << std::setprecision(1) << 100.0 * exact[a][e] / sampled[a][e] << "% (" << exact[a][e] << ")";
      std::cout << std::setw(18) << cell.str();
    }
    std::cout << '\n';
  }
}

std::vector<std::size_t> counts(const std::vector<std::atomic<std::size_t>>& atomic) {
  return {atomic.begin(), atomic.end()};
}

std::vector<std::vector<std::size_t>> counts(const std::vector<std::vector<std::atomic<std::size_t>>>& atomic) {
  std::vector<std::vector<std::size_t>> plain;
  for (const auto& row : atomic) plain.push_back(counts(row));
  return plain;
}

// The same rating as jobs of the runner: case (curve, epsilon) is the input
// CURVE|epsilon=E, sampled by the same safe sampler, and a job is exact when its edges
// are the ground truth, as above. The table counts the rows of DIR/results.csv.
void rate_with_runner(const Rate_options& options, const std::vector<const algorithms::Algorithm*>& chosen,
                      const std::vector<std::string>& curves, std::pair<std::size_t, std::size_t> shard) {
  std::vector<bench::Suite_case> cases;
  std::map<std::string, std::size_t> epsilon_of_level;
  for (std::size_t e = 0; e < options.epsilons.size(); ++e)
    epsilon_of_level["epsilon=" + bench::format_number(options.epsilons[e])] = e;
  for (const std::string& curve : curves)
    for (const double epsilon : options.epsilons)
      cases.push_back({"rate", curve + "|epsilon=" + bench::format_number(epsilon), "epsilon=" + bench::format_number(epsilon)});
  bench::Run_options run{.suite = "rate", .output = options.output, .jobs = options.jobs, .shard = shard.first,
                         .shards = shard.second, .resume = options.resume, .pictures = bench::Pictures::none,
                         .report = false, .progress = !options.quiet};
  bench::run_cases(cases, chosen, run);

  std::map<std::string_view, std::size_t> algorithm_index;
  for (std::size_t a = 0; a < chosen.size(); ++a) algorithm_index[chosen[a]->name] = a;
  std::vector<std::vector<std::size_t>> exact(chosen.size(), std::vector<std::size_t>(options.epsilons.size())),
      sampled = exact;
  std::set<std::string> rated;
  std::vector<std::string> errors;
  for (const bench::Result_row& row : bench::read_results_csv(options.output / "results.csv")) {
    const std::size_t e = epsilon_of_level.at(row[bench::Column::level]);
    const std::size_t a = algorithm_index.at(row[bench::Column::algorithm]);
    const std::string& input = row[bench::Column::input];
    rated.insert(input.substr(0, input.rfind('|')));
    sampled[a][e] += !row[bench::Column::n_points].empty();  // else the sampler failed: left out, as above
    exact[a][e] += row[bench::Column::exact] == "1";
    if (row[bench::Column::status] != "ok")
      errors.push_back(input + ": " + row[bench::Column::algorithm] + " " + row[bench::Column::status] + ": " +
                       row[bench::Column::message]);
  }
  if (shard.second > 1) std::cout << "Shard " << shard.first << '/' << shard.second << ". ";
  print_table(rated.size(), options, chosen, exact, sampled);
  std::ranges::sort(errors);
  for (const std::string& error : errors) std::cerr << "error: " << error << '\n';
}

void run_rate(const Rate_options& options) {
  const std::vector<const algorithms::Algorithm*> chosen = bench::find_algorithms(algorithm_names(options.algorithms));
  std::vector<std::string> specs;
  for (const std::string& spec : options.curves)
    for (std::string& one : geometry::expand_curve_specs(spec)) specs.push_back(std::move(one));
  std::vector<std::string> every;
  for (std::size_t i = 0; i < specs.size(); i += std::max<std::size_t>(options.stride, 1)) every.push_back(specs[i]);
  const auto shard = bench::chosen_shard(options.shard, bench::slurm_array_task_from_environment());
  if (!options.output.empty()) return rate_with_runner(options, chosen, every, shard);
  if (shard.second > 1 || options.resume)
    throw std::invalid_argument("rate: a shard (--shard or a Slurm array task) or --resume needs -o DIR");

  const auto threads = options.jobs > 0 ? options.jobs : tbb::this_task_arena::max_concurrency();
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  Tally tally(chosen.size(), options.epsilons.size());
  tbb::parallel_for(std::size_t{0}, every.size(), [&](std::size_t i) {
    rate_curve(every[i], options, chosen, tally);
    if (const std::size_t done = ++tally.done; !options.quiet && (done % 100 == 0 || done == every.size()))
      std::cerr << "rated " << done << " / " << every.size() << " curves\n";
  });

  print_table(every.size(), options, chosen, counts(tally.exact),
              std::vector<std::vector<std::size_t>>(chosen.size(), counts(tally.sampled)));
  std::ranges::sort(tally.errors);
  for (const std::string& error : tally.errors) std::cerr << "error: " << error << '\n';
}

}  // namespace

void add_rate_command(CLI::App& app) {
  auto options = std::make_shared<Rate_options>();
  CLI::App* command =
      app.add_subcommand("rate", "Exact-reconstruction rate of the algorithms over safe-epsilon-sampled curves");
  command->add_option("-c,--curves", options->curves, "Curve specs (glyph:* = every glyph of DejaVuSans.ttf)")
      ->capture_default_str();
  command->add_option("-e,--epsilon", options->epsilons, "Epsilons to sample at")->delimiter(',')->capture_default_str();
  command->add_option("-a,--algorithms", options->algorithms,
                      "Algorithms to rate (default: all): NAME,NAME,...; repeat -a for each exec:COMMAND");
  add_algorithm_file_option(command);
  command->add_option("--stride", options->stride, "Rate every k-th curve only")->capture_default_str();
  command->add_option("-j,--jobs", options->jobs, "Threads, or with -o worker processes (default: all cores)");
  command->add_option("-o,--output", options->output,
                      "Rate as jobs of the benchmark runner, rows in DIR/results.csv: resumable, shardable, mergeable "
                      "with `curvebench merge`");
  command->add_option("--shard", options->shard,
                      "With -o: rate shard K of N (K/N). Default: the Slurm array task's, else all");
  command->add_flag("--resume", options->resume, "With -o: continue an interrupted rating in DIR");
  command->add_flag("-q,--quiet", options->quiet, "No progress output");
  command->callback([options] { run_rate(*options); });
}

}  // namespace curvebench::cli
