#include "certify/theorems.h"

#include "algorithms/registry.h"

namespace curvebench::certify {

std::optional<Theorem> theorem_of(const algorithms::Algorithm& algorithm) {
  if (!algorithm.condition.epsilon_below) return std::nullopt;
  return Theorem{&algorithm, *algorithm.condition.epsilon_below, algorithm.condition.uniformity_below};
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

Verdict classify(const Theorem& theorem, double measured_epsilon, bool exact, double measured_uniformity) {
  if (!(measured_epsilon < theorem.epsilon_below)) return Verdict::hypothesis_violation;
  // u is a ratio of two lengths in doubles: no margin is kept, a case that close to the
  // bound is a coin toss of rounding either way.
  if (theorem.uniformity_below && !(measured_uniformity < *theorem.uniformity_below))
    return Verdict::hypothesis_violation;
  if (!(measured_epsilon * (1 + epsilon_relative_error) < theorem.epsilon_below)) return Verdict::inconclusive;
  return exact ? Verdict::passed : Verdict::failure;
}

}  // namespace curvebench::certify
