// Growing-n benchmarks of every registered algorithm run each size once the smaller size
// took under a budget: an algorithm slower than the survey's O(n log n) (or than its own
// Table 1 entry) still gets its Complexity() fit from the sizes it can do, instead of
// running for hours at n = 10^6. Sizes must be registered in increasing order.
#pragma once

#include <chrono>
#include <map>
#include <string>

#include <benchmark/benchmark.h>

namespace curvebench::bench {

class Size_budget {
 public:
  explicit Size_budget(std::chrono::duration<double> per_iteration) : budget_(per_iteration.count()) {}

  // False, with the row marked skipped, if a smaller size of `name` was over budget.
  bool admits(benchmark::State& state, const std::string& name) {
    const auto over = over_budget_.find(name);
    if (over == over_budget_.end()) return true;
    state.SkipWithError(("skipped: n = " + std::to_string(over->second) + " already took over " +
                         std::to_string(static_cast<int>(budget_)) + " s")
                            .c_str());
    return false;
  }

  // Records one size's mean time per iteration.
  void record(const std::string& name, long n, double seconds_per_iteration) {
    if (seconds_per_iteration > budget_) over_budget_.try_emplace(name, n);
  }

 private:
  double budget_;
  std::map<std::string, long> over_budget_;
};

}  // namespace curvebench::bench
