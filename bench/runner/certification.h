// `curvebench certify`: a sampling-condition theorem (certify/theorems.h) as an experiment.
// Generated curves are sampled so that the *measured* epsilon (or rho, for a theorem on
// rho; and local uniformity, for one that bounds it too) lies below the bound, each
// case is reconstructed as a job of the benchmark runner (run.h: parallel, resumable,
// shardable), and each is classified: passed, failure (a bug or a counterexample),
// inconclusive (within the lfs estimate's error of the bound) or hypothesis violation (the
// sampler missed the bound). A failure is shrunk (a circle instead of the curve, fewer
// harmonics, a coarser sampling: fewer points, while it still fails under a verified
// hypothesis) and written as a self-contained counterexample.
//
// Every case is reproducible from (curves, index, seed): case i of `fourier` is the
// input `fourier:seed=SEED*2^32+i,harmonics=1+i%8|epsilon=E`, of `multi` the input
// `fourier:seed=SEED*2^32+3i,harmonics=1+i%8,components=2+i%2|epsilon=E`, of `nested`
// `nested:seed=SEED*2^32+i,separation=0.1|...`, of `rounded`
// `star:seed=SEED*2^32+i,angle=30+30(i%3),rounding=0.05|...`, of `open` (only for a
// theorem that covers curves with ends: Conservative Crust's) the Fourier curve of i
// opened by a gap of 0.1 or 0.5 (i%3 = 0, 1) or `spiral:seed=SEED*2^32+i` (i%3 = 2);
// `mixed` takes case i/K of the K families the theorem is stated for in turn (fourier,
// multi, nested, rounded, and open if it covers them; fourier and rounded for an
// algorithm that reconstructs one curve, Connect2D, whose theorem is about one). A rho
// theorem samples with `rho=R` (safe_rho_sampling), Connect2D's with
// `epsilon=E|uniformity=1.609` (graded_epsilon_sampling).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/algorithm.h"
#include "bench/runner/run.h"
#include "certify/theorems.h"

namespace curvebench::bench {

// What `curvebench certify` runs: which curves, how many cases, at which level, and where.
struct Certify_options {
  // fourier (random smooth closed curves), multi (2 or 3 of them side by side), nested (one
  // inside another), rounded (star polygons with every corner rounded), open (curves with
  // ends), mixed (those the theorem is stated for, in turn), svg (the bundled drawings), glyphs
  std::string curves = "fourier";
  std::size_t count = 100;         // cases (svg, glyphs: at most this many)
  certify::Measure measure = certify::Measure::epsilon;  // which theorem: on epsilon or on rho
  std::optional<double> level;     // sample at this epsilon (rho), else at below_bound x the bound
  double below_bound = 0.95;       // the level as a share of the bound, when `level` is unset
  std::uint64_t seed = 0;          // the generated curves' seeds start at SEED*2^32
  Run_options run;                 // output directory, workers, shard, resume, time limit
};

// A failure, shrunk and written to a directory of its own.
struct Counterexample {
  std::string input;  // the shrunk input's name: it makes the sampling again
  std::size_t points = 0;  // the shrunk input's number of points
  double measured = 0;  // its epsilon (rho)
  std::filesystem::path directory;  // points.xy, truth.edges, the run's picture, replay.sh
};

// What a certification found: its cases counted by certify::Verdict.
struct Certify_summary {
  std::string algorithm;  // the algorithm's name
  certify::Measure measure = certify::Measure::epsilon;  // the theorem's measure
  // The theorem's bound.
  double bound = 0, requested_level = 0;  // the level the cases were sampled at
  // Cases run: the sum of the four counts.
  std::size_t cases = 0, passed = 0, failures = 0, inconclusive = 0, hypothesis_violations = 0;
  // \var passed
  // Cases with the hypothesis verified and reconstructed exactly.
  // \var failures
  // Cases with the hypothesis verified and not reconstructed exactly.
  // \var inconclusive
  // Cases whose measure is within its error of the bound.
  // \var hypothesis_violations
  // Cases whose measure is not below the bound: the sampler missed it.
  std::vector<Counterexample> counterexamples = {};  // the first five failures, shrunk
};

// The cases of a certification: input names of the benchmark runner (bench_input.h),
// sampled at `level` of the theorem's measure (and its uniformity bound, if it has one).
std::vector<Suite_case> certification_cases(const Certify_options& options, const certify::Theorem& theorem, double level);

// Throws std::invalid_argument if `algorithm` has no bound on options.measure or the options are bad.
// Writes options.run.output anew unless options.run.resume.
Certify_summary certify_algorithm(const algorithms::Algorithm& algorithm, const Certify_options& options);

// The summary as `curvebench certify --json` prints it: algorithm, bound, measure,
// requested_level, curves, seed, cases, passed, failures, inconclusive,
// hypothesis_violations, counterexamples (each: input, points, the measure's value, path,
// replay) and results (options.run.output's results.csv).
std::string certify_summary_json(const Certify_summary& summary, const Certify_options& options);

}  // namespace curvebench::bench
