// What every curvebench fuzz target shares with the replay driver: the libFuzzer entry
// point, and FUZZ_CHECK, the assertion a target states its laws with.
//
// FUZZ_CHECK is not assert(): it stays on in release builds (the replay tests run with
// NDEBUG), and it traps rather than throws, so that libFuzzer records the input as a
// crash whatever the code under test catches, after the broken law (and, optionally, a
// description of the case it broke on) has been printed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace curvebench::fuzz {

[[noreturn]] inline void report_broken_law(const char* file, int line, std::string_view law,
                                           std::string_view context = {}) {
  std::fprintf(stderr, "%s:%d: law broken: %.*s\n%.*s", file, line, int(law.size()), law.data(),
               int(context.size()), context.data());
  __builtin_trap();
}

}  // namespace curvebench::fuzz

// FUZZ_CHECK(condition, law[, context]): `context` (a string) is only evaluated on failure.
#define FUZZ_CHECK(condition, law, ...)                                                          \
  do {                                                                                           \
    if (!(condition))                                                                            \
      ::curvebench::fuzz::report_broken_law(__FILE__, __LINE__, law __VA_OPT__(, ) __VA_ARGS__); \
  } while (false)
