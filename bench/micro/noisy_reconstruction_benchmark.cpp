// Runtime scaling of every registered algorithm that Table 1 says handles noise, on a
// noisy sample of a smooth closed curve (n = 10^3 ... 10^5 at equal arc-length steps on a
// random Fourier curve, moved along the normal by lfs noise of delta = 0.1; survey,
// "Robustness to Noise"), and on the authors' 1000-point fish (data/stretchdenoise/fish.txt).
// The authors' FitConnect takes 3.0 s on the fish and 4.9 s on a 10^4-point noise-free
// curve; reconstruction_benchmark has the noise-free rows.
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>

#include <benchmark/benchmark.h>

#include "algorithms/registry.h"
#include "bench/micro/size_budget.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/io/point_io.h"
#include "geometry/sampling/sampling.h"
#include "geometry/sampling/sampling_noise.h"

namespace {

using namespace curvebench;
using geometry::Point;

const std::vector<Point>& noisy_curve_sample(std::size_t n) {
  static std::map<std::size_t, std::vector<Point>> cache;
  auto& points = cache[n];
  if (points.empty()) {
    const geometry::Local_feature_size lfs(geometry::random_fourier_curve(7));
    points = geometry::with_lfs_noise(lfs, geometry::uniform_sampling(lfs, n), 0.1, 7).points;
  }
  return points;
}

const std::vector<Point>& fish() {
  static const std::vector<Point> points =
      geometry::read_point_file(std::filesystem::path(CURVEBENCH_SOURCE_DIR) / "data/stretchdenoise/fish.txt").points;
  return points;
}

void run(benchmark::State& state, const algorithms::Algorithm& algorithm, const std::vector<Point>& points) {
  for (auto _ : state) benchmark::DoNotOptimize(algorithm.reconstruct(points, {}).edges.size());
  state.counters["points"] = static_cast<double>(points.size());
}

void register_all() {
  static bench::Size_budget budget(std::chrono::seconds(60));
  fish();  // read now, so that a missing file stops the run before it starts
  for (const algorithms::Algorithm& algorithm : algorithms::registry()) {
    if (algorithm.capabilities.noise == algorithms::Support::no) continue;
    const std::string name(algorithm.name);
    benchmark::RegisterBenchmark((name + "/noisy_fourier").c_str(),
                                 [&algorithm, name](benchmark::State& state) {
                                   if (!budget.admits(state, name)) return;
                                   const auto start = std::chrono::steady_clock::now();
                                   run(state, algorithm, noisy_curve_sample(static_cast<std::size_t>(state.range(0))));
                                   const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
                                   budget.record(name, state.range(0), elapsed.count() / state.iterations());
                                   state.SetComplexityN(state.range(0));
                                 })
        ->Arg(1000)->Arg(10000)->Arg(100000)->Complexity(benchmark::oNLogN)->Unit(benchmark::kMillisecond);
    // Named /1000 so that the smoke test's --benchmark_filter=/1000$ runs it too.
    benchmark::RegisterBenchmark((name + "/fish").c_str(),
                                 [&algorithm](benchmark::State& state) { run(state, algorithm, fish()); })
        ->Arg(1000)->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    register_all();
  } catch (const std::exception& error) {  // the fish file is missing or unreadable
    std::fprintf(stderr, "noisy_reconstruction_benchmark: %s\n", error.what());
    return 1;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
