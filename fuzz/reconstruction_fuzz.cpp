// libFuzzer target for algorithms/: every registered reconstruction algorithm on a small,
// deliberately degenerate point set with duplicates (cocircular and collinear runs,
// 1-ulp moves, extreme scales; degenerate_point_program.h), through the registry's
// reconstruct() as the command line calls it. Laws: no exception for valid parameters,
// edges canonical and between input points, none at a merged duplicate, and the same
// output on a second run.
//
// Input: one byte choosing the algorithm (index modulo the registry's size), one byte
// per parameter (0: its default; else a value spread over its range), then a point program.
#include "algorithms/registry.h"
#include "fuzz/reconstruction_laws.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  curvebench::fuzz::Fuzz_input input(data, size);
  curvebench::fuzz::check_reconstruction_input(curvebench::algorithms::registry(), input);
  return 0;
}
