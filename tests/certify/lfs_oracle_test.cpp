// lfs within the error local_feature_size.h states, checked by an oracle that shares
// nothing with geometry/lfs (tests/support/shrinking_ball_lfs.h: maximal empty balls of a
// dense sample, no Voronoi diagram), where it decides something: at the point where each
// sampling's epsilon is attained and at every sample, on every bundled SVG drawing (the
// survey's own files) and on analytic curves. An lfs that reads high makes a measured
// epsilon read low, and every certificate's margin rests on it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "certify/sampling_measure.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/sampling/sampling.h"
#include "tests/support/shrinking_ball_lfs.h"

namespace curvebench::certify {
namespace {

using geometry::Local_feature_size;

// How far ours reads above the oracle, at the points where epsilon 0.2, 0.33 and 0.5 safe
// samplings attain it and at 50 samples of each spread along the curve (every sample of
// small ones), where lfs is above the samplers' floor (below it lfs is not used): the
// largest ours / oracle - 1, the largest ours - oracle in units of the diagonal, and the
// largest excess over the stated bound, truth (1 + relative) + resolution x diagonal, as a
// share of that bound's slack (at most 1 means within it).
struct Excess {
  double relative = -1, absolute = -1, over_bound = -1;
};

double share_of_bound(double ours, double truth, double diagonal) {
  return (ours - truth) /
         (truth * Local_feature_size::stated_relative_error + Local_feature_size::default_resolution * diagonal);
}

Excess worst_excess(const std::string& spec) {
  const geometry::Curve curve = geometry::make_curve(spec);
  const Local_feature_size lfs(curve);
  const double diagonal = lfs.bounding_box_diagonal(), floor = geometry::default_minimum_lfs(lfs);
  testing::Shrinking_ball_lfs oracle(curve, 2e-5 * diagonal, 10 * diagonal);
  Excess worst;
  const auto check = [&](const geometry::Curve_location& where) {
    const double ours = lfs.at(where.component, where.parameter);
    if (!(ours > floor)) return;
    const double truth = oracle.at(curve.components[where.component].point(where.parameter));
    worst.relative = std::max(worst.relative, ours / truth - 1);
    worst.absolute = std::max(worst.absolute, (ours - truth) / diagonal);
    worst.over_bound = std::max(worst.over_bound, share_of_bound(ours, truth, diagonal));
  };
  for (const double epsilon : {0.2, 0.33, 0.5}) {
    const geometry::Sample sample = geometry::safe_epsilon_sampling(lfs, epsilon, floor);
    check(measure_epsilon(lfs, sample.points, sample.minimum_lfs).where);
    const std::size_t stride = std::max<std::size_t>(1, sample.size() / 50);
    for (std::size_t i = 0; i < sample.size(); i += stride) check(sample.locations[i]);
  }
  return worst;
}

std::vector<std::string> specs() {
  std::vector<std::string> all;
  for (const auto& entry : std::filesystem::directory_iterator(CURVEBENCH_SOURCE_DIR "/data/svg"))
    if (entry.path().extension() == ".svg") all.push_back("svg:" + entry.path().string());
  std::sort(all.begin(), all.end());
  for (const char* analytic : {"ellipse:a=4,b=1", "fourier:seed=1", "fourier:seed=2,harmonics=8,amplitude=0.5,decay=1.5",
                               "fourier:seed=3,gap=0.1", "spiral:seed=1", "nested:seed=1",
                               "star:seed=1,angle=60,rounding=0.05", "corner:angle=30"})
    all.push_back(analytic);
  return all;
}

class LfsAgainstShrinkingBalls : public ::testing::TestWithParam<std::string> {};

TEST_P(LfsAgainstShrinkingBalls, NeverAboveTheOracleByMoreThanTheStatedError) {
  const Excess excess = worst_excess(GetParam());
  std::printf("%s: ours / oracle - 1 at most %.3g, ours - oracle at most %.3g of the diagonal, %.2f of the bound\n",
              GetParam().c_str(), excess.relative, excess.absolute, excess.over_bound);
  EXPECT_LE(excess.over_bound, 1) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(BundledAndAnalyticCurves, LfsAgainstShrinkingBalls, ::testing::ValuesIn(specs()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = std::filesystem::path(info.param.substr(info.param.find(':') + 1)).stem();
                           if (!info.param.starts_with("svg:")) name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// The check can fail: on f5.svg, before the ends of the medial axis' branches were given
// exactly, ours read 16 % high beside a Bézier join where the curvature jumps 50-fold;
// an lfs made 1 % high everywhere is caught.
TEST(ShrinkingBallLfs, CatchesAnLfsOnePercentHigh) {
  const geometry::Curve curve = geometry::make_curve("ellipse:a=4,b=1");
  const Local_feature_size lfs(curve);
  testing::Shrinking_ball_lfs oracle(curve, 2e-5 * lfs.bounding_box_diagonal(), 10 * lfs.bounding_box_diagonal());
  double worst = 0;
  for (int i = 0; i < 50; ++i) {
    const double s = i / 50.0;
    worst = std::max(worst, share_of_bound(1.01 * lfs.at(0, s), oracle.at(curve.components[0].point(s)),
                                           lfs.bounding_box_diagonal()));
  }
  EXPECT_GT(worst, 1);
}

}  // namespace
}  // namespace curvebench::certify
