#include "bench/cli/ambiguity_command.h"

#include <chrono>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "certify/ambiguity_search.h"

namespace curvebench::cli {
namespace {

struct Ambiguity_command_options {
  certify::Ambiguity_search_options search;
  std::filesystem::path output = std::filesystem::path("out") / "ambiguity";
  bool json = false;
};

void run(const Ambiguity_command_options& o) {
  const auto start = std::chrono::steady_clock::now();
  const certify::Ambiguity_search_result result = certify::search_ambiguity(o.search);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<std::pair<std::string, double>> extra = {
      {"starts", static_cast<double>(o.search.count)},
      {"evaluations", static_cast<double>(result.evaluations)},
      {"best_start", static_cast<double>(result.best_start)},
      {"mirror", o.search.mirror ? 1.0 : 0.0},
      {"seconds", seconds}};
  const certify::Ambiguity_files files =
      certify::write_ambiguity_case(o.output, result.best, result.measure, o.search.seed, extra);
  const nlohmann::json summary = {
      {"points", result.best.points.size()},
      {"epsilon_1", result.measure.epsilon[0]},
      {"epsilon_2", result.measure.epsilon[1]},
      {"max_epsilon", result.measure.max_epsilon()},
      {"valid", result.measure.valid},
      {"lfs_error_bound", certify::lfs_relative_error_bound},
      {"seed", o.search.seed},
      {"starts", o.search.count},
      {"start_results", result.start_results},
      {"evaluations", result.evaluations},
      {"seconds", seconds},
      {"directory", o.output.string()},
      {"picture", files.picture.string()},
      {"replay", files.replay.string()},
  };
  if (o.json) {
    std::cout << summary.dump(2) << '\n';
    return;
  }
  std::cout << "ambiguity: " << o.search.count << " starts, " << result.evaluations << " evaluations in " << seconds
            << " s\nbest: " << result.best.points.size() << " points, epsilon " << result.measure.epsilon[0]
            << " (C1) and " << result.measure.epsilon[1] << " (C2), max " << result.measure.max_epsilon()
            << (result.measure.max_epsilon() < 0.72 ? " < 0.72" : " (not below 0.72)") << ", lfs relative error <= "
            << certify::lfs_relative_error_bound << "\npicture: " << files.picture.string()
            << "\nreplay: sh " << files.replay.string() << '\n';
}

}  // namespace

void add_ambiguity_command(CLI::App& app) {
  auto o = std::make_shared<Ambiguity_command_options>();
  CLI::App* command = app.add_subcommand(
      "ambiguity", "Search point sets that epsilon-sample two smooth curves with different polygons (smallest epsilon)");
  command->add_option("--count", o->search.count, "Number of independent starts")->capture_default_str();
  command->add_option("--points", o->search.points, "Points per start (0: drawn from 6..16)")->capture_default_str();
  command->add_option("--seed", o->search.seed, "Seed of the search")->capture_default_str();
  command->add_option("--evaluations", o->search.evaluations, "Hill-climbing steps per start")->capture_default_str();
  command->add_flag("--via-points", o->search.via_points,
                    "After the climb, let each curve pass through a free point (not a sample) between every two samples, "
                    "and climb as long again");
  command->add_flag("--mirror", o->search.mirror,
                    "Search mirror-symmetric cases only (S = R(S), C2 = R(C1)), from where a random curve crosses its "
                    "mirror image; --points is then the exact size of S");
  command->add_option("-o,--out", o->output, "Output directory for the best case")->capture_default_str();
  command->add_flag("--json", o->json, "Print the summary as JSON");
  command->callback([o] { run(*o); });
}

}  // namespace curvebench::cli
