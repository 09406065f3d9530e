// Runtime scaling of every proximity-graph builder on uniform random points, next to the
// bare CGAL Delaunay triangulation of the same points as the yardstick.
//
//   proximity_graphs_benchmark --benchmark_filter='/1048576$'   # the n = 2^20 row of each
#include <random>
#include <map>

#include <CGAL/Delaunay_triangulation_2.h>
#include <benchmark/benchmark.h>

#include "graphs/beta_skeleton.h"
#include "graphs/proximity_graph.h"
#include "bench/runner/huge_page_malloc.h"

namespace {

using namespace curvebench::graphs;

const std::vector<Point>& uniform_points(std::size_t n) {
  static std::map<std::size_t, std::vector<Point>> cache;
  auto& points = cache[n];
  if (points.empty()) {
    std::mt19937_64 random(n);
    std::uniform_real_distribution<double> coordinate(0, 1);
    points.reserve(n);
    for (std::size_t i = 0; i < n; ++i) points.emplace_back(coordinate(random), coordinate(random));
  }
  return points;
}

template <class Build>
void run(benchmark::State& state, Build build) {
  const auto& points = uniform_points(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(build(points));
  state.SetComplexityN(state.range(0));
}

void cgal_delaunay(benchmark::State& state) {
  run(state, [](const std::vector<Point>& points) {
    CGAL::Delaunay_triangulation_2<curvebench::geometry::Kernel> dt(points.begin(), points.end());
    return dt.number_of_faces();
  });
}

void flattened_delaunay(benchmark::State& state) {
  run(state, [](const std::vector<Point>& points) { return Delaunay_triangulation(points).edges().size(); });
}

void register_all() {
  const auto sizes = [](benchmark::internal::Benchmark* b, int first, int last, benchmark::BigO order) {
    b->RangeMultiplier(4)->Range(first, last)->Complexity(order)->Unit(benchmark::kMillisecond);
  };
  sizes(benchmark::RegisterBenchmark("cgal_delaunay_triangulation", cgal_delaunay), 1 << 10, 1 << 20, benchmark::oNLogN);
  sizes(benchmark::RegisterBenchmark("delaunay_triangulation", flattened_delaunay), 1 << 10, 1 << 20, benchmark::oNLogN);
  for (const Proximity_graph& graph : proximity_graphs()) {
    sizes(benchmark::RegisterBenchmark(std::string(graph.name).c_str(),
                                       [&graph](benchmark::State& state) {
                                         run(state, [&](const std::vector<Point>& points) {
                                           return boost::num_edges(graph.build(Delaunay_triangulation(points), {}));
                                         });
                                       }),
          1 << 10, 1 << 20, benchmark::oNLogN);
  }
  // Below 1 the skeleton is not a Delaunay subgraph: every pair against every point.
  sizes(benchmark::RegisterBenchmark("beta-lune(0.9)",
                                     [](benchmark::State& state) {
                                       run(state, [](const std::vector<Point>& points) {
                                         return boost::num_edges(beta_skeleton(points, 0.9, Beta_region::lune));
                                       });
                                     }),
        1 << 5, 1 << 9, benchmark::oNCubed);
}

}  // namespace

int main(int argc, char** argv) {
  curvebench::bench::restart_with_huge_page_malloc(argv);
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
