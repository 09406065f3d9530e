// Issue "Curves, medial axis + lfs, and samplers": every bundled SVG and every glyph of
// DejaVuSans.ttf samples without error at epsilon 0.1, 0.3 and 0.5, and the safe sampler's
// measured epsilon (certify/sampling_measure.h, an independent dense search) is at most the
// requested one. Thousands of human-designed curves with corners, holes and thin features.
//
// All 5857 glyphs take about 20 CPU-minutes (most of it near corners, where the lfs floor
// makes samples dense), so CI checks every 16th code point (~370 glyphs) and a full
// sweep runs with CURVEBENCH_GLYPH_STRIDE=1.
#include <gtest/gtest.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "certify/sampling_measure.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/curves/glyph_curves.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::certify {
namespace {

using namespace geometry;

constexpr double requested_epsilons[] = {0.1, 0.3, 0.5};

// "" if the safe sampler meets every requested epsilon on `curve`, else what went wrong.
std::string check_safe_sampling(const Curve& curve) {
  try {
    const Local_feature_size lfs(curve);
    const double minimum_lfs = default_minimum_lfs(lfs);
    for (const double epsilon : requested_epsilons) {
      const Sample sample = safe_epsilon_sampling(lfs, epsilon, minimum_lfs);
      if (sample.points.empty()) return "no points at epsilon " + std::to_string(epsilon);
      const double measured = measure_epsilon(lfs, sample.points, minimum_lfs).epsilon;
      if (!(measured <= epsilon))
        return "epsilon " + std::to_string(epsilon) + " measured " + std::to_string(measured);
    }
  } catch (const std::exception& error) {
    return std::string("threw: ") + error.what();
  }
  return "";
}

// Runs `check` on every curve in parallel; the failures, sorted by name.
template <class Curve_of>
std::vector<std::string> failures(std::size_t count, Curve_of curve_of) {
  std::vector<std::string> failed;
  std::mutex guard;
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    const Curve curve = curve_of(i);
    if (std::string why = check_safe_sampling(curve); !why.empty()) {
      const std::lock_guard lock(guard);
      failed.push_back(curve.name + ": " + why);
    }
  });
  std::ranges::sort(failed);
  return failed;
}

TEST(SamplingSweep, EveryBundledSvgMeetsTheRequestedEpsilon) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(CURVEBENCH_SOURCE_DIR) / "data/svg"))
    if (entry.path().extension() == ".svg") files.push_back(entry.path());
  ASSERT_GE(files.size(), 19u);
  const auto failed = failures(files.size(), [&](std::size_t i) { return make_curve("svg:" + files[i].string()); });
  EXPECT_TRUE(failed.empty()) << failed.size() << " failures, first: " << failed.front();
}

std::size_t glyph_stride() {
  const char* stride = std::getenv("CURVEBENCH_GLYPH_STRIDE");
  return stride ? std::max(1, std::atoi(stride)) : 16;
}

TEST(SamplingSweep, EveryDejaVuSansGlyphMeetsTheRequestedEpsilon) {
  const std::vector<char32_t> all = glyph_code_points(default_glyph_font);
  ASSERT_GT(all.size(), 5000u);
  std::vector<char32_t> code_points;
  for (std::size_t i = 0; i < all.size(); i += glyph_stride()) code_points.push_back(all[i]);
  const auto failed =
      failures(code_points.size(), [&](std::size_t i) { return glyph_curve(default_glyph_font, code_points[i]); });
  EXPECT_TRUE(failed.empty()) << failed.size() << " of " << code_points.size() << " glyphs fail, first: "
                              << (failed.empty() ? "" : failed.front());
}

}  // namespace
}  // namespace curvebench::certify
