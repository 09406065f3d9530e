// Runtime scaling of every registered reconstruction algorithm on points sampled along a
// smooth closed curve (n = 10^3 ... 10^6 at equal arc-length steps on a random Fourier
// curve), next to the bare CGAL Delaunay triangulation of the same points: the issue's
// targets are ratios to that row. A size is skipped when the one before it, scaled
// linearly, predicts over a minute (size_budget.h).
//
//   reconstruction_benchmark --benchmark_filter='/1000000$'   # the n = 10^6 row of each
#include <chrono>
#include <map>

#include <CGAL/Delaunay_triangulation_2.h>
#include <benchmark/benchmark.h>

#include "algorithms/registry.h"
#include "bench/micro/size_budget.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/sampling/sampling.h"

namespace {

using namespace curvebench;
using geometry::Point;

const std::vector<Point>& curve_sample(std::size_t n) {
  static std::map<std::size_t, std::vector<Point>> cache;
  auto& points = cache[n];
  if (points.empty()) {
    const geometry::Local_feature_size lfs(geometry::random_fourier_curve(7));
    points = geometry::uniform_sampling(lfs, n).points;
  }
  return points;
}

template <class Run>
void run(benchmark::State& state, const std::string& name, Run reconstruct) {
  static bench::Size_budget budget(std::chrono::seconds(60));
  if (!budget.admits(state, name)) return;
  const auto& points = curve_sample(static_cast<std::size_t>(state.range(0)));
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) benchmark::DoNotOptimize(reconstruct(points));
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  budget.record(name, state.range(0), elapsed.count() / static_cast<double>(state.iterations()));
  state.SetComplexityN(state.range(0));
}

void cgal_delaunay(benchmark::State& state) {
  run(state, "cgal_delaunay_triangulation", [](const std::vector<Point>& points) {
    CGAL::Delaunay_triangulation_2<geometry::Kernel> dt(points.begin(), points.end());
    return dt.number_of_faces();
  });
}

void register_all() {
  const auto sizes = [](benchmark::internal::Benchmark* b) {
    b->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Complexity(benchmark::oNLogN)->Unit(benchmark::kMillisecond);
  };
  sizes(benchmark::RegisterBenchmark("cgal_delaunay_triangulation", cgal_delaunay));
  // algorithm.reconstruct, not algorithms::reconstruct: the points are distinct already,
  // so the duplicate merge would only add its own cost to every row.
  for (const algorithms::Algorithm& algorithm : algorithms::registry())
    sizes(benchmark::RegisterBenchmark(std::string(algorithm.name).c_str(), [&algorithm](benchmark::State& state) {
      run(state, std::string(algorithm.name),
          [&](const std::vector<Point>& points) { return algorithm.reconstruct(points, {}).edges.size(); });
    }));
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
