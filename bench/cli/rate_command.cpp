#include "bench/cli/rate_command.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "bench/cli/algorithm_options.h"
#include "bench/runner/external_algorithm.h"
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

void run_rate(const Rate_options& options) {
  const std::vector<const algorithms::Algorithm*> chosen = bench::find_algorithms(algorithm_names(options.algorithms));
  std::vector<std::string> specs;
  for (const std::string& spec : options.curves)
    for (std::string& one : geometry::expand_curve_specs(spec)) specs.push_back(std::move(one));
  std::vector<std::string> every;
  for (std::size_t i = 0; i < specs.size(); i += std::max<std::size_t>(options.stride, 1)) every.push_back(specs[i]);

  const auto threads = options.jobs > 0 ? options.jobs : tbb::this_task_arena::max_concurrency();
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  Tally tally(chosen.size(), options.epsilons.size());
  tbb::parallel_for(std::size_t{0}, every.size(), [&](std::size_t i) {
    rate_curve(every[i], options, chosen, tally);
    if (const std::size_t done = ++tally.done; done % 100 == 0 || done == every.size())
      std::cerr << "rated " << done << " / " << every.size() << " curves\n";
  });

  std::cout << "Exact reconstructions of " << every.size() << " curves (" << options.curves.front()
            << (options.curves.size() > 1 ? ", ..." : "") << "), safe epsilon-sampling\n";
  std::cout << std::left << std::setw(20) << "algorithm";
  for (const double epsilon : options.epsilons) std::cout << std::setw(18) << ("epsilon " + std::to_string(epsilon).substr(0, 4));
  std::cout << '\n';
  for (std::size_t a = 0; a < chosen.size(); ++a) {
    std::cout << std::setw(20) << chosen[a]->name;
    for (std::size_t e = 0; e < options.epsilons.size(); ++e) {
      const std::size_t exact = tally.exact[a][e], sampled = tally.sampled[e];
      std::ostringstream cell;
      cell << std::fixed << std::setprecision(1) << (sampled ? 100.0 * exact / sampled : 0.0) << "% (" << exact << ")";
      std::cout << std::setw(18) << cell.str();
    }
    std::cout << '\n';
  }
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
  command->add_option("-j,--jobs", options->jobs, "Threads (default: all cores)");
  command->callback([options] { run_rate(*options); });
}

}  // namespace curvebench::cli
