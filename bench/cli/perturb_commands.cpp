#include "bench/cli/perturb_commands.h"

#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include "bench/cli/sample_files.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "geometry/sampling/sampling_noise.h"

namespace curvebench::cli {
namespace {

struct Perturb_options {
  std::filesystem::path input, output;
  std::string curve;
  std::optional<double> uniform, lfs;
  double percent = 0;
  std::uint64_t seed = 0;
};

std::filesystem::path edges_beside(std::filesystem::path points) {
  return std::filesystem::exists(points.replace_extension(".edges")) ? points : std::filesystem::path();
}

// The point file as a Sample whose position on the curve is unknown: enough for the
// models that need only the points (uniform noise, outliers).
geometry::Sample read_points_only(const std::filesystem::path& points) {
  geometry::Sample sample;
  sample.points = geometry::read_point_file(points).points;
  if (const auto edges = edges_beside(points); !edges.empty()) sample.edges = geometry::read_edges(edges);
  sample.lfs.assign(sample.size(), std::numeric_limits<double>::quiet_NaN());
  sample.locations.assign(sample.size(), {});
  sample.labels.assign(sample.size(), geometry::Sample_label::curve_point);
  return sample;
}

void finish(const Perturb_options& o, const geometry::Sample& sample) {
  write_sample(o.output, sample);
  std::cout << o.output.string() << ".xy: " << sample.size() << " points\n";
}

void add_common_options(CLI::App* command, Perturb_options& o) {
  command->add_option("-i,--input", o.input, "Point file (its .edges, if any, is carried along)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--seed", o.seed, "seed")->capture_default_str();
  command->add_option("-o,--output", o.output, "write BASE.xy, BASE.edges, BASE.lfs, BASE.labels")->required();
}

}  // namespace

void add_noise_command(CLI::App& app) {
  auto o = std::make_shared<Perturb_options>();
  CLI::App* command = app.add_subcommand("noise", "Add uniform or lfs noise to a point file");
  add_common_options(command, *o);
  auto* model = command->add_option_group("model", "exactly one noise model");
  model->add_option("--uniform", o->uniform, "offsets of length uniform in [0, DELTA x bbox diagonal], random direction");
  model->add_option("--lfs", o->lfs, "offsets along the curve normal, uniform in [-DELTA, DELTA] x lfs (needs --curve)");
  model->require_option(1);
  command->add_option("--curve", o->curve, "the curve the points sample (for --lfs)");
  command->callback([o] {
    if (o->uniform) return finish(*o, geometry::with_uniform_noise(read_points_only(o->input), *o->uniform, o->seed));
    if (o->curve.empty()) throw std::invalid_argument("noise --lfs needs --curve SPEC");
    const geometry::Local_feature_size lfs(geometry::make_curve(o->curve));
    finish(*o, geometry::with_lfs_noise(lfs, read_sample(lfs, o->input, edges_beside(o->input)), *o->lfs, o->seed));
  });
}

void add_outliers_command(CLI::App& app) {
  auto o = std::make_shared<Perturb_options>();
  CLI::App* command = app.add_subcommand("outliers", "Add outliers uniform in the bounding box of a point file");
  add_common_options(command, *o);
  command->add_option("--percent", o->percent, "outliers as a percentage of the points")->required();
  command->callback([o] { finish(*o, geometry::with_outliers(read_points_only(o->input), o->percent, o->seed)); });
}

}  // namespace curvebench::cli
