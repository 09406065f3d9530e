#include "bench/cli/tightness_command.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "bench/cli/algorithm_options.h"
#include "bench/runner/external_algorithm.h"
#include "certify/tightness_search.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "geometry/io/svg_picture.h"

namespace curvebench::cli {
namespace {

struct Tightness_command_options {
  std::vector<std::string> algorithms;
  certify::Tightness_options search;
  bool rho = false;
  std::filesystem::path output = std::filesystem::path("out") / "tightness";
  bool json = false;
};

// The case's files; returns its directory's JSON record.
nlohmann::json write_case(const std::filesystem::path& directory, const algorithms::Algorithm& algorithm,
                          const certify::Tightness_result& result) {
  const certify::Tightness_case& c = *result.best;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  geometry::write_points(directory / "points.xy", c.sample.points);
  geometry::write_edges(directory / "truth.edges", geometry::canonical_edges(c.sample.edges));
  geometry::write_edges(directory / "reconstruction.edges", c.reconstruction);
  std::ofstream(directory / "curve.txt") << c.curve << '\n';

  geometry::SvgPicture picture(c.sample.points);
  const std::string measure(certify::measure_name(result.theorem.measure));
  std::ostringstream title;
  title << algorithm.name << " fails at measured " << measure << ' ' << std::setprecision(4) << c.measured
        << " (proven bound " << result.theorem.bound << "): " << c.curve;
  picture.set_title(title.str());
  picture.add_edges(c.sample.edges, {.colour = "#bbbbbb", .width_px = 5, .legend = "ground truth"});
  picture.add_edges(c.reconstruction, {.colour = "#d62728", .width_px = 1.5, .legend = std::string(algorithm.name)});
  picture.add_points();
  picture.write(directory / "picture.svg");

  std::ofstream replay(directory / "replay.sh");
  replay << "#!/bin/sh\n# " << algorithm.name << " does not reconstruct these " << c.sample.size()
         << " points of " << c.curve << "\n# (measured " << measure << ' ' << std::setprecision(17) << c.measured
         << "; proven bound " << result.theorem.bound << "). Run from this directory with curvebench on PATH.\n"
         << "set -e\ncurvebench reconstruct " << bench::replay_arguments(algorithm)
         << " -i points.xy -o replayed.edges --svg replayed.svg\n"
         << "cmp replayed.edges reconstruction.edges && echo 'the same edges as found'\n"
         << "curvebench evaluate -i points.xy -e replayed.edges -g truth.edges\n"
         << "curvebench measure --curve " << bench::shell_quoted(c.curve) << " -i points.xy -e truth.edges --min-lfs 0\n";
  replay.close();
  std::filesystem::permissions(directory / "replay.sh", std::filesystem::perms::owner_exec, std::filesystem::perm_options::add);

  const nlohmann::json record = {{"algorithm", algorithm.name},  {"measure", measure},
                                 {"bound", result.theorem.bound}, {"smallest_failure", c.measured},
                                 {"ratio", c.measured / result.theorem.bound},
                                 {"curve", c.curve},              {"points", c.sample.size()},
                                 {"level", c.level},              {"samples_added", c.added},
                                 {"moves_kept", c.moved},         {"error", c.error},
                                 {"largest_passed", result.largest_passed},
                                 {"curves", result.curves},       {"failing_curves", result.failing_curves},
                                 {"evaluations", result.evaluations}, {"seconds", result.seconds},
                                 {"directory", directory.string()}};
  std::ofstream(directory / "case.json") << record.dump(2) << '\n';
  return record;
}

void run(const Tightness_command_options& o) {
  certify::Tightness_options search = o.search;
  search.measure = o.rho ? certify::Measure::rho : certify::Measure::epsilon;
  nlohmann::json records = nlohmann::json::array();
  if (!o.json)
    std::cout << "algorithm            measure  bound   smallest failure f  f / b   curves (failing)  evaluations  seconds\n";
  for (const std::string& name : algorithm_names(o.algorithms)) {
    const algorithms::Algorithm& algorithm = chosen_algorithm(name);
    const certify::Tightness_result result = certify::search_tightness(algorithm, search);
    nlohmann::json record = {{"algorithm", algorithm.name}, {"bound", result.theorem.bound},
                             {"largest_passed", result.largest_passed},
                             {"curves", result.curves},     {"failing_curves", result.failing_curves},
                             {"evaluations", result.evaluations}, {"seconds", result.seconds}};
    if (result.best) record = write_case(o.output / (std::string(algorithm.name) + (o.rho ? "-rho" : "")), algorithm, result);
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
