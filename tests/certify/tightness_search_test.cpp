#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "algorithms/emst.h"
#include "algorithms/registry.h"
#include "certify/sampling_measure.h"
#include "certify/tightness_search.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::certify {
namespace {

using geometry::Local_feature_size;

// The case's measure again, from its curve spec and points alone.
double remeasured(const Tightness_case& c) {
  const Local_feature_size lfs(geometry::make_curve(c.curve));
  return measure_epsilon(lfs, c.sample.points, 0).epsilon;
}

// Its ground truth is the cycle through each component's samples in curve order.
bool truth_is_the_cycle_in_curve_order(const geometry::Sample& sample) {
  for (std::size_t i = 1; i < sample.size(); ++i)
    if (sample.locations[i - 1].component == sample.locations[i].component &&
        !(sample.locations[i - 1].parameter < sample.locations[i].parameter))
      return false;
  return sample.edges.size() == sample.size();  // closed components: as many edges as points
}

// A false claim is caught below its bound: the EMST is a tree, never the n-edge cycle of a
// closed curve, so every sampling fails, and the search must come back with one whose
// measure is below the claimed 0.5, densified further than the sampler's level.
TEST(Tightness, FindsACounterexampleToAFalseClaim) {
  algorithms::Algorithm emst = algorithms::emst_algorithm();
  emst.condition.epsilon_below = 0.5;
  const Tightness_result result = search_tightness(emst, {.seconds = 60, .max_curves = 2, .moves = 10});
  ASSERT_TRUE(result.best);
  const Tightness_case& c = *result.best;
  EXPECT_EQ(result.failing_curves, result.curves);
  EXPECT_LT(c.measured, 0.5);
  EXPECT_GT(c.added, 0u);
  EXPECT_LT(c.measured, c.level);
  EXPECT_TRUE(truth_is_the_cycle_in_curve_order(c.sample));
  EXPECT_EQ(algorithms::emst_reconstruction(c.sample.points).size(), c.sample.size() - 1);
  EXPECT_EQ(c.reconstruction, algorithms::emst_reconstruction(c.sample.points));
  EXPECT_EQ(remeasured(c), c.measured);
}

// NN-Crust's theorem (epsilon < 1/3) held on every case the certifier tried; the search's
// smallest failure must be above it, a failure again when rerun, and measured as reported.
TEST(Tightness, NnCrustFailsOnlyAboveItsBound) {
  const algorithms::Algorithm& nn_crust = *algorithms::find_algorithm("nn-crust");
  const Tightness_result result = search_tightness(nn_crust, {.seconds = 60, .seed = 3, .max_curves = 4, .moves = 10});
  EXPECT_EQ(result.curves, 4u);
  EXPECT_GE(result.largest_passed, 1.0 / 3 * 0.8);  // the ladder's first level passed, measured in (0.8 b, b]
  ASSERT_TRUE(result.best);
  const Tightness_case& c = *result.best;
  EXPECT_GE(c.measured, 1.0 / 3);
  EXPECT_TRUE(truth_is_the_cycle_in_curve_order(c.sample));
  const auto rerun = algorithms::reconstruct(nn_crust, c.sample.points).edges;
  EXPECT_EQ(rerun, c.reconstruction);
  EXPECT_NE(rerun, geometry::canonical_edges(c.sample.edges));
  EXPECT_EQ(remeasured(c), c.measured);
}

TEST(Tightness, RhoSearchForHnnCrust) {
  const algorithms::Algorithm& hnn_crust = *algorithms::find_algorithm("hnn-crust");
  const Tightness_result result =
      search_tightness(hnn_crust, {.measure = Measure::rho, .seconds = 60, .max_curves = 12, .moves = 5});
  EXPECT_EQ(result.theorem.bound, 0.9);
  if (!result.best) return;  // no failure on these curves: nothing below the bound either
  const Tightness_case& c = *result.best;
  EXPECT_GE(c.measured, 0.9);
  EXPECT_GE(c.sample.size(), 3u);
  const Local_feature_size lfs(geometry::make_curve(c.curve));
  EXPECT_EQ(measure_rho(lfs, c.sample, 0).rho, c.measured);
  EXPECT_FALSE(check_reconstruction(hnn_crust, c.sample).exact);
}

TEST(Tightness, RefusesAnAlgorithmWithoutABound) {
  EXPECT_THROW(search_tightness(algorithms::emst_algorithm(), {}), std::invalid_argument);
  EXPECT_THROW(search_tightness(*algorithms::find_algorithm("nn-crust"), {.measure = Measure::rho}), std::invalid_argument);
}

TEST(Tightness, CheckReconstructionAgainstKnownOutcomes) {
  const Local_feature_size lfs(geometry::make_curve("circle:r=1"));
  const geometry::Sample dense = geometry::safe_epsilon_sampling(lfs, 0.2, geometry::default_minimum_lfs(lfs));
  EXPECT_TRUE(check_reconstruction(*algorithms::find_algorithm("nn-crust"), dense).exact);
  EXPECT_FALSE(check_reconstruction(algorithms::emst_algorithm(), dense).exact);
}

// The densify step rests on this law: one more sample never raises the measured epsilon.
RC_GTEST_PROP(Tightness, AnotherSampleNeverRaisesEpsilon, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1000);
  const double level = *rc::gen::element(0.3, 0.6, 1.0, 2.0);
  const Local_feature_size lfs(geometry::make_curve("fourier:seed=" + std::to_string(seed)));
  const double floor = geometry::default_minimum_lfs(lfs);
  const geometry::Sample sample = geometry::safe_epsilon_sampling(lfs, level, floor);
  std::vector<double> parameters;
  for (const auto& location : sample.locations) parameters.push_back(location.parameter);
  parameters.push_back(*rc::gen::inRange(0, 1000) / 1000.0 * static_cast<double>(lfs.curve().components[0].piece_count()));
  std::sort(parameters.begin(), parameters.end());
  const geometry::Sample denser = geometry::sampling_at(lfs, {parameters}, floor);
  RC_ASSERT(denser.size() == sample.size() + 1);
  RC_ASSERT(measure_epsilon(lfs, denser.points, 0).epsilon <= measure_epsilon(lfs, sample.points, 0).epsilon * (1 + 1e-12));
}

}  // namespace
}  // namespace curvebench::certify
