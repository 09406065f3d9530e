#include "bench/runner/certification.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "bench/runner/bench_input.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/results_table.h"
#include "certify/theorems.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"

namespace curvebench::bench {
namespace {

using certify::Verdict;

constexpr std::string_view suite_name = "certify";
constexpr std::size_t max_counterexamples = 5;  // shrinking costs a few runs each

std::string fourier_source(std::uint64_t seed, int harmonics, int components = 1) {
  return "fourier:seed=" + std::to_string(seed) + ",harmonics=" + std::to_string(harmonics) +
         (components > 1 ? ",components=" + std::to_string(components) : "");
}

Column measured_column(const certify::Theorem& theorem) {
  return theorem.measure == certify::Measure::rho ? Column::rho : Column::epsilon;
}

// The verdict of one finished row.
Verdict verdict_of(const certify::Theorem& theorem, const Result_row& row) {
  const auto measured = [&row](Column column) { return row[column].empty() ? INFINITY : std::stod(row[column]); };
  return certify::classify(theorem, measured(measured_column(theorem)),
                           row[Column::status] == "ok" && row[Column::exact] == "1", measured(Column::uniformity));
}

// The sampler keys of a case at `level` (bench_input.h): epsilon= or rho=, and for a
// theorem that also bounds local uniformity, uniformity= at that bound, so that every case
// meets both hypotheses on purpose (the 1e-3 margins are the samplers').
std::string sampling_keys(const certify::Theorem& theorem, double level) {
  std::string keys(1, '|');
  keys.append(certify::measure_name(theorem.measure)).append("=").append(format_number(level));
  if (theorem.uniformity_below) keys += "|uniformity=" + format_number(*theorem.uniformity_below);
  return keys;
}

// Runs `algorithm` on one input in a scratch directory: its row.
Result_row run_one(const algorithms::Algorithm& algorithm, const std::string& input, const Run_options& base,
                   const std::filesystem::path& directory, Pictures pictures) {
  std::filesystem::remove_all(directory);
  Run_options options = base;
  options.output = directory, options.resume = false, options.shard = 1, options.shards = 1;
  options.pictures = pictures, options.report = false, options.progress = false;
  run_cases({{std::string(suite_name), input, ""}}, {&algorithm}, options);
  return read_results_csv(directory / "results.csv").at(0);
}

// The integer value of `key` in a `kind:key=value,...` source, if it has one.
std::optional<int> value_of(const std::string& source, const std::string& key) {
  const auto at = source.find("," + key + "=");
  if (at == std::string::npos) return std::nullopt;
  return std::stoi(source.substr(at + key.size() + 2));
}

// `source` with `key`'s value replaced, or the key dropped if `value` is empty.
std::string with_value(const std::string& source, const std::string& key, std::optional<int> value) {
  const auto at = source.find("," + key + "=");
  const auto end = std::min(source.find(',', at + 1), source.size());
  return source.substr(0, at) + (value ? "," + key + "=" + std::to_string(*value) : "") + source.substr(end);
}

// Simpler inputs than `input` (sampled at `level` of the theorem's measure), simplest
// first: a circle at the same level, one component fewer, one harmonic fewer, then a
// coarser sampling (fewer points) half-way to the bound.
std::vector<std::string> simpler_inputs(const std::string& input, const certify::Theorem& theorem, double level) {
  const std::string source(input_source(input));
  std::vector<std::string> simpler;
  const auto at = [&](const std::string& s, double l) { return s + sampling_keys(theorem, l); };
  if (!source.starts_with("circle:")) simpler.push_back(at("circle:r=1", level));
  if (source.starts_with("fourier:")) {
    if (const auto components = value_of(source, "components"); components && *components > 1)
      simpler.push_back(at(with_value(source, "components", *components > 2 ? std::optional(*components - 1) : std::nullopt), level));
    if (const auto harmonics = value_of(source, "harmonics"); harmonics && *harmonics > 0)
      simpler.push_back(at(with_value(source, "harmonics", *harmonics - 1), level));
  }
  const double coarser = level + (0.99 * theorem.bound - level) / 2;
  if (coarser - level > 1e-3 * theorem.bound) simpler.push_back(at(source, coarser));
  return simpler;
}

// The level an input was sampled at: the value of its epsilon= or rho= key.
double level_of(const std::string& input, const certify::Theorem& theorem) {
  std::string key(1, '|');
  key.append(certify::measure_name(theorem.measure)).push_back('=');
  return std::stod(input.substr(input.rfind(key) + key.size()));
}

// Greedy shrinking: take the first simpler input that still fails under a verified
// hypothesis, until none does.
Counterexample shrink(const algorithms::Algorithm& algorithm, const certify::Theorem& theorem, std::string input,
                      const Run_options& options, const std::filesystem::path& directory) {
  const std::filesystem::path scratch = directory / "shrinking";
  for (bool smaller = true; smaller;) {
    smaller = false;
    for (const std::string& candidate : simpler_inputs(input, theorem, level_of(input, theorem))) {
      const Result_row row = run_one(algorithm, candidate, options, scratch, Pictures::none);
      if (verdict_of(theorem, row) == Verdict::failure) {
        input = candidate, smaller = true;
        break;
      }
    }
  }
  std::filesystem::remove_all(scratch);

  // The counterexample: its run (row and picture), its files and how to replay it.
  const Result_row row = run_one(algorithm, input, options, directory, Pictures::all);
  const std::vector<std::string> names{input};
  const Bench_input made = make_bench_inputs(names).front();
  geometry::write_points(directory / "points.xy", made.points);
  geometry::write_edges(directory / "truth.edges", *made.truth);
  std::ofstream replay(directory / "replay.sh");
  const std::string_view measure = certify::measure_name(theorem.measure);
  replay << "#!/bin/sh\n# " << algorithm.name << " does not reconstruct " << input << "\n# (" << made.points.size()
         << " points, measured " << measure << " " << row[measured_column(theorem)] << " < " << theorem.bound
         << "). Run from this directory with curvebench on PATH.\n"
         << "curvebench reconstruct " << replay_arguments(algorithm)
         << " -i points.xy -o reconstruction.edges --svg reconstruction.svg\n"
         << "curvebench evaluate -i points.xy -e reconstruction.edges -g truth.edges\n";
  return {input, made.points.size(), std::stod(row[measured_column(theorem)]), directory};
}

}  // namespace

std::vector<Suite_case> certification_cases(const Certify_options& options, const certify::Theorem& theorem, double level) {
  std::vector<std::string> sources;
  const std::uint64_t base = options.seed << 32;
  // The smooth generated families of the benchmark: one closed curve, two side by side,
  // one inside another (a hole), a star with every corner rounded, and open curves (the
  // open-curves suite's: a Fourier curve opened by a small gap, so that its ends nearly
  // meet, or by half of it, and a spiral).
  const auto generated = [&](const std::string& family, std::size_t i) {
    const std::string seed = std::to_string(base + i);
    const int harmonics = 1 + static_cast<int>(i % 8);
    if (family == "fourier") return fourier_source(base + i, harmonics);
    if (family == "multi") return fourier_source(base + 3 * i, harmonics, 2 + static_cast<int>(i % 2));
    if (family == "nested") return "nested:seed=" + seed + ",separation=0.1";
    if (family == "open")
      return i % 3 == 2 ? "spiral:seed=" + seed : fourier_source(base + i, harmonics) + (i % 3 == 0 ? ",gap=0.1" : ",gap=0.5");
    return "star:seed=" + seed + ",angle=" + std::to_string(30 + 30 * (i % 3)) + ",rounding=0.05";
  };
  // A theorem is tested on the families it is stated for: several curves only for an
  // algorithm that reconstructs several (not Connect2D), open curves only where the
  // theorem covers them (Conservative Crust's).
  const bool several = theorem.algorithm->capabilities.multiple != algorithms::Support::no;
  std::vector<std::string> families{"fourier", "rounded"};
  if (several) families.insert(families.begin() + 1, {"multi", "nested"});
  if (theorem.covers_open_curves) families.push_back("open");
  if (!several && (options.curves == "multi" || options.curves == "nested"))
    throw std::invalid_argument(std::string(theorem.algorithm->name) + " reconstructs one curve: its theorem is not about " +
                                options.curves + " curves");
  if (!theorem.covers_open_curves && options.curves == "open")
    throw std::invalid_argument(std::string(theorem.algorithm->name) + "'s theorem is stated for closed curves only");
  if (std::ranges::find(families, options.curves) != families.end()) {
    for (std::size_t i = 0; i < options.count; ++i) sources.push_back(generated(options.curves, i));
  } else if (options.curves == "mixed") {
    for (std::size_t i = 0; i < options.count; ++i)
      sources.push_back(generated(families[i % families.size()], i / families.size()));
  } else if (options.curves == "svg" || options.curves == "glyphs") {
    std::vector<std::string> all;
    if (options.curves == "glyphs") {
      all = geometry::expand_curve_specs("glyph:*");
    } else {
      for (const auto& file : std::filesystem::directory_iterator(resolve_data_path("data/svg")))
        if (file.path().extension() == ".svg") all.push_back("svg:data/svg/" + file.path().filename().string());
      std::ranges::sort(all);
    }
    const std::size_t step = std::max<std::size_t>(1, all.size() / std::max<std::size_t>(options.count, 1));
    for (std::size_t i = 0; i < all.size() && sources.size() < options.count; i += step) sources.push_back(all[i]);
  } else {
    throw std::invalid_argument("--curves must be fourier, multi, nested, rounded, open, mixed, svg or glyphs, not '" +
                                options.curves + "'");
  }
  std::vector<Suite_case> cases;
  for (const std::string& source : sources) cases.push_back({std::string(suite_name), source + sampling_keys(theorem, level), ""});
  return cases;
}

Certify_summary certify_algorithm(const algorithms::Algorithm& algorithm, const Certify_options& options) {
  const auto theorem = certify::theorem_of(algorithm, options.measure);
  const std::string measure(certify::measure_name(options.measure));
  if (!theorem) throw std::invalid_argument(std::string(algorithm.name) + " has no proven " + measure + " bound to certify");
  const double level = options.level.value_or(options.below_bound * theorem->bound);
  if (!(level > 0)) throw std::invalid_argument("the " + measure + " to sample at must be positive");

  Run_options run = options.run;
  run.report = false;
  if (!run.resume) std::filesystem::remove_all(run.output);
  run_cases(certification_cases(options, *theorem, level), {&algorithm}, run);

  Certify_summary summary{.algorithm = std::string(algorithm.name), .measure = options.measure, .bound = theorem->bound,
                          .requested_level = level};
  for (const Result_row& row : read_results_csv(run.output / "results.csv")) {
    ++summary.cases;
    switch (verdict_of(*theorem, row)) {
      case Verdict::passed: ++summary.passed; break;
      case Verdict::inconclusive: ++summary.inconclusive; break;
      case Verdict::hypothesis_violation: ++summary.hypothesis_violations; break;
      case Verdict::failure:
        if (++summary.failures <= max_counterexamples)
          summary.counterexamples.push_back(
              shrink(algorithm, *theorem, row[Column::input], run, run.output / "counterexamples" / row[Column::job]));
        break;
    }
  }
  return summary;
}

std::string certify_summary_json(const Certify_summary& s, const Certify_options& options) {
  const std::string measure(certify::measure_name(s.measure));
  nlohmann::json counterexamples = nlohmann::json::array();
  for (const Counterexample& c : s.counterexamples)
    counterexamples.push_back({{"input", c.input}, {"points", c.points}, {measure, c.measured},
                               {"path", c.directory.string()}, {"replay", (c.directory / "replay.sh").string()}});
  const nlohmann::json summary = {
      {"algorithm", s.algorithm},
      {"bound", s.bound},
      {"measure", measure},
      {"requested_level", s.requested_level},
      {"curves", options.curves},
      {"seed", options.seed},
      {"cases", s.cases},
      {"passed", s.passed},
      {"failures", s.failures},
      {"inconclusive", s.inconclusive},
      {"hypothesis_violations", s.hypothesis_violations},
      {"counterexamples", counterexamples},
      {"results", (options.run.output / "results.csv").string()},
  };
  return summary.dump(2);
}

}  // namespace curvebench::bench
