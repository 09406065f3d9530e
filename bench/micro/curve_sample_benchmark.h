// The growing-n runs that reconstruction_benchmark.cpp gives every built-in algorithm and
// registered_algorithms_benchmark.cpp a program's own: points at equal arc-length steps
// on one random smooth closed Fourier curve, n = 10^3 ... 10^6, each size run only while
// the sizes before it predict under a minute (size_budget.h), with Complexity() fitted.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "algorithms/registry.h"
#include "bench/micro/size_budget.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::bench {

// n points at equal arc-length steps on random_fourier_curve(7), made once per n.
inline const std::vector<geometry::Point>& curve_sample(std::size_t n) {
  static std::map<std::size_t, std::vector<geometry::Point>> cache;
  auto& points = cache[n];
  if (points.empty()) {
    const geometry::Local_feature_size lfs(geometry::random_fourier_curve(7));
    points = geometry::uniform_sampling(lfs, n).points;
  }
  return points;
}

// Times `reconstruct(points)` on curve_sample(state.range(0)) within the size budget.
template <class Run>
void run_on_curve_sample(benchmark::State& state, const std::string& name, Run reconstruct) {
  static Size_budget budget(std::chrono::seconds(60));
  if (!budget.admits(state, name)) return;
  const auto& points = curve_sample(static_cast<std::size_t>(state.range(0)));
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) benchmark::DoNotOptimize(reconstruct(points));
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  budget.record(name, state.range(0), elapsed.count() / static_cast<double>(state.iterations()));
  state.SetComplexityN(state.range(0));
}

// The sizes 10^3 ... 10^6 in milliseconds, with an O(n log n) fit.
inline void growing_n(benchmark::internal::Benchmark* b) {
  b->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Complexity(benchmark::oNLogN)->Unit(benchmark::kMillisecond);
}

// Registers `algorithm` (which must outlive the run) over growing_n. It calls
// algorithm.reconstruct, not algorithms::reconstruct: the points are distinct already, so
// the duplicate merge would only add its own cost to every row.
inline void register_growing_n(const algorithms::Algorithm& algorithm) {
  growing_n(benchmark::RegisterBenchmark(std::string(algorithm.name).c_str(), [&algorithm](benchmark::State& state) {
    run_on_curve_sample(state, std::string(algorithm.name), [&](const std::vector<geometry::Point>& points) {
      return algorithm.reconstruct(points, {}).edges.size();
    });
  }));
}

}  // namespace curvebench::bench
