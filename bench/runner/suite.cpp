#include "bench/runner/suite.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "bench/runner/bench_input.h"
#include "geometry/curves/curve_spec.h"

namespace curvebench::bench {
namespace {

// Smooth closed curves with their own ground truth: the SVG Bézier outline that is
// smooth (simple.svg; blob2.svg and complex.svg have tangent breaks, lfs 0, so they are
// not) and random Fourier curves, seeds 1, 2, ...: stand-ins for the survey's bunny and
// classic manifold curves, whose ground truth we cannot redistribute. A name per curve,
// so each instance replays on its own.
std::vector<std::string_view> smooth_closed_curves(std::size_t count) {
  static std::vector<std::unique_ptr<std::string>> names;  // the views below point here
  while (names.size() + 1 < count) names.push_back(std::make_unique<std::string>("fourier:seed=" + std::to_string(names.size() + 1)));
  std::vector<std::string_view> curves{"svg:data/svg/simple.svg"};
  for (std::size_t i = 0; i + 1 < count; ++i) curves.push_back(*names[i]);
  return curves;
}

// A share of one closed curve per input (the noise experiments) rests on 30 curves in the
// default suites, so that it carries a Wilson interval a few tens of points wide rather
// than a coin's, and on 200 in the `full` suite.
constexpr std::size_t default_instances = 30, full_instances = 200;

// The smooth-curve experiments, on `count` curves each (`suffix` names the size).
std::vector<Suite> smooth_curve_suites(std::size_t count, std::string_view suffix) {
  static std::vector<std::unique_ptr<std::string>> texts;  // names and descriptions the views keep
  const auto text = [](std::string value) -> std::string_view {
    return *texts.emplace_back(std::make_unique<std::string>(std::move(value)));
  };
  const std::string curves = std::to_string(count) + " smooth closed curves";
  const std::vector<std::string_view> inputs = smooth_closed_curves(count);
  return {
      {.name = text("sampling" + std::string(suffix)),
       .description = text("Sampling density: " + curves + ", safe epsilon-sampling (survey: Sampling Density)"),
       .inputs = inputs,
       .settings = "|epsilon={}",
       .variable = "epsilon",
       .levels = {"0.25", "0.5", "0.75"}},
      {.name = text("noisy" + std::string(suffix)),
       .description = text("Uniform noise of extent delta x bounding-box diagonal at epsilon 0.3, " + curves +
                           " (survey: Uniform Noise)"),
       .inputs = inputs,
       .settings = "|epsilon=0.3|noise={}|seed=1",
       .variable = "delta",
       .levels = {"0", "0.003", "0.01", "0.03"}},
      {.name = text("lfsnoise" + std::string(suffix)),
       .description = text("Noise along the normal of delta x lfs at epsilon 0.3, " + curves +
                           " (survey: LFS-based Noise)"),
       .inputs = inputs,
       .settings = "|epsilon=0.3|lfs-noise={}|seed=1",
       .variable = "delta",
       .levels = {"0", "0.1", "0.33", "0.5"}},
      {.name = text("sampling-noise" + std::string(suffix)),
       .description = text("Varying sampling density with lfs noise delta = 1/3, " + curves +
                           " (survey: Varying Sampling Density + LFS Noise)"),
       .inputs = inputs,
       .settings = "|epsilon={}|lfs-noise=0.33|seed=1",
       .variable = "epsilon",
       .levels = {"0.1", "0.2", "0.4"}},
      {.name = text("outliers" + std::string(suffix)),
       .description = text("Outliers uniform in the bounding box, percent of the samples, at epsilon 0.3, " + curves +
                           " (survey: Outliers)"),
       .inputs = inputs,
       .settings = "|epsilon=0.3|outliers={}|seed=1",
       .variable = "percent",
       .levels = {"0", "5", "10", "20"}},
  };
}

const std::vector<Suite>& table() {
  static const std::vector<Suite> all = [] {
    std::vector<Suite> suites = smooth_curve_suites(default_instances, "");
    for (Suite& suite : smooth_curve_suites(full_instances, "-full")) suites.push_back(std::move(suite));
    suites.insert(suites.end(), {
      {.name = "manifold",
       .description = "Whether the output is a manifold, on the bundled classic point sets and sampled closed curves "
                      "(survey: Manifold Curves)",
       .inputs = {"file:data/hnncrust/crocodile-conf.p2d", "file:data/hnncrust/mushroom.p2d",
                  "file:data/hnncrust/ventilator.p2d", "file:data/stretchdenoise/Circle0.txt",
                  "file:data/stretchdenoise/Cup0.txt", "file:data/stretchdenoise/Keyboard0.txt",
                  "file:data/stretchdenoise/Mouse0.txt", "file:data/stretchdenoise/thing.txt",
                  "file:data/stretchdenoise/vase.txt", "file:data/stretchdenoise/drill.txt",
                  "svg:data/svg/simple.svg|epsilon=0.4", "svg:data/svg/blob2.svg|epsilon=0.4",
                  "svg:data/svg/complex.svg|epsilon=0.4", "fourier:seed=1|epsilon=0.4", "fourier:seed=2|epsilon=0.4",
                  "fourier:seed=3|epsilon=0.4"}},
      {.name = "sharp-corners",
       .description = "The survey's sharp-corner family: a unit circle opening to a corner of the given angle, "
                      "10, 16 and 20 points per circle, a sample at the corner (survey: Sharp Corners)",
       .inputs = {"corner:angle={}|per-circle=10", "corner:angle={}|per-circle=16", "corner:angle={}|per-circle=20"},
       .variable = "angle",
       .levels = {"10", "20", "30", "40", "50", "60", "70", "80", "90"}},
      {.name = "open-curves",
       .description = "Open curves of the bundled SVG drawings (survey: Open Curves)",
       .inputs = {"svg:data/svg/Deery.svg|epsilon={}", "svg:data/svg/Fishi.svg|epsilon={}",
                  "svg:data/svg/Goldi.svg|epsilon={}", "svg:data/svg/Porpi.svg|epsilon={}",
                  "svg:data/svg/Snail.svg|epsilon={}", "svg:data/svg/Spidy.svg|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.2", "0.4"}},
      {.name = "multiple-curves",
       .description = "Several components: multi-curve drawings and glyphs with holes (survey: Multiple Curves)",
       .inputs = {"svg:data/svg/Frog2.svg|epsilon={}", "svg:data/svg/Croco.svg|epsilon={}", "glyph:B|epsilon={}",
                  "glyph:g|epsilon={}", "glyph:8|epsilon={}", "glyph:%|epsilon={}", "glyph:@|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.2", "0.4"}},
      {.name = "intersecting",
       .description = "Curves that cross themselves (lfs 0 at the crossing, floored) (survey: Curves with "
                      "Self-Intersections)",
       .inputs = {"svg:data/svg/f1.svg|epsilon={}", "svg:data/svg/f4.svg|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.2", "0.4"}},
      {.name = "qualitative",
       .description = "The bundled point sets of the surveyed authors, without ground truth: topology and pictures "
                      "(survey: Qualitative Comparison)",
       .inputs = {"file:data/hnncrust/crocodile-conf.p2d", "file:data/hnncrust/mushroom.p2d",
                  "file:data/hnncrust/ventilator.p2d", "file:data/stretchdenoise/apple_2percent_noise.txt",
                  "file:data/stretchdenoise/butterfly_2percent_noise.txt", "file:data/stretchdenoise/fish.txt",
                  "file:data/stretchdenoise/stair.xy", "file:data/stretchdenoise/Monitor0.txt"}},
      {.name = "runtime",
       .description = "Runtime over growing n on one smooth curve (survey: Computational Time)",
       .inputs = {"fourier:seed=7|uniform={}"},
       .variable = "n",
       .levels = {"1000", "10000", "100000"}},
      {.name = "glyphs",
       .description = "Every glyph of DejaVu Sans, safe epsilon-sampling: the large real-curve set",
       .inputs = {"glyph:*|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.2", "0.4", "0.6"}},
      {.name = "certify",
       .description = "Empirical breakdown: exact reconstruction against the measured epsilon (and rho) of smooth "
                      "curves, from dense to sparser than any theorem covers (survey: Guarantees as Sampling Conditions)",
       .inputs = {"fourier:seed=1,harmonics=8,amplitude=0.6,decay=1|epsilon={}",
                  "fourier:seed=2,harmonics=8,amplitude=0.6,decay=1|epsilon={}",
                  "fourier:seed=3,harmonics=8,amplitude=0.6,decay=1|epsilon={}",
                  "fourier:seed=4,harmonics=8,amplitude=0.6,decay=1|epsilon={}",
                  "fourier:seed=5,harmonics=8,amplitude=0.6,decay=1|epsilon={}",
                  "fourier:seed=6,harmonics=8,amplitude=0.6,decay=1|epsilon={}", "svg:data/svg/simple.svg|epsilon={}",
                  "svg:data/svg/blob2.svg|epsilon={}", "svg:data/svg/complex.svg|epsilon={}",
                  "svg:data/svg/spiral.svg|epsilon={}", "glyph:O|epsilon={}", "glyph:o|epsilon={}", "glyph:0|epsilon={}",
                  "glyph:S|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.05", "0.1", "0.15", "0.2", "0.25", "0.3", "0.35", "0.4", "0.45", "0.5",
                  "0.55", "0.6", "0.65", "0.7", "0.75", "0.8", "0.85", "0.9", "0.95", "1"}},
      {.name = "smoke",
       .description = "Two circles, for tests: a dense and a coarse sampling",
       .inputs = {"circle:r=1|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.1", "0.6"}},
      {.name = "default",
       .description = "The main job, well under 5 minutes on 2 cores: every experiment but the glyphs",
       .parts = {"sampling", "noisy", "lfsnoise", "sampling-noise", "outliers", "manifold", "sharp-corners",
                 "open-curves", "multiple-curves", "intersecting", "qualitative", "runtime", "certify"}},
      {.name = "all",
       .description = "Every experiment suite",
       .parts = {"sampling", "noisy", "lfsnoise", "sampling-noise", "outliers", "manifold", "sharp-corners",
                 "open-curves", "multiple-curves", "intersecting", "qualitative", "runtime", "certify", "glyphs"}},
      {.name = "full",
       .description = "The smooth-curve experiments on 200 curves per cell, for rates with narrow intervals "
                      "(under an hour on 2 cores; shard it for more)",
       .parts = {"sampling-full", "noisy-full", "lfsnoise-full", "sampling-noise-full", "outliers-full"}},
    });
    return suites;
  }();
  return all;
}

std::string substituted(std::string_view text, std::string_view value) {
  std::string result(text);
  for (std::size_t at; (at = result.find("{}")) != std::string::npos;) result.replace(at, 2, value);
  return result;
}

}  // namespace

std::span<const Suite> suites() { return table(); }

const Suite* find_suite(std::string_view name) {
  const auto found = std::ranges::find(table(), name, &Suite::name);
  return found == table().end() ? nullptr : &*found;
}

std::vector<Suite_case> suite_cases(const Suite& suite) {
  std::vector<Suite_case> cases;
  for (const std::string_view part : suite.parts) {
    const Suite* inner = find_suite(part);
    if (!inner || !inner->parts.empty()) throw std::invalid_argument("suite " + std::string(suite.name) + ": bad part " + std::string(part));
    for (Suite_case& c : suite_cases(*inner)) cases.push_back(std::move(c));
  }
  const std::vector<std::string_view> one_level{""};
  for (const std::string_view input : suite.inputs)
    for (const std::string_view level : suite.variable.empty() ? one_level : suite.levels) {
      const std::string name = substituted(std::string(input) + std::string(suite.settings), level);
      const std::string label = suite.variable.empty() ? "" : std::string(suite.variable) + "=" + std::string(level);
      const std::string_view source = input_source(name);
      for (const std::string& spec : geometry::expand_curve_specs(source))
        cases.push_back({std::string(suite.name), spec + name.substr(source.size()), label});
    }
  return cases;
}

}  // namespace curvebench::bench
