// Runtime of the lfs estimate (medial axis of an adaptive dense sample) and of the
// samplers against curve complexity: random Fourier curves with N = 1 to 64 harmonics
// (each curve point costs O(N), and the dense sample grows with N: counter "dense"); and
// of the epsilon measure and of lfs queries against the number of samples or queries;
// and of the glyph sweep's work for one glyph (glyph_sampling/0, 1, 2: 'A', 'g', '@'):
// the lfs estimate, then a safe epsilon sampling and its measure for epsilon 0.1, 0.3
// and 0.5. Glyphs have sharp corners, where lfs -> 0 and dense and medial points crowd.
//
//   sampling_benchmark --benchmark_filter='local_feature_size'
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "certify/sampling_measure.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/glyph_curves.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/seeded_random.h"

namespace {

using namespace curvebench::geometry;

Curve fourier_curve(int harmonics) { return random_fourier_curve(1, {harmonics, 0.4, 2}); }

const Local_feature_size& fourier_lfs(int harmonics) {
  static std::map<int, std::unique_ptr<Local_feature_size>> cache;
  auto& lfs = cache[harmonics];
  if (!lfs) lfs = std::make_unique<Local_feature_size>(fourier_curve(harmonics));
  return *lfs;
}

std::size_t dense_size(const Local_feature_size& lfs) { return lfs.dense_parameters(0).size(); }

void local_feature_size(benchmark::State& state) {
  const Curve curve = fourier_curve(static_cast<int>(state.range(0)));
  std::size_t dense = 0;
  for (auto _ : state) dense = dense_size(Local_feature_size(curve));
  state.counters["dense"] = static_cast<double>(dense);
  state.SetComplexityN(state.range(0));
}

template <Sample (*sampler)(const Local_feature_size&, double, double)>
void sampling(benchmark::State& state) {
  const Local_feature_size& lfs = fourier_lfs(static_cast<int>(state.range(0)));
  std::size_t points = 0;
  for (auto _ : state) points = sampler(lfs, 0.3, default_minimum_lfs(lfs)).size();
  state.counters["points"] = static_cast<double>(points);
  state.counters["dense"] = static_cast<double>(dense_size(lfs));
  state.SetComplexityN(state.range(0));
}

void measure_epsilon(benchmark::State& state) {
  const Local_feature_size& lfs = fourier_lfs(8);
  const Sample sample = uniform_sampling(lfs, static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(curvebench::certify::measure_epsilon(lfs, sample.points, 0).epsilon);
  state.SetComplexityN(state.range(0));
}

void lfs_queries(benchmark::State& state) {
  const Local_feature_size& lfs = fourier_lfs(8);
  std::vector<double> parameters;
  Seeded_random random(1);
  for (std::int64_t i = 0; i < state.range(0); ++i) parameters.push_back(random.uniform());
  for (auto _ : state)
    for (const double s : parameters) benchmark::DoNotOptimize(lfs.at(0, s));
  state.SetComplexityN(state.range(0));
}

void glyph_sampling(benchmark::State& state) {
  constexpr char32_t glyphs[] = {U'A', U'g', U'@'};
  const Curve curve = glyph_curve(default_glyph_font, glyphs[state.range(0)]);
  std::size_t points = 0;
  for (auto _ : state) {
    const Local_feature_size lfs(curve);
    points = 0;
    for (const double epsilon : {0.1, 0.3, 0.5}) {
      const Sample sample = safe_epsilon_sampling(lfs, epsilon, default_minimum_lfs(lfs));
      benchmark::DoNotOptimize(curvebench::certify::measure_epsilon(lfs, sample.points, sample.minimum_lfs).epsilon);
      points += sample.size();
    }
  }
  state.counters["points"] = static_cast<double>(points);
}

bool register_all() {
  const auto harmonics = [](benchmark::internal::Benchmark* b) {
    b->RangeMultiplier(2)->Range(1, 64)->Complexity(benchmark::oAuto)->Unit(benchmark::kMillisecond);
  };
  harmonics(benchmark::RegisterBenchmark("local_feature_size", local_feature_size));
  harmonics(benchmark::RegisterBenchmark("epsilon_sampling", sampling<epsilon_sampling>));
  harmonics(benchmark::RegisterBenchmark("safe_epsilon_sampling", sampling<safe_epsilon_sampling>));
  harmonics(benchmark::RegisterBenchmark("rho_sampling", sampling<rho_sampling>));
  benchmark::RegisterBenchmark("measure_epsilon", measure_epsilon)
      ->RangeMultiplier(4)->Range(16, 1024)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("lfs_queries", lfs_queries)
      ->RangeMultiplier(8)->Range(64, 1 << 15)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("glyph_sampling", glyph_sampling)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
  return true;
}

const bool registered = register_all();

}  // namespace

BENCHMARK_MAIN();
