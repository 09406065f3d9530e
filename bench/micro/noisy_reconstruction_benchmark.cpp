// Runtime scaling of every registered algorithm that Table 1 says handles noise, on noisy
// samples of a smooth closed curve (n = 10^3 ... 10^5 at equal arc-length steps on a random
// Fourier curve, moved along the normal by lfs noise; survey, "Robustness to Noise"), and on
// the authors' 1000-point fish (data/stretchdenoise/fish.txt). Two noise scalings:
//   noisy_fourier   delta = 0.1 at every n: the band keeps its width while n grows, so it
//                   holds ever more points across, and FitConnect's neighbourhoods (which
//                   grow until they span the band) grow with n: about n^2 here.
//   noisy_band      delta = 0.1 * 1000 / n: the band narrows with the sample spacing, so
//                   every n has the 10^3 sample's points across the band, and this row
//                   measures the cost per point of a band of fixed density.
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
#include "bench/runner/huge_page_malloc.h"

namespace {

using namespace curvebench;
using geometry::Point;

const std::vector<Point>& noisy_curve_sample(std::size_t n, double delta) {
  static std::map<std::pair<std::size_t, double>, std::vector<Point>> cache;
  auto& points = cache[{n, delta}];
  if (points.empty()) {
    const geometry::Local_feature_size lfs(geometry::random_fourier_curve(7));
    points = geometry::with_lfs_noise(lfs, geometry::uniform_sampling(lfs, n), delta, 7).points;
  }
  return points;
}

double fixed_delta(std::size_t) { return 0.1; }
double band_of_fixed_density(std::size_t n) { return 0.1 * 1000.0 / static_cast<double>(n); }

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
    for (const auto& [row, delta_at] : {std::pair{"/noisy_fourier", &fixed_delta}, std::pair{"/noisy_band", &band_of_fixed_density}}) {
      const std::string key = name + row;
      benchmark::RegisterBenchmark(key.c_str(),
                                   [&algorithm, key, delta_at](benchmark::State& state) {
                                     if (!budget.admits(state, key)) return;
                                     const auto n = static_cast<std::size_t>(state.range(0));
                                     const auto& points = noisy_curve_sample(n, delta_at(n));
                                     const auto start = std::chrono::steady_clock::now();
                                     run(state, algorithm, points);
                                     const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
                                     budget.record(key, state.range(0), elapsed.count() / state.iterations());
                                     state.SetComplexityN(state.range(0));
                                   })
          ->Arg(1000)->Arg(10000)->Arg(100000)->Complexity(benchmark::oNLogN)->Unit(benchmark::kMillisecond);
    }
    // Named /1000 so that the smoke test's --benchmark_filter=/1000$ runs it too.
    benchmark::RegisterBenchmark((name + "/fish").c_str(),
                                 [&algorithm](benchmark::State& state) { run(state, algorithm, fish()); })
        ->Arg(1000)->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  curvebench::bench::restart_with_huge_page_malloc(argv);
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
