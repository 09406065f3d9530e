#include "bench/cli/sample_command.h"

#include <iostream>
#include <memory>
#include <optional>

#include "bench/cli/sample_files.h"
#include "geometry/curves/curve_spec.h"
#include "bench/runner/curve_sampling.h"

namespace curvebench::cli {
namespace {

struct Sample_options {
  std::string curve;
  bench::Sampling_request request;
  std::filesystem::path base;
  bool svg = false;
};

void run_sample(const Sample_options& o) {
  const geometry::Local_feature_size lfs(geometry::make_curve(o.curve));
  const geometry::Sample sample = bench::sample_curve(lfs, o.request);
  write_sample(o.base, sample);
  if (o.svg) write_sample_picture(std::filesystem::path(o.base) += ".svg", lfs, sample);
  std::cout << o.base.string() << ".xy: " << sample.size() << " points, " << sample.edges.size() << " edges";
  if (!sample.floored.empty())
    std::cout << ", " << sample.floored.size() << " spaced by the lfs floor " << sample.minimum_lfs
              << " (near sharp points)";
  std::cout << '\n';
}

}  // namespace

void add_sample_command(CLI::App& app) {
  auto o = std::make_shared<Sample_options>();
  CLI::App* command = app.add_subcommand("sample", "Sample a curve: points, ground-truth edges and lfs");
  command->add_option("--curve", o->curve, "Curve spec: circle:r=1, ellipse:a=2,b=1, superellipse:a=1,b=1,n=4, "
                                           "fourier:seed=7[,gap=G|,components=K,separation=D], "
                                           "nested:seed=7,separation=0.1, spiral:seed=7, lissajous:a=1,b=2,seed=7, "
                                           "corner:angle=30, star:seed=7,angle=60[,rounding=R], svg:FILE[,corner=DEG], "
                                           "glyph:[FONT:]CHAR")
      ->required();
  auto* how = command->add_option_group("sampler", "exactly one sampler");
  how->add_option("--epsilon", o->request.epsilon, "epsilon-sampling by the survey's greedy walk");
  how->add_option("--rho", o->request.rho, "HNN-Crust's rho-sampling");
  how->add_option("--uniform", o->request.uniform, "N points at equal arc-length steps");
  how->add_option("--random", o->request.random, "N points uniform in arc length (--seed)");
  how->require_option(1);
  command->add_flag("--safe", o->request.safe, "with --epsilon or --rho: guarantee the measured epsilon (rho) stays below it");
  command->add_flag("--crossing-samples", o->request.crossing_samples,
                    "a sample on every crossing, shared by both branches (degree 4 in the ground truth)");
  command->add_option("--min-lfs", o->request.minimum_lfs, "lfs floor near sharp points (default 1e-3 of the bbox diagonal)");
  command->add_option("--uniform-noise", o->request.uniform_noise, "add uniform noise of extent DELTA x bbox diagonal");
  command->add_option("--lfs-noise", o->request.lfs_noise, "add noise along the normal, uniform in [-DELTA, DELTA] x lfs");
  command->add_option("--outliers", o->request.outliers, "add PERCENT outliers uniform in the bounding box");
  command->add_option("--seed", o->request.seed, "seed of every random choice")->capture_default_str();
  command->add_option("-o,--output", o->base, "write BASE.xy, BASE.edges, BASE.lfs, BASE.labels")->required();
  command->add_flag("--svg", o->svg, "also draw curve, medial axis and samples to BASE.svg");
  command->callback([o] { run_sample(*o); });
}

}  // namespace curvebench::cli
