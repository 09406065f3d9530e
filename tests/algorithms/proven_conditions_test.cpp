// The survey's table "Sampling conditions" as properties: every registered algorithm with
// a proven epsilon bound reconstructs exactly (edge set = ground truth) every smooth
// closed curve, one to three components (one for an algorithm that returns a single
// curve, as Connect2D), safe-sampled at a measured epsilon below that bound
// (tests/support/reconstruction_cases.h), and of local uniformity below its bound if the
// condition has one (Connect2D). A failure here is a finding about the
// sampler, the lfs estimate or the algorithm, never a reason to loosen the bound.
#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <string>

#include "algorithms/registry.h"
#include "certify/sampling_measure.h"
#include "tests/support/reconstruction_cases.h"

namespace curvebench::algorithms {
namespace {

std::vector<std::string> algorithms_with_an_epsilon_bound() {
  std::vector<std::string> names;
  for (const Algorithm& algorithm : registry())
    if (algorithm.condition.epsilon_below) names.emplace_back(algorithm.name);
  return names;
}

class Proven_condition : public ::testing::TestWithParam<std::string> {};

TEST_P(Proven_condition, ReconstructsEverySafelySampledSmoothCurveExactly) {
  const Algorithm& algorithm = *find_algorithm(GetParam());
  const double bound = *algorithm.condition.epsilon_below;
  const bool passed = rc::check(algorithm.title.data(), [&] {
    const int components = algorithm.capabilities.multiple == Support::no ? 1 : 3;
    const testing::Sampled_case input = *testing::safely_sampled_smooth_curves(bound, components);
    if (const auto u_bound = algorithm.condition.uniformity_below)
      RC_PRE(certify::measure_uniformity(input.sample.points, input.truth).uniformity < *u_bound);
    RC_TAG(input.curve.components.size());
    const Reconstruction result = reconstruct(algorithm, input.sample.points);
    RC_ASSERT(result.edges == input.truth);
  });
  EXPECT_TRUE(passed);
}

INSTANTIATE_TEST_SUITE_P(Registry, Proven_condition, ::testing::ValuesIn(algorithms_with_an_epsilon_bound()),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Proven_condition);

}  // namespace
}  // namespace curvebench::algorithms
