#include "bench/cli/tightness_command.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "bench/cli/algorithm_options.h"
#include "bench/runner/tightness_case.h"
#include "certify/tightness_search.h"

namespace curvebench::cli {
namespace {

struct Tightness_command_options {
  std::vector<std::string> algorithms;
  certify::Tightness_options search;
  bool rho = false;
  std::filesystem::path output = std::filesystem::path("out") / "tightness";
  bool json = false;
};

void run(const Tightness_command_options& o) {
  certify::Tightness_options search = o.search;
  search.measure = o.rho ? certify::Measure::rho : certify::Measure::epsilon;
  nlohmann::json records = nlohmann::json::array();
  if (!o.json)
    std::cout << "algorithm            measure  bound   smallest failure f  f / b   curves (failing)  evaluations  seconds\n";
  for (const std::string& name : algorithm_names(o.algorithms)) {
    const algorithms::Algorithm& algorithm = chosen_algorithm(name);
    const certify::Tightness_result result = certify::search_tightness(algorithm, search);
    const nlohmann::json record = nlohmann::json::parse(
        bench::tightness_record_json(algorithm, result, o.output / (std::string(algorithm.name) + (o.rho ? "-rho" : ""))));
    records.push_back(record);
    if (o.json) continue;
    std::cout << std::left << std::setw(21) << algorithm.name << std::setw(9) << certify::measure_name(search.measure)
              << std::setw(8) << std::setprecision(3) << result.theorem.bound << std::setw(20)
              << (result.best ? std::to_string(result.best->measured).substr(0, 6)
                              : "none <= " + std::to_string(result.largest_passed).substr(0, 5))
              << std::setw(8)
              << (result.best ? std::to_string(result.best->measured / result.theorem.bound).substr(0, 5) : std::string("-"))
              << std::setw(18) << (std::to_string(result.curves) + " (" + std::to_string(result.failing_curves) + ")")
              << std::setw(13) << result.evaluations << std::setprecision(3) << result.seconds << '\n';
    if (result.best) std::cout << "  " << record["directory"].get<std::string>() << "/replay.sh\n";
  }
  if (o.json) std::cout << records.dump(2) << '\n';
}

}  // namespace

void add_tightness_command(CLI::App& app) {
  auto o = std::make_shared<Tightness_command_options>();
  CLI::App* command = app.add_subcommand(
      "tightness", "Search for the failing sampling of smallest measured epsilon (rho): how tight each proven bound is");
  command->add_option("-a,--algorithms", o->algorithms, "Algorithms with a proven bound: NAME,NAME,...")->required();
  command->add_flag("--rho", o->rho, "Search below the rho bound (HNN-Crust) instead of epsilon");
  command->add_option("--seconds", o->search.seconds, "Search time per algorithm")->capture_default_str();
  command->add_option("--curves", o->search.max_curves, "Stop after this many curves (0: search for --seconds)")
      ->capture_default_str();
  command->add_option("--moves", o->search.moves, "Sample moves tried per promising curve")->capture_default_str();
  command->add_option("--seed", o->search.seed, "Seed of the search")->capture_default_str();
  command->add_option("-o,--out", o->output, "Output directory: one case directory per algorithm")->capture_default_str();
  command->add_flag("--json", o->json, "Print the records as JSON");
  command->callback([o] { run(*o); });
}

}  // namespace curvebench::cli
