#include "certify/theorems.h"

#include "algorithms/registry.h"

namespace curvebench::certify {

std::string_view measure_name(Measure measure) { return measure == Measure::rho ? "rho" : "epsilon"; }

std::optional<Theorem> theorem_of(const algorithms::Algorithm& algorithm, Measure measure) {
  const std::optional<double>& bound =
      measure == Measure::rho ? algorithm.condition.rho_below : algorithm.condition.epsilon_below;
  if (!bound) return std::nullopt;
  return Theorem{&algorithm, measure, *bound, algorithm.condition.uniformity_below,
                 algorithm.condition.covers_open_curves};
}

std::vector<Theorem> theorems() {
  std::vector<Theorem> all;
  for (const algorithms::Algorithm& algorithm : algorithms::registry())
    if (auto theorem = theorem_of(algorithm)) all.push_back(*theorem);
  return all;
}

std::string_view verdict_name(Verdict verdict) {
  switch (verdict) {
    case Verdict::passed: return "passed";
    case Verdict::failure: return "failure";
    case Verdict::inconclusive: return "inconclusive";
    default: return "hypothesis_violation";
  }
}

Verdict classify(const Theorem& theorem, double measured, bool exact, double measured_uniformity) {
  if (!(measured < theorem.bound)) return Verdict::hypothesis_violation;
  // u is a ratio of two lengths in doubles: no margin is kept, a case that close to the
  // bound is a coin toss of rounding either way.
  if (theorem.uniformity_below && !(measured_uniformity < *theorem.uniformity_below))
    return Verdict::hypothesis_violation;
  if (!(measured * (1 + epsilon_relative_error) < theorem.bound)) return Verdict::inconclusive;
  return exact ? Verdict::passed : Verdict::failure;
}

}  // namespace curvebench::certify
