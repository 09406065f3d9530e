// Conformance with the survey's own sampling tool ("Sampling Tools": sample2d of
// stefango74/sampling2d, which made the survey's samplings) on its four single closed
// curves, data/svg/{simple,blob2,complex,spiral}.svg, at epsilon 0.2, 0.33 and 0.5:
// - its samplings (data/sample2d/, its output unchanged) measure within 5 % of their
//   epsilon by our measure: the two agree on what epsilon and lfs are;
// - our safe sampler needs at most 10 % more points than it did, and measures at most
//   its target: we sample the survey's curves as the survey did.
// Both failed before rounding kinks stopped being corners (svg_path.h): blob2's 0.33
// sampling measured 2.93, and we needed 1.7 to 1.9 times its points.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "certify/sampling_measure.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/io/point_io.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::certify {
namespace {

struct Survey_sampling {
  const char* curve;
  double epsilon;
  std::size_t points;  // sample2d's count, from its program (data/README.md says how it was run)
};

constexpr Survey_sampling survey_samplings[] = {
    {"simple", 0.2, 47},   {"simple", 0.33, 29},   {"simple", 0.5, 19},   {"blob2", 0.2, 107},  {"blob2", 0.33, 64},
    {"blob2", 0.5, 42},    {"complex", 0.2, 423},  {"complex", 0.33, 257}, {"complex", 0.5, 168}, {"spiral", 0.2, 853},
    {"spiral", 0.33, 517}, {"spiral", 0.5, 341},
};

std::string epsilon_text(double epsilon) {
  char text[16];
  std::snprintf(text, sizeof text, "%g", epsilon);
  return text;
}

class SurveySampling : public ::testing::TestWithParam<Survey_sampling> {};

TEST_P(SurveySampling, AgreesWithTheSurveysSamplingTool) {
  const Survey_sampling& survey = GetParam();
  const std::string data = CURVEBENCH_SOURCE_DIR "/data/";
  const geometry::Curve curve = geometry::make_curve("svg:" + data + "svg/" + survey.curve + ".svg");
  const geometry::Local_feature_size lfs(curve);
  const double floor = geometry::default_minimum_lfs(lfs);

  const auto theirs =
      geometry::read_point_file(data + "sample2d/" + survey.curve + "_" + epsilon_text(survey.epsilon) + ".txt").points;
  ASSERT_EQ(theirs.size(), survey.points);
  const double their_epsilon = measure_epsilon(lfs, theirs, floor).epsilon;

  const geometry::Sample ours = geometry::safe_epsilon_sampling(lfs, survey.epsilon, floor);
  const double our_epsilon = measure_epsilon(lfs, ours.points, ours.minimum_lfs).epsilon;

  std::printf("%s at %g: sample2d %zu points, measured %.4f (%.4f x); ours %zu points (%.3f x), measured %.4f\n",
              survey.curve, survey.epsilon, theirs.size(), their_epsilon, their_epsilon / survey.epsilon, ours.size(),
              double(ours.size()) / double(theirs.size()), our_epsilon);
  EXPECT_LE(std::abs(their_epsilon / survey.epsilon - 1), 0.05);
  EXPECT_LE(double(ours.size()), 1.1 * double(theirs.size()));
  EXPECT_LE(our_epsilon, survey.epsilon);
}

INSTANTIATE_TEST_SUITE_P(ClosedCurves, SurveySampling, ::testing::ValuesIn(survey_samplings),
                         [](const ::testing::TestParamInfo<Survey_sampling>& info) {
                           std::string name = info.param.curve + std::string("_") + epsilon_text(info.param.epsilon);
                           for (char& c : name)
                             if (c == '.') c = '_';
                           return name;
                         });

// The check can fail: with every join as written (corner=0), blob2's kinks are corners
// and the survey's sampling measures far above its epsilon (2.93 at 0.33).
TEST(SurveySampling, FailsOnBlob2TakenAsWritten) {
  const std::string data = CURVEBENCH_SOURCE_DIR "/data/";
  const geometry::Local_feature_size lfs(geometry::make_curve("svg:" + data + "svg/blob2.svg,corner=0"));
  const auto theirs = geometry::read_point_file(data + "sample2d/blob2_0.33.txt").points;
  EXPECT_GT(measure_epsilon(lfs, theirs, geometry::default_minimum_lfs(lfs)).epsilon, 0.33 * 1.05);
}

}  // namespace
}  // namespace curvebench::certify
