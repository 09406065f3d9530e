#include "bench/runner/suite.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "bench/runner/bench_input.h"
#include "geometry/curves/curve_spec.h"

namespace curvebench::bench {
namespace {

// Names and descriptions the suites' string_views point at, made once.
std::string_view stored(std::string value) {
  static std::vector<std::unique_ptr<std::string>> texts;
  return *texts.emplace_back(std::make_unique<std::string>(std::move(value)));
}

// `pattern` with "#" replaced by each seed first, first + 1, ...: one replayable name per
// instance of a generated family.
std::vector<std::string_view> seeded(std::string_view pattern, std::size_t first, std::size_t count) {
  std::vector<std::string_view> names;
  const std::size_t at = pattern.find('#');
  for (std::size_t seed = first; seed < first + count; ++seed)
    names.push_back(stored(std::string(pattern.substr(0, at)) + std::to_string(seed) + std::string(pattern.substr(at + 1))));
  return names;
}

std::vector<std::string_view> joined(std::initializer_list<std::vector<std::string_view>> parts) {
  std::vector<std::string_view> all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

// Smooth closed curves with their own ground truth: the survey's four closed Bézier
// outlines, which its sampling tool samples (simple, blob2, complex, spiral: smooth once
// rounding kinks are not corners, svg_path.h), then random Fourier curves, seeds 1, 2, ...:
// stand-ins for the survey's bunny and classic manifold curves, whose ground truth we
// cannot redistribute. Their complexity cycles with the seed: blobs of 3 harmonics, the
// default 5, and wiggly curves of 8 slowly decaying ones. A name per curve, so each
// instance replays on its own.
std::vector<std::string_view> smooth_closed_curves(std::size_t count) {
  constexpr std::string_view complexities[] = {",harmonics=3", "", ",harmonics=8,amplitude=0.5,decay=1.5"};
  std::vector<std::string_view> curves{"svg:data/svg/simple.svg", "svg:data/svg/blob2.svg", "svg:data/svg/complex.svg",
                                       "svg:data/svg/spiral.svg"};
  for (std::size_t seed = 1; curves.size() < count; ++seed)
    curves.push_back(stored("fourier:seed=" + std::to_string(seed) + std::string(complexities[seed % 3])));
  return curves;
}

// Each curve at its own requested epsilon, spread evenly over [0.05, 2) by the golden-ratio
// sequence, so that the measured epsilons cover the range without levels (suite `breakdown`).
std::vector<std::string_view> spread_over_epsilon(const std::vector<std::string_view>& curves) {
  std::vector<std::string_view> inputs;
  double fraction = 0.5;
  for (const std::string_view curve : curves) {
    fraction = std::fmod(fraction + 0.6180339887498949, 1.0);
    char epsilon[16];
    std::snprintf(epsilon, sizeof epsilon, "%.3f", 0.05 + 1.95 * fraction);
    inputs.push_back(stored(std::string(curve) + "|epsilon=" + epsilon));
  }
  return inputs;
}

// A share per cell rests on 30 instances in the default suites, so that it carries a
// Wilson interval a few tens of points wide rather than a coin's, and on 200 in `full`.
constexpr std::size_t default_instances = 30, full_instances = 200;

// The smooth-curve experiments, on `count` curves each (`suffix` names the size).
std::vector<Suite> smooth_curve_suites(std::size_t count, std::string_view suffix) {
  const auto name = [&](std::string_view base) { return stored(std::string(base) + std::string(suffix)); };
  const std::string curves = std::to_string(count) + " smooth closed curves of three complexities";
  const std::vector<std::string_view> inputs = smooth_closed_curves(count);
  return {
      {.name = name("sampling"),
       .description = stored("Sampling density: " + curves + ", safe epsilon-sampling (survey: Sampling Density)"),
       .inputs = inputs,
       .settings = "|epsilon={}",
       .variable = "epsilon",
       .levels = {"0.25", "0.5", "0.75"}},
      {.name = name("noisy"),
       .description = stored("Uniform noise of extent delta x bounding-box diagonal at epsilon 0.3, " + curves +
                             " (survey: Uniform Noise)"),
       .inputs = inputs,
       .settings = "|epsilon=0.3|noise={}|seed=1",
       .variable = "delta",
       .levels = {"0", "0.003", "0.01", "0.03"}},
      {.name = name("lfsnoise"),
       .description = stored("Noise along the normal of delta x lfs at epsilon 0.3, " + curves +
                             " (survey: LFS-based Noise)"),
       .inputs = inputs,
       .settings = "|epsilon=0.3|lfs-noise={}|seed=1",
       .variable = "delta",
       .levels = {"0", "0.1", "0.33", "0.5"}},
      {.name = name("sampling-noise"),
       .description = stored("Varying sampling density with lfs noise delta = 1/3, " + curves +
                             " (survey: Varying Sampling Density + LFS Noise)"),
       .inputs = inputs,
       .settings = "|epsilon={}|lfs-noise=0.33|seed=1",
       .variable = "epsilon",
       .levels = {"0.1", "0.2", "0.4"}},
      {.name = name("outliers"),
       .description = stored("Outliers uniform in the bounding box, percent of the samples, at epsilon 0.3, " + curves +
                             " (survey: Outliers)"),
       .inputs = inputs,
       .settings = "|epsilon=0.3|outliers={}|seed=1",
       .variable = "percent",
       .levels = {"0", "5", "10", "20"}},
  };
}

// The generated families with exact ground truth beyond one smooth closed curve, `count`
// instances per cell: open curves, several components, crossings, sharp and rounded corners.
std::vector<Suite> family_suites(std::size_t count, std::string_view suffix) {
  const auto name = [&](std::string_view base) { return stored(std::string(base) + std::string(suffix)); };
  const std::size_t third = count / 3, half = count / 2;
  const std::string n = std::to_string(count);
  return {
      {.name = name("open-curves"),
       .description = stored("Open curves, " + n + " per cell: a third smooth closed curves with 10% of their "
                             "parameter range missing (the survey's samples missing from a boundary), a third "
                             "half curves (arcs), a third spirals; safe epsilon-sampling (survey: Open Curves)"),
       .inputs = joined({seeded("fourier:seed=#,gap=0.1|epsilon={}", 1, third),
                         seeded("fourier:seed=#,gap=0.5|epsilon={}", 1, third),
                         seeded("spiral:seed=#|epsilon={}", 1, count - 2 * third)}),
       .variable = "epsilon",
       .levels = {"0.2", "0.4"}},
      {.name = name("multiple-curves"),
       .description = stored("Several components at a separation D, " + n + " per cell: half a smooth curve with a "
                             "hole D inside it (nested), half two curves whose bounding boxes are D apart; 64 points "
                             "per unit of circle length, so where the components face each other (lfs D / 2) the "
                             "samples are 0.2 / D lfs apart (survey: Multiple Curves)"),
       .inputs = joined({seeded("nested:seed=#,separation={}|per-circle=64", 1, half),
                         seeded("fourier:seed=#,components=2,separation={}|per-circle=64", 1, count - half)}),
       .variable = "separation",
       .levels = {"0.1", "0.04", "0.02"}},
      {.name = name("intersecting"),
       .description = stored("Smooth closed curves crossing themselves transversally, " + n + " per cell: Lissajous "
                             "figures with 1, 2 and 7 crossings, 100 points per unit of circle length at equal "
                             "steps (lfs is 0 at a crossing, so no epsilon-sampling reaches it); "
                             "crossings=1 puts a sample on each crossing, shared by both branches (degree 4 in the "
                             "ground truth), crossings=0 lets the branches pass between samples (survey: Non-manifold "
                             "Point Sets, Curves with Self-Intersections)"),
       .inputs = joined({seeded("lissajous:a=1,b=2,seed=#", 1, third), seeded("lissajous:a=1,b=3,seed=#", 1, third),
                         seeded("lissajous:a=2,b=3,seed=#", 1, count - 2 * third)}),
       .settings = "|per-circle=100|crossings={}",
       .variable = "crossings",
       .levels = {"0", "1"}},
      {.name = name("sharp-corners"),
       .description = stored("Non-convex star polygons with every tip at the given angle, " + n + " per cell, 32 "
                             "points per unit of circle length at equal steps as the survey's corner family "
                             "(survey: Sharp Corners)"),
       .inputs = seeded("star:seed=#,angle={}|per-circle=32", 1, count),
       .variable = "angle",
       .levels = {"30", "60", "90"}},
      {.name = name("rounded-corners"),
       .description = stored("The stars of sharp-corners with every corner rounded by an arc of radius 0.05: the "
                             "same turns, smooth (lfs > 0), " + n + " per cell (control for sharp-corners)"),
       .inputs = seeded("star:seed=#,angle={},rounding=0.05|per-circle=32", 1, count),
       .variable = "angle",
       .levels = {"30", "60", "90"}},
  };
}

const std::vector<Suite>& table() {
  static const std::vector<Suite> all = [] {
    std::vector<Suite> suites = smooth_curve_suites(default_instances, "");
    for (Suite& suite : family_suites(default_instances, "")) suites.push_back(std::move(suite));
    for (Suite& suite : smooth_curve_suites(full_instances, "-full")) suites.push_back(std::move(suite));
    for (Suite& suite : family_suites(full_instances, "-full")) suites.push_back(std::move(suite));
    suites.insert(suites.end(), {
      {.name = "manifold",
       .description = "Whether the output is a manifold, on the bundled classic point sets (no ground truth) and "
                      "sampled smooth closed curves (survey: Manifold Curves)",
       .inputs = joined({{"file:data/hnncrust/crocodile-conf.p2d", "file:data/hnncrust/mushroom.p2d",
                          "file:data/hnncrust/ventilator.p2d", "file:data/stretchdenoise/Circle0.txt",
                          "file:data/stretchdenoise/Cup0.txt", "file:data/stretchdenoise/Keyboard0.txt",
                          "file:data/stretchdenoise/Mouse0.txt", "file:data/stretchdenoise/thing.txt",
                          "file:data/stretchdenoise/vase.txt", "file:data/stretchdenoise/drill.txt",
                          "svg:data/svg/simple.svg|epsilon=0.4"},
                         seeded("fourier:seed=#|epsilon=0.4", 1, 29)})},
      {.name = "corner-family",
       .description = "The survey's sharp-corner family: a unit circle opening to a corner of the given angle, "
                      "10, 16 and 20 points per circle, a sample at the corner (survey: Sharp Corners)",
       .inputs = {"corner:angle={}|per-circle=10", "corner:angle={}|per-circle=16", "corner:angle={}|per-circle=20"},
       .variable = "angle",
       .levels = {"10", "20", "30", "40", "50", "60", "70", "80", "90"}},
      {.name = "drawings",
       .description = "Real drawings, outside every theorem (corners, T-junctions, touching strokes: measured epsilon "
                      "is infinite): the SVG animals, multi-curve and crossing drawings and DejaVu glyphs, epsilon "
                      "0.3 (survey: Open Curves, Multiple Curves, Qualitative Comparison)",
       .inputs = {"svg:data/svg/Deery.svg|epsilon=0.3", "svg:data/svg/Fishi.svg|epsilon=0.3",
                  "svg:data/svg/Goldi.svg|epsilon=0.3", "svg:data/svg/Porpi.svg|epsilon=0.3",
                  "svg:data/svg/Snail.svg|epsilon=0.3", "svg:data/svg/Spidy.svg|epsilon=0.3",
                  "svg:data/svg/Frog2.svg|epsilon=0.3", "svg:data/svg/Croco.svg|epsilon=0.3",
                  "svg:data/svg/f1.svg|epsilon=0.3", "svg:data/svg/f4.svg|epsilon=0.3",
                  "svg:data/svg/f2.svg|epsilon=0.3", "svg:data/svg/f6.svg|epsilon=0.3",
                  "glyph:B|epsilon=0.3", "glyph:g|epsilon=0.3", "glyph:8|epsilon=0.3", "glyph:%|epsilon=0.3",
                  "glyph:@|epsilon=0.3", "glyph:a|epsilon=0.3", "glyph:e|epsilon=0.3", "glyph:k|epsilon=0.3",
                  "glyph:R|epsilon=0.3", "glyph:S|epsilon=0.3", "glyph:Q|epsilon=0.3", "glyph:&|epsilon=0.3",
                  "glyph:$|epsilon=0.3", "glyph:4|epsilon=0.3", "glyph:w|epsilon=0.3", "glyph:x|epsilon=0.3",
                  "glyph:y|epsilon=0.3", "glyph:3|epsilon=0.3"}},
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
       .levels = {"1000", "10000"}},
      {.name = "runtime-large",
       .description = "Runtime at n = 100,000 on the curve of `runtime`",
       .inputs = {"fourier:seed=7|uniform=100000"}},
      {.name = "glyphs",
       .description = "Every glyph of DejaVu Sans, safe epsilon-sampling: the large real-curve set",
       .inputs = {"glyph:*|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.2", "0.4", "0.6"}},
      {.name = "certify",
       .description = "Empirical breakdown: exact reconstruction against the measured epsilon (and rho) of 30 smooth "
                      "curves with 8 harmonics, from dense to sparser than any theorem covers (survey: Guarantees as "
                      "Sampling Conditions)",
       .inputs = seeded("fourier:seed=#,harmonics=8,amplitude=0.6,decay=1|epsilon={}", 1, 30),
       .variable = "epsilon",
       .levels = {"0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.8", "1"}},
      {.name = "breakdown",
       .description = "Empirical breakdown as numbers: 1,000 smooth closed curves of three complexities, each at "
                      "its own epsilon between 0.05 and 2 (the theorems stop below 0.5, the algorithms from about 0.8); the report fits each algorithm's exact rate against the "
                      "measured epsilon (survey: Guarantees as Sampling Conditions)",
       .inputs = spread_over_epsilon(smooth_closed_curves(1000))},
      {.name = "smoke",
       .description = "Two circles, for tests: a dense and a coarse sampling",
       .inputs = {"circle:r=1|epsilon={}"},
       .variable = "epsilon",
       .levels = {"0.1", "0.6"}},
      // Every kind of input the experiments make, one or two of each, and more sources than
      // two batches of a two-worker run (run.cpp makes 8 per worker at a time, in this
      // process, before forking the workers): the determinism test runs it three ways.
      {.name = "determinism",
       .description = "For tests: one or two inputs of every experiment (30 sources: sampled, noisy, with outliers, "
                      "open, several curves, crossings, corners, drawings, glyphs, the bundled point sets, 1,000 "
                      "points), each once",
       .inputs = {"svg:data/svg/simple.svg|epsilon=0.3", "fourier:seed=1,harmonics=3|epsilon=0.25",
                  "fourier:seed=2|epsilon=0.5", "fourier:seed=3,harmonics=8,amplitude=0.5,decay=1.5|epsilon=0.75",
                  "fourier:seed=4|epsilon=0.3|noise=0.01|seed=1", "fourier:seed=5|epsilon=0.3|lfs-noise=0.33|seed=1",
                  "fourier:seed=6|epsilon=0.2|lfs-noise=0.33|seed=1", "fourier:seed=7|epsilon=0.3|outliers=10|seed=1",
                  "fourier:seed=1,gap=0.1|epsilon=0.2", "fourier:seed=2,gap=0.5|epsilon=0.4", "spiral:seed=1|epsilon=0.2",
                  "nested:seed=1,separation=0.04|per-circle=64",
                  "fourier:seed=1,components=2,separation=0.02|per-circle=64",
                  "lissajous:a=1,b=2,seed=1|per-circle=100|crossings=1",
                  "lissajous:a=2,b=3,seed=1|per-circle=100|crossings=0", "star:seed=1,angle=30|per-circle=32",
                  "star:seed=2,angle=60,rounding=0.05|per-circle=32", "corner:angle=20|per-circle=16",
                  "fourier:seed=8,harmonics=8,amplitude=0.6,decay=1|epsilon=0.6", "svg:data/svg/f4.svg|epsilon=0.3",
                  "svg:data/svg/Snail.svg|epsilon=0.3", "glyph:B|epsilon=0.3", "glyph:%|epsilon=0.4",
                  "glyph:x|epsilon=0.6", "file:data/hnncrust/mushroom.p2d", "file:data/stretchdenoise/Keyboard0.txt",
                  "file:data/stretchdenoise/stair.xy", "file:data/stretchdenoise/apple_2percent_noise.txt",
                  "file:data/hnncrust/crocodile-conf.p2d|outliers=5|seed=2", "fourier:seed=9|uniform=1000"}},
      {.name = "default",
       .description = "The main job, about a minute on 2 cores: every experiment but the glyphs, 30 instances a cell",
       .parts = {"sampling", "noisy", "lfsnoise", "sampling-noise", "outliers", "open-curves", "multiple-curves",
                 "intersecting", "sharp-corners", "rounded-corners", "manifold", "drawings", "qualitative", "runtime",
                 "certify"}},
      {.name = "all",
       .description = "Every experiment suite at its default size",
       .parts = {"sampling", "noisy", "lfsnoise", "sampling-noise", "outliers", "open-curves", "multiple-curves",
                 "intersecting", "sharp-corners", "rounded-corners", "manifold", "corner-family", "drawings",
                 "qualitative", "runtime", "runtime-large", "certify", "breakdown", "glyphs"}},
      {.name = "full",
       .description = "The generated experiments on 200 instances per cell, for rates with narrow intervals "
                      "(about 4 minutes on 2 cores; shard it for more)",
       .parts = {"sampling-full", "noisy-full", "lfsnoise-full", "sampling-noise-full", "outliers-full",
                 "open-curves-full", "multiple-curves-full", "intersecting-full", "sharp-corners-full",
                 "rounded-corners-full"}},
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
