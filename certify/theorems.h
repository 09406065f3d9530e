// The sampling-condition theorems (survey, "Guarantees as Sampling Conditions"): for each
// registered algorithm with a proven condition, "every epsilon-sampling (rho-sampling) of
// a smooth closed curve below the bound is reconstructed exactly", and the verdict of one
// experiment on it.
#pragma once

#include <optional>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::certify {

struct Theorem {
  const algorithms::Algorithm* algorithm = nullptr;
  double epsilon_below = 0;  // the hypothesis: measured epsilon < epsilon_below
  std::optional<double> uniformity_below = {};  // and, if set, local uniformity u < this
};

// The registry's algorithms with an epsilon bound, in registry order.
std::vector<Theorem> theorems();
// The theorem of one algorithm (any Algorithm, also one that is not registered);
// std::nullopt if its condition has no epsilon bound.
std::optional<Theorem> theorem_of(const algorithms::Algorithm& algorithm);

// lfs is estimated from a dense sample of the medial axis (geometry/lfs/local_feature_size.h)
// and over-estimates the true lfs by a relative 2e-4 at most on the curves measured
// there; a measured epsilon is therefore trusted to this relative margin, with room.
inline constexpr double epsilon_relative_error = 1e-3;

enum class Verdict {
  passed,                // hypothesis verified, reconstructed exactly
  failure,               // hypothesis verified, not reconstructed exactly: a bug or a counterexample
  inconclusive,          // the measured epsilon is within its error of the bound
  hypothesis_violation,  // the measured epsilon is not below the bound: the sampler missed
};

std::string_view verdict_name(Verdict verdict);

// The verdict on one case: its measured epsilon (infinite near an unsampled sharp point),
// whether the algorithm reconstructed it exactly, and its local uniformity over the
// ground truth (certify/sampling_measure.h; only read if the theorem bounds it).
Verdict classify(const Theorem& theorem, double measured_epsilon, bool exact, double measured_uniformity = 1);

}  // namespace curvebench::certify
