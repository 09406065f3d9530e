// `curvebench run SUITE -o DIR`: every registered algorithm (or the chosen ones) on every
// input of a suite, as jobs in worker processes (process_pool.h), each row appended to
// DIR/results.csv the moment it ends, so that nothing computed is lost when a run is
// interrupted and --resume runs only what is missing. --shard K/N runs a deterministic 1/N
// of the jobs and `curvebench merge` combines shards: the cases, in runs of one source
// (the same curve), are dealt to the shards in turn, so that no input is made twice; a
// run of fewer such runs than shards deals its jobs (job j to shard j mod N + 1).
//
// DIR/ holds run.json (which run: a fingerprint of its jobs, and which shard of it),
// results.csv (sorted by job at the end), results.json, pictures/JOB.svg (a
// reconstruction of at most 5,000 points on its ground truth, wrong edges red, missing
// ones dashed) and the report (report.html, summary.csv and charts/, by
// bench/report/make_report.py).
// Pictures: by default (Pictures::some) the first few failures of each algorithm in each
// suite, in job order, and its first two jobs if they succeed, so that a run of tens of
// thousands of jobs writes a gallery, not gigabytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/algorithm.h"
#include "bench/runner/suite.h"

namespace curvebench::bench {

// some: per algorithm and suite, the first `failure_pictures` jobs that are not exact and
// those of its first `success_pictures` jobs that are.
enum class Pictures { some, all, failures, none };
// Pictures::some: how many jobs that are not exact get a picture, per algorithm and suite.
inline constexpr std::size_t failure_pictures = 6, success_pictures = 2;  // of the first this many, the exact ones

// What `curvebench run` runs, and how.
struct Run_options {
  std::string suite;            // a suite's name (suite.h)
  std::filesystem::path output;  // the run directory, DIR
  std::vector<std::string> algorithms = {};  // registry names; empty: all
  std::size_t jobs = 0;                 // worker processes; 0: one per core
  // The shard this run does, from 1 to `shards`.
  std::size_t shard = 1, shards = 1;    // run shard `shard` of `shards` (1-based)
  bool resume = false;                  // run only the jobs missing from DIR/results.csv
  // Per job; 0: none. A minute: every algorithm but Optimal Transport (quadratic in
  // CGAL, 13 s at n = 10^4) takes seconds at the runtime suite's n = 10^5.
  double timeout_seconds = 60;
  Pictures pictures = Pictures::some;  // which jobs get a picture
  bool report = true;                  // write the report at the end (make_report)
  bool progress = true;                // show progress on stderr
  // Set: each job's algorithm gets its input points in an order drawn from this seed and
  // the job's number, and its edges are mapped back to the input's indices (duplicates to
  // their first occurrence), so that the row is the unshuffled one's if the algorithm does
  // not depend on the order. An algorithm that returns points of its own has no input
  // indices to map back: it runs on the input as made. A check (the determinism test).
  std::optional<std::uint64_t> shuffle_seed = {};
};

// What a run did, counted by job status.
struct Run_summary {
  std::size_t jobs = 0;     // in this shard
  std::size_t resumed = 0;  // found done in results.csv
  // Jobs that ended with status `ok`.
  std::size_t ok = 0, failed = 0, invalid_output = 0, crashed = 0, timed_out = 0;  // of those run now
  // \var failed
  // Jobs whose algorithm, or the making of their input, threw: status `failed`.
  // \var invalid_output
  // Jobs with invalid output: status `invalid-output`.
  // \var crashed
  // Jobs whose program or worker process crashed: status `crashed`.
};

// Throws std::invalid_argument for an unknown suite or algorithm, bad shard numbers, or an
// existing results.csv without --resume (or one from another suite definition).
Run_summary run_suite(const Run_options& options);

// The runner under run_suite, for callers that make their own cases (the certifier) or
// algorithms (a test's deliberately broken one): every algorithm on every case, as jobs
// case * algorithms + algorithm. `options.suite` and `options.algorithms` are not read.
Run_summary run_cases(const std::vector<Suite_case>& cases, const std::vector<const algorithms::Algorithm*>& algorithms,
                      const Run_options& options);

// Combines the results of shard runs into `output` (rows by job, pictures copied) and
// writes results.json and, if asked, the report. `pictures`: what the shards ran with
// (Pictures::some caps the merged pictures as one run would have). Each run directory
// names its run and shard in run.json; throws std::invalid_argument, before writing
// anything, for shards of different runs (another suite, level, algorithm list or shard
// count), a shard given twice, and missing or unfinished shards (named by number), and
// if two shards disagree on a job.
std::size_t merge_runs(std::span<const std::filesystem::path> shards, const std::filesystem::path& output,
                       Pictures pictures, bool report);

// "K/N" as (K, N), for --shard; throws std::invalid_argument naming the text otherwise.
std::pair<std::size_t, std::size_t> parse_shard(const std::string& text);

// Writes DIR/report.html and DIR/charts/ from DIR/results.csv with /usr/bin/python3 and
// matplotlib; false, with the reason on stderr, if that fails.
bool make_report(const std::filesystem::path& dir);

}  // namespace curvebench::bench
