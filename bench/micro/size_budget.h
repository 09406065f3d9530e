// Growing-n benchmarks of every registered algorithm run a size only if the size before
// it, scaled linearly to this n, stays within a budget: an algorithm slower than the
// survey's O(n log n) still gets its Complexity() fit from the sizes it can do, instead
// of running for hours at n = 10^6. Sizes must be registered in increasing order.
#pragma once

#include <chrono>
#include <map>
#include <string>

#include <benchmark/benchmark.h>

namespace curvebench::bench {

class Size_budget {
 public:
  explicit Size_budget(std::chrono::duration<double> per_iteration) : budget_(per_iteration.count()) {}

  // False, with the row marked skipped, if the last size of `name` predicts over budget.
  bool admits(benchmark::State& state, const std::string& name) {
    const auto last = last_.find(name);
    if (last == last_.end()) return true;
    const double predicted =
        last->second.seconds * static_cast<double>(state.range(0)) / static_cast<double>(last->second.n);
    if (predicted <= budget_) return true;
    state.SkipWithError(("skipped: n = " + std::to_string(last->second.n) + " took " +
                         std::to_string(static_cast<int>(last->second.seconds)) + " s, so this size would take over " +
                         std::to_string(static_cast<int>(budget_)) + " s")
                            .c_str());
    return false;
  }

  // Records one size's mean time per iteration.
  void record(const std::string& name, long n, double seconds_per_iteration) {
    last_[name] = {n, seconds_per_iteration};
  }

 private:
  struct Size {
    long n;
    double seconds;
  };
  double budget_;
  std::map<std::string, Size> last_;
};

}  // namespace curvebench::bench
