#include "certify/theorems.h"

#include "algorithms/registry.h"

namespace curvebench::certify {

std::optional<Theorem> theorem_of(const algorithms::Algorithm& algorithm) {
  if (!algorithm.condition.epsilon_below) return std::nullopt;
  return Theorem{&algorithm, *algorithm.condition.epsilon_below};
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

Verdict classify(const Theorem& theorem, double measured_epsilon, bool exact) {
  if (!(measured_epsilon < theorem.epsilon_below)) return Verdict::hypothesis_violation;
  if (!(measured_epsilon * (1 + epsilon_relative_error) < theorem.epsilon_below)) return Verdict::inconclusive;
  return exact ? Verdict::passed : Verdict::failure;
}

}  // namespace curvebench::certify
