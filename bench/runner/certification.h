// `curvebench certify`: a sampling-condition theorem (certify/theorems.h) as an experiment.
// Generated curves are sampled so that the *measured* epsilon lies below the bound, each
// case is reconstructed as a job of the benchmark runner (run.h: parallel, resumable,
// shardable), and each is classified: passed, failure (a bug or a counterexample),
// inconclusive (within the lfs estimate's error of the bound) or hypothesis violation (the
// sampler missed the bound). A failure is shrunk (a circle instead of the curve, fewer
// harmonics, a coarser sampling: fewer points, while it still fails under a verified
// hypothesis) and written as a self-contained counterexample.
//
// Every case is reproducible from (curves, index, seed): case i of `fourier` is the
// input `fourier:seed=SEED*2^32+i,harmonics=1+i%8|epsilon=E`, of `multi` the input
// `fourier:seed=SEED*2^32+3i,harmonics=1+i%8,components=2+i%2|epsilon=E`.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/algorithm.h"
#include "bench/runner/run.h"

namespace curvebench::bench {

struct Certify_options {
  std::string curves = "fourier";  // fourier (random smooth closed curves), multi (2 or 3 of them), svg (the bundled drawings), glyphs
  std::size_t count = 100;
  std::optional<double> epsilon;   // sample at this epsilon, else at below_bound x the bound
  double below_bound = 0.95;
  std::uint64_t seed = 0;
  Run_options run;                 // output directory, workers, shard, resume, time limit
};

struct Counterexample {
  std::string input;  // the shrunk input's name: it makes the sampling again
  std::size_t points = 0;
  double epsilon = 0;  // measured
  std::filesystem::path directory;  // points.xy, truth.edges, the run's picture, replay.sh
};

struct Certify_summary {
  std::string algorithm;
  double bound = 0, requested_epsilon = 0;
  std::size_t cases = 0, passed = 0, failures = 0, inconclusive = 0, hypothesis_violations = 0;
  std::vector<Counterexample> counterexamples = {};  // the first five failures, shrunk
};

// The cases of a certification: input names of the benchmark runner (bench_input.h).
std::vector<Suite_case> certification_cases(const Certify_options& options, double epsilon);

// Throws std::invalid_argument if `algorithm` has no epsilon bound or the options are bad.
// Writes options.run.output anew unless options.run.resume.
Certify_summary certify_algorithm(const algorithms::Algorithm& algorithm, const Certify_options& options);

}  // namespace curvebench::bench
