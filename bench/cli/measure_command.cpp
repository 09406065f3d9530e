#include "bench/cli/measure_command.h"

#include <iostream>
#include <memory>

#include "bench/cli/sample_files.h"
#include "bench/runner/sampling_report.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::cli {
namespace {

struct Measure_options {
  std::string curve;
  std::filesystem::path points, edges;
  std::optional<double> minimum_lfs;
};

void run_measure(Measure_options o) {
  const geometry::Local_feature_size lfs(geometry::make_curve(o.curve));
  if (o.edges.empty()) {  // BASE.edges beside BASE.xy, as `curvebench sample` writes them
    auto beside = o.points;
    if (std::filesystem::exists(beside.replace_extension(".edges"))) o.edges = beside;
  }
  geometry::Sample sample = read_sample(lfs, o.points, o.edges);
  sample.minimum_lfs = o.minimum_lfs.value_or(geometry::default_minimum_lfs(lfs));
  std::cout << bench::measure_report_json(lfs, sample, o.edges.string()) << '\n';
}

}  // namespace

void add_measure_command(CLI::App& app) {
  auto o = std::make_shared<Measure_options>();
  CLI::App* command = app.add_subcommand("measure", "Measure a sampling of a curve: epsilon, rho, uniformity (JSON)");
  command->add_option("--curve", o->curve, "Curve spec (see `curvebench sample --help`)")->required();
  command->add_option("-i,--input", o->points, "Point file")->required()->check(CLI::ExistingFile);
  command->add_option("-e,--edges", o->edges, "Ground-truth edges (default: POINTS with extension .edges, if any)")
      ->check(CLI::ExistingFile);
  command->add_option("--min-lfs", o->minimum_lfs, "lfs floor (default 1e-3 of the bbox diagonal; 0: none)");
  command->callback([o] { run_measure(*o); });
}

}  // namespace curvebench::cli
