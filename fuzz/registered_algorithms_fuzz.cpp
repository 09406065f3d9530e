// The libFuzzer target of a program built with curvebench_add_program: the algorithms it
// registered itself (algorithms/registry.h), on the same degenerate inputs and under the
// same laws as the built-ins' target, reconstruction_fuzz.cpp (reconstruction_laws.h).
// Installed as the library curvebench::fuzz_main, which supplies LLVMFuzzerTestOneInput;
// the user's sources are compiled by clang with -fsanitize=fuzzer,address,undefined.
#include <cstdio>
#include <cstdlib>

#include "algorithms/registry.h"
#include "fuzz/reconstruction_laws.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto registered = curvebench::algorithms::registered_algorithms();
  if (registered.empty()) {
    std::fputs("curvebench fuzz target: the program registers no algorithm (curvebench::algorithms::Registration)\n",
               stderr);
    std::abort();
  }
  curvebench::fuzz::Fuzz_input input(data, size);
  curvebench::fuzz::check_reconstruction_input(registered, input);
  return 0;
}
