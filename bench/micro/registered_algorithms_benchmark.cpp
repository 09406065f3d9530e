// The Google Benchmark main of a program built with curvebench_add_program: each algorithm
// the program registered itself (algorithms/registry.h) over growing n, beside NN-Crust
// and HNN-Crust as yardsticks, exactly as reconstruction_benchmark runs the built-ins
// (curve_sample_benchmark.h). Installed as the library curvebench::benchmark_main.
//
//   my-curvebench-benchmark --benchmark_filter='/10000$'   # the n = 10^4 row of each
#include <cstdio>

#include <benchmark/benchmark.h>

#include "algorithms/registry.h"
#include "bench/micro/curve_sample_benchmark.h"
#include "bench/runner/huge_page_malloc.h"

int main(int argc, char** argv) {
  curvebench::bench::restart_with_huge_page_malloc(argv);
  using namespace curvebench;
  if (algorithms::registered_algorithms().empty())
    std::fputs("curvebench benchmark: the program registers no algorithm; only the yardsticks run\n", stderr);
  for (const char* yardstick : {"nn-crust", "hnn-crust"}) bench::register_growing_n(*algorithms::find_algorithm(yardstick));
  for (const algorithms::Algorithm& algorithm : algorithms::registered_algorithms()) bench::register_growing_n(algorithm);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
