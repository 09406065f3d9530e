// The sampling-condition theorems (survey, "Guarantees as Sampling Conditions"): for each
// registered algorithm with a proven condition, "every epsilon-sampling (rho-sampling) of
// a smooth closed curve below the bound is reconstructed exactly" (of closed and open
// curves, for Conservative Crust), and the verdict of one experiment on it.
#pragma once

#include <optional>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::certify {

// What a theorem bounds: epsilon (Amenta and Bern's sampling) or rho (HNN-Crust's).
enum class Measure { epsilon, rho };
// "epsilon" or "rho".
std::string_view measure_name(Measure measure);

// One algorithm's sampling condition as a hypothesis to check.
struct Theorem {
  const algorithms::Algorithm* algorithm = nullptr;  // not owned: it must outlive the theorem
  Measure measure = Measure::epsilon;                // what `bound` limits
  double bound = 0;  // the hypothesis: the measured epsilon (or rho) < bound
  std::optional<double> uniformity_below = {};  // and, if set, local uniformity u < this
  bool covers_open_curves = false;  // stated for curves with ends too, not only closed ones
};

// The registry's algorithms with an epsilon bound, in registry order.
std::vector<Theorem> theorems();
// The theorem of one algorithm on `measure` (any Algorithm, also one that is not
// registered); std::nullopt if its condition has no such bound.
std::optional<Theorem> theorem_of(const algorithms::Algorithm& algorithm, Measure measure = Measure::epsilon);

// lfs is estimated from a dense sample of the medial axis (geometry/lfs/local_feature_size.h)
// and over-estimates the true lfs by a relative 2e-4 at most on the curves measured
// there; a measured epsilon (or rho, a distance over the least lfs) is therefore trusted
// to this relative margin, with room.
inline constexpr double epsilon_relative_error = 1e-3;

// The outcome of one case under a theorem (classify).
enum class Verdict {
  passed,                // hypothesis verified, reconstructed exactly
  failure,               // hypothesis verified, not reconstructed exactly: a bug or a counterexample
  inconclusive,          // the measured epsilon is within its error of the bound
  hypothesis_violation,  // the measured epsilon is not below the bound: the sampler missed
};

// "passed", "failure", "inconclusive" or "hypothesis_violation".
std::string_view verdict_name(Verdict verdict);

// The verdict on one case: its measured epsilon (infinite near an unsampled sharp point),
// whether the algorithm reconstructed it exactly, and its local uniformity over the
// ground truth (certify/sampling_measure.h; only read if the theorem bounds it).
Verdict classify(const Theorem& theorem, double measured, bool exact, double measured_uniformity = 1);

}  // namespace curvebench::certify
