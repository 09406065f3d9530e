// Growing-n benchmarks of every registered algorithm run a size only if the sizes before
// it, extrapolated to this n, stay within a budget: an algorithm slower than the survey's
// O(n log n) still gets its Complexity() fit from the sizes it can do, instead of running
// for hours at n = 10^6. The extrapolation grows as n^k, k the exponent the last two sizes
// showed (at least 1), so that a quadratic row is not admitted at 10^5 on a linear guess
// (FitConnect's fixed-delta noisy row took 4.6 s at 10^4, then 446 s). Sizes must be
// registered in increasing order.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

namespace curvebench::bench {

class Size_budget {
 public:
  explicit Size_budget(std::chrono::duration<double> per_iteration) : budget_(per_iteration.count()) {}

  // False, with the row marked skipped, if the last sizes of `name` predict over budget.
  bool admits(benchmark::State& state, const std::string& name) {
    const auto sizes = last_.find(name);
    if (sizes == last_.end()) return true;
    const auto& [before, last] = sizes->second;
    double exponent = 1;
    if (before.n > 0 && before.seconds > 0 && last.n > before.n)
      exponent = std::max(1.0, std::log(last.seconds / before.seconds) / std::log(double(last.n) / double(before.n)));
    const double predicted = last.seconds * std::pow(static_cast<double>(state.range(0)) / static_cast<double>(last.n), exponent);
    if (predicted <= budget_) return true;
    state.SkipWithError(("skipped: n = " + std::to_string(last.n) + " took " + std::to_string(static_cast<int>(last.seconds)) +
                         " s, so this size would take over " + std::to_string(static_cast<int>(budget_)) + " s")
                            .c_str());
    return false;
  }

  // Records one size's mean time per iteration.
  void record(const std::string& name, long n, double seconds_per_iteration) {
    auto& [before, last] = last_[name];
    before = last;
    last = {n, seconds_per_iteration};
  }

 private:
  struct Size {
    long n = 0;
    double seconds = 0;
  };
  double budget_;
  std::map<std::string, std::pair<Size, Size>> last_;  // the last two sizes run, newest second
};

}  // namespace curvebench::bench
