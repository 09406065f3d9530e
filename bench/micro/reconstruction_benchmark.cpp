// Runtime scaling of every registered reconstruction algorithm on points sampled along a
// smooth closed curve (n = 10^3 ... 10^6 at equal arc-length steps on a random Fourier
// curve), next to the bare CGAL Delaunay triangulation of the same points: the issue's
// targets are ratios to that row. A size is skipped when the one before it, scaled
// linearly, predicts over a minute (size_budget.h).
//
//   reconstruction_benchmark --benchmark_filter='/1000000$'   # the n = 10^6 row of each
#include <CGAL/Delaunay_triangulation_2.h>
#include <benchmark/benchmark.h>

#include "algorithms/nn_crust.h"
#include "algorithms/registry.h"
#include "bench/micro/curve_sample_benchmark.h"
#include "bench/runner/huge_page_malloc.h"

namespace {

using namespace curvebench;
using geometry::Point;

void cgal_delaunay(benchmark::State& state) {
  bench::run_on_curve_sample(state, "cgal_delaunay_triangulation", [](const std::vector<Point>& points) {
    CGAL::Delaunay_triangulation_2<geometry::Kernel> dt(points.begin(), points.end());
    return dt.number_of_faces();
  });
}

// NN-Crust's neighbour search in each structure (algorithms/nn_crust.h): the kd-tree the
// algorithm uses, and the triangulation it falls back to.
void neighbor_search(benchmark::State& state, algorithms::Search_structure structure, const char* name) {
  bench::run_on_curve_sample(state, name, [structure](const std::vector<Point>& points) {
    return algorithms::nearest_and_half_neighbors(points, algorithms::Half_plane::behind_p, structure).size();
  });
}

void register_all() {
  bench::growing_n(benchmark::RegisterBenchmark("cgal_delaunay_triangulation", cgal_delaunay));
  for (const auto& [structure, name] :
       {std::pair{algorithms::Search_structure::kd_tree, "nearest_and_half_neighbors_kd_tree"},
        std::pair{algorithms::Search_structure::delaunay_triangulation, "nearest_and_half_neighbors_delaunay"}})
    bench::growing_n(benchmark::RegisterBenchmark(name, neighbor_search, structure, name));
  for (const algorithms::Algorithm& algorithm : algorithms::registry()) bench::register_growing_n(algorithm);
}

}  // namespace

int main(int argc, char** argv) {
  curvebench::bench::restart_with_huge_page_malloc(argv);
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
