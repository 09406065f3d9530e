// The benchmark runner: worker processes that crash or hang, input names, suites, the
// results table, and whole runs (rows, exact reconstruction of a dense circle, resume).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include <CGAL/Polygon_2_algorithms.h>

#include "algorithms/registry.h"
#include "bench/runner/bench_input.h"
#include "bench/runner/evaluation.h"
#include "bench/runner/process_pool.h"
#include "bench/runner/results_table.h"
#include "bench/runner/run.h"
#include "bench/runner/suite.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/io/point_io.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::bench {
namespace {

using Kind = Task_outcome::Kind;

// The hooks a host process sets (python/ does, for its interpreter): `before` and
// `after_parent` once per fork in the parent, `after_child` in the child before its first
// task. Five tasks in two workers that do not fail are two forks.
TEST(ProcessPool, ForkHooksRunAroundEachFork) {
  int before = 0, after_parent = 0;
  static bool hooked_child = false;  // set in the child's copy only
  const Fork_hooks previous = set_fork_hooks({.before = [&] { ++before; },
                                              .after_parent = [&] { ++after_parent; },
                                              .after_child = [] { hooked_child = true; }});
  std::vector<std::string> outputs(5);
  run_in_processes(
      5, {.workers = 2}, [](std::size_t) { return std::string(hooked_child ? "hooked" : "plain"); },
      [&](std::size_t i, Task_outcome outcome) { outputs[i] = outcome.output; });
  const Fork_hooks ours = set_fork_hooks(previous);
  EXPECT_TRUE(ours.before && ours.after_parent && ours.after_child);
  EXPECT_EQ(before, 2);
  EXPECT_EQ(after_parent, 2);
  EXPECT_FALSE(hooked_child);
  EXPECT_EQ(outputs, std::vector<std::string>(5, "hooked"));
  // Without hooks (empty functions), forks go on as before.
  run_in_processes(
      2, {.workers = 2}, [](std::size_t) { return std::string(hooked_child ? "hooked" : "plain"); },
      [&](std::size_t i, Task_outcome outcome) { outputs[i] = outcome.output; });
  EXPECT_EQ(outputs[0], "plain");
  EXPECT_EQ(before, 2);
}

// An interruption (python/'s Ctrl-C) ends the run at once: the check's exception passes on,
// and no child is left running (none is left to wait for).
TEST(ProcessPool, AnInterruptionEndsTheRunAndReapsItsChildren) {
  const auto start = std::chrono::steady_clock::now();
  const std::function<void()> previous = set_interruption_check([&] {
    if (std::chrono::steady_clock::now() - start > std::chrono::milliseconds(300)) throw std::runtime_error("interrupted");
  });
  std::size_t done = 0;
  EXPECT_THROW(run_in_processes(
                   4, {.workers = 2},
                   [](std::size_t) {
                     std::this_thread::sleep_for(std::chrono::seconds(30));
                     return std::string("slept");
                   },
                   [&](std::size_t, Task_outcome) { ++done; }),
               std::runtime_error);
  set_interruption_check(previous);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_EQ(done, 0u);
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);  // no child at all, running or unreaped
  EXPECT_EQ(errno, ECHILD);
}

TEST(ProcessPool, ACrashOrAHangCostsOnlyItsOwnTask) {
  std::map<std::size_t, Task_outcome> outcomes;
  const auto start = std::chrono::steady_clock::now();
  run_in_processes(
      6, {.workers = 3, .timeout_seconds = 1},
      [](std::size_t i) -> std::string {
        switch (i) {
          case 1: raise(SIGSEGV); break;
          case 2: std::abort();
          case 3: std::this_thread::sleep_for(std::chrono::seconds(30)); break;
          case 4: _exit(3);
          case 5: return std::string(1 << 20, 'x');  // more than a pipe holds at once
        }
        return "task " + std::to_string(i);
      },
      [&](std::size_t i, Task_outcome outcome) { EXPECT_TRUE(outcomes.emplace(i, std::move(outcome)).second); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  ASSERT_EQ(outcomes.size(), 6u);
  EXPECT_EQ(outcomes[0].kind, Kind::finished);
  EXPECT_EQ(outcomes[0].output, "task 0");
  EXPECT_EQ(outcomes[1].kind, Kind::crashed);
  EXPECT_NE(outcomes[1].reason.find("signal 11"), std::string::npos) << outcomes[1].reason;
  EXPECT_EQ(outcomes[2].kind, Kind::crashed);
  EXPECT_NE(outcomes[2].reason.find("signal 6"), std::string::npos) << outcomes[2].reason;
  EXPECT_EQ(outcomes[3].kind, Kind::timed_out);
  EXPECT_EQ(outcomes[4].kind, Kind::crashed);
  EXPECT_NE(outcomes[4].reason.find("status 3"), std::string::npos) << outcomes[4].reason;
  EXPECT_EQ(outcomes[5].kind, Kind::finished);
  EXPECT_EQ(outcomes[5].output.size(), 1u << 20);
}

// One worker runs task after task, in order; one that dies is replaced by a fresh fork for
// the tasks left, which the death does not reach. An empty answer is an answer.
TEST(ProcessPool, AWorkerRunsTaskAfterTaskAndIsReplacedWhenItDies) {
  std::map<std::size_t, Task_outcome> outcomes;
  run_in_processes(
      6, {.workers = 1},
      [](std::size_t i) -> std::string {
        if (i == 2) raise(SIGSEGV);
        if (i == 5) return "";
        return std::to_string(getpid());
      },
      [&](std::size_t i, Task_outcome outcome) { outcomes.emplace(i, std::move(outcome)); });
  ASSERT_EQ(outcomes.size(), 6u);
  const std::string parent = std::to_string(getpid());
  EXPECT_EQ(outcomes[0].output, outcomes[1].output);
  EXPECT_NE(outcomes[0].output, parent);
  EXPECT_EQ(outcomes[2].kind, Kind::crashed);
  EXPECT_EQ(outcomes[3].kind, Kind::finished);
  EXPECT_EQ(outcomes[3].output, outcomes[4].output);
  EXPECT_NE(outcomes[3].output, outcomes[0].output);
  EXPECT_EQ(outcomes[5].kind, Kind::finished);
  EXPECT_EQ(outcomes[5].output, "");
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);  // every worker reaped
}

// A worker stopped by SIGTERM (as scancel stops every process of a task) stops the run:
// its task gets no "crashed" row, which a resumed run would keep instead of running it.
TEST(ProcessPool, AWorkerStoppedFromOutsideStopsTheRunWithoutAnOutcome) {
  std::map<std::size_t, Task_outcome> outcomes;
  EXPECT_THROW(run_in_processes(
                   4, {.workers = 1},
                   [](std::size_t i) -> std::string {
                     if (i == 1) raise(SIGTERM);
                     return "ok";
                   },
                   [&](std::size_t i, Task_outcome outcome) { outcomes.emplace(i, std::move(outcome)); }),
               Run_stopped);
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_EQ(outcomes[0].kind, Kind::finished);
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);  // every worker reaped
}

TEST(ProcessPool, AMemoryHogFailsAlone) {
  Task_outcome outcome;
  run_in_processes(
      1, {.workers = 1, .memory_limit_bytes = 1ull << 30},
      [](std::size_t) -> std::string {
        try {
          std::vector<char> huge(4ull << 30, 1);
          return "allocated";
        } catch (const std::bad_alloc&) {
          return "bad_alloc";
        }
      },
      [&](std::size_t, Task_outcome o) { outcome = std::move(o); });
  EXPECT_EQ(outcome.output, "bad_alloc");
}

TEST(BenchInput, ACircleSampleHasItsClosedChainAsGroundTruth) {
  const std::vector<std::string> names{"circle:r=1|epsilon=0.1", "circle:r=1|uniform=12|noise=0.01|seed=4"};
  const std::vector<Bench_input> inputs = make_bench_inputs(names);
  ASSERT_EQ(inputs.size(), 2u);
  for (const Bench_input& input : inputs) {
    const std::size_t n = input.points.size();
    ASSERT_TRUE(input.truth.has_value());
    ASSERT_EQ(input.truth->size(), n);  // a closed chain: as many edges as points
    std::map<std::size_t, int> degree;
    for (const auto& [i, j] : *input.truth) ++degree[i], ++degree[j];
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(degree[i], 2);
    ASSERT_TRUE(input.curve);
    for (const Point& p : input.curve->points) EXPECT_NEAR(std::hypot(p.x(), p.y()), 1, 1e-3);
  }
  EXPECT_EQ(inputs[1].points.size(), 12u);
  // Noise moves the points off the circle but within 1% of the diagonal (2 sqrt 2).
  double largest = 0;
  for (const Point& p : inputs[1].points) largest = std::max(largest, std::abs(std::hypot(p.x(), p.y()) - 1));
  EXPECT_GT(largest, 0);
  EXPECT_LE(largest, 0.01 * 2 * std::sqrt(2.0) + 1e-12);
  // The same name gives the same bits.
  EXPECT_EQ(make_bench_inputs(names)[1].points, inputs[1].points);
}

TEST(BenchInput, APointFileHasNoGroundTruth) {
  const std::vector<std::string> names{"file:data/hnncrust/mushroom.p2d", "file:data/hnncrust/mushroom.p2d|outliers=10"};
  const std::vector<Bench_input> inputs = make_bench_inputs(names);
  const auto file = geometry::read_point_file(std::filesystem::path(CURVEBENCH_SOURCE_DIR) / "data/hnncrust/mushroom.p2d");
  EXPECT_EQ(inputs[0].points, file.points);
  EXPECT_FALSE(inputs[0].truth);
  EXPECT_FALSE(inputs[0].curve);
  EXPECT_EQ(inputs[1].points.size(), file.points.size() + static_cast<std::size_t>(std::round(0.1 * file.points.size())));
}

TEST(BenchInput, MalformedNamesAreClearErrors) {
  for (const std::string name : {"circle:r=1", "circle:r=1|epsilon=0.1|uniform=5", "circle:r=1|epsilon=x",
                                 "circle:r=1|colour=red", "circle:r=1|uniform=2.5", "file:data/hnncrust/mushroom.p2d|epsilon=0.2",
                                 "circle:r=1|epsilon=0.1|seed=1|seed=2"}) {
    const std::vector<std::string> names{name};
    EXPECT_THROW(make_bench_inputs(names), std::invalid_argument) << name;
  }
}

// An algorithm that moves points: the reconstruction of a square's corners, each moved a
// little and listed in another order, is exact; moved halfway to a neighbour, or two
// points for one corner, it is not.
TEST(Evaluation, MovedPointsAreMatchedToTheInputPointTheyStandFor) {
  const std::vector<Point> input{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Edge> truth{{0, 1}, {0, 3}, {1, 2}, {2, 3}};
  const geometry::Polyline_view truth_view{input, truth};
  const auto exact = [&](const std::vector<Point>& output, const std::vector<Edge>& edges) {
    return evaluate({output, edges}, false, &truth_view, nullptr).exact;
  };
  // Output k is input 3 - k, moved by 0.1.
  const std::vector<Point> moved{{0.1, 1}, {1, 0.9}, {0.9, 0}, {0, 0.1}};
  const std::vector<Edge> renamed{{0, 1}, {0, 3}, {1, 2}, {2, 3}};
  EXPECT_EQ(exact(moved, renamed), true);
  EXPECT_EQ(exact(moved, {{0, 1}, {1, 2}, {2, 3}}), false);                  // an edge missing
  EXPECT_EQ(exact({{0.5, 1}, {1, 0.9}, {0.9, 0}, {0, 0.1}}, renamed), false);  // halfway: ambiguous
  EXPECT_EQ(exact({{0.1, 1}, {0.05, 1}, {0.9, 0}, {0, 0.1}}, renamed), false); // two for one corner
  // On the input points themselves, the edge sets are compared directly.
  EXPECT_EQ(evaluate({input, truth}, true, &truth_view, nullptr).exact, true);
}

// A simplifier's output on the unit square, measured each way against closed forms. The
// bottom edge and the corner (1, 1) alone: they lie on the square (0 out); from the square,
// the right side is min(y, 1 - y) away, the top 1 - x, the left y, so H = 1 (at (0, 1)) and
// RMS^2 = (0 + 1/12 + 1/3 + 1/3) / 4 = 3/16. Two opposite corners alone: every side runs
// from a kept corner to a dropped one, t away at t, so RMS^2 = 1/3.
TEST(Evaluation, ASimplifiersOutputIsMeasuredEachWayWithItsIsolatedVertices) {
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Edge> cycle{{0, 1}, {0, 3}, {1, 2}, {2, 3}};
  const geometry::Polyline_view truth{square, cycle};
  const std::vector<Point> kept{{0, 0}, {1, 0}, {1, 1}};
  const std::vector<Edge> bottom{{0, 1}};
  const Evaluation edge_and_corner = evaluate({kept, bottom}, false, &truth, nullptr, true);
  ASSERT_TRUE(edge_and_corner.to_curve && edge_and_corner.from_curve);
  EXPECT_NEAR(edge_and_corner.to_curve->hausdorff, 0, 1e-12);
  EXPECT_NEAR(edge_and_corner.to_curve->rms, 0, 1e-12);
  EXPECT_NEAR(edge_and_corner.from_curve->hausdorff, 1, 1e-12);
  EXPECT_NEAR(edge_and_corner.from_curve->rms, std::sqrt(3.0) / 4, 1e-6);
  EXPECT_EQ(edge_and_corner.topology.unconnected, 1u);  // the isolated corner

  const std::vector<Point> corners{{0, 0}, {1, 1}};
  const Evaluation two_corners = evaluate({corners, {}}, false, &truth, nullptr, true);
  ASSERT_TRUE(two_corners.from_curve);
  EXPECT_NEAR(two_corners.from_curve->hausdorff, 1, 1e-12);
  EXPECT_NEAR(two_corners.from_curve->rms, 1 / std::sqrt(3.0), 1e-6);
  EXPECT_EQ(two_corners.to_curve->hausdorff, 0);

  // An interpolator's points in no edge are no output: nothing is measured one way.
  const Evaluation interpolated = evaluate({kept, bottom}, false, &truth, nullptr);
  EXPECT_FALSE(interpolated.to_curve || interpolated.from_curve);
}

TEST(Suites, EveryCaseNamesAKnownSourceAndLevel) {
  std::set<std::string_view> names;
  for (const Suite& suite : suites()) {
    EXPECT_TRUE(names.insert(suite.name).second) << suite.name;
    if (suite.name == "glyphs" || suite.name == "all") continue;  // thousands of glyphs; covered by `all`'s parts
    const std::vector<Suite_case> cases = suite_cases(suite);
    EXPECT_FALSE(cases.empty()) << suite.name;
    for (const Suite_case& c : cases) {
      EXPECT_EQ(c.input.find("{}"), std::string::npos) << c.input;
      EXPECT_EQ(c.level.empty(), find_suite(c.suite)->variable.empty()) << c.input;
      const std::string_view source = input_source(c.input);
      if (source.starts_with("file:") || source.starts_with("svg:")) {
        EXPECT_TRUE(std::filesystem::exists(resolve_data_path(source.substr(source.find(':') + 1)))) << c.input;
      }
    }
  }
  const std::vector<Suite_case> smoke = suite_cases(*find_suite("smoke"));
  ASSERT_EQ(smoke.size(), 2u);
  EXPECT_EQ(smoke[0].input, "circle:r=1|epsilon=0.1");
  EXPECT_EQ(smoke[1].level, "epsilon=0.6");
}

// The smooth-curve experiments hold what their names say: every cell (suite x level) has
// its instance count, and every curve is closed with no corner (blob2.svg and complex.svg,
// once taken with their rounding kinks as corners, made "smooth" suites measure corners).
TEST(Suites, SmoothCurveCellsHaveTheirCountOfSmoothClosedCurves) {
  for (const auto& [suffix, count] : {std::pair<std::string, std::size_t>{"", 30}, {"-full", 200}}) {
    std::set<std::string> curves;
    for (const char* experiment : {"sampling", "noisy", "lfsnoise", "sampling-noise", "outliers"}) {
      const Suite* suite = find_suite(experiment + suffix);
      ASSERT_NE(suite, nullptr) << experiment << suffix;
      std::map<std::string, std::size_t> per_level;
      for (const Suite_case& c : suite_cases(*suite)) {
        ++per_level[c.level];
        curves.insert(std::string(input_source(c.input)));
      }
      EXPECT_EQ(per_level.size(), suite->levels.size()) << suite->name;
      for (const auto& [level, instances] : per_level) EXPECT_EQ(instances, count) << suite->name << ' ' << level;
    }
    EXPECT_EQ(curves.size(), count) << "the experiments of one size share their curves";
    for (std::string source : curves) {
      if (source.starts_with("svg:")) source = "svg:" + resolve_data_path(source.substr(4)).string();
      const geometry::Curve curve = geometry::make_curve(source);
      for (const geometry::Curve_component& component : curve.components) {
        EXPECT_TRUE(component.closed()) << source;
        EXPECT_TRUE(component.corners().empty()) << source << " has a tangent break";
      }
    }
  }
  EXPECT_FALSE(geometry::make_curve("svg:" + resolve_data_path("data/svg/blob2.svg").string() + ",corner=0")
                   .components.front()
                   .corners()
                   .empty());  // the check above can fail: blob2 as written has kinks
}

// The survey samples its four closed Bézier outlines in its sampling and noise experiments
// (survey: Sampling Density), and so do ours.
TEST(Suites, SmoothCurveExperimentsSampleTheSurveysClosedOutlines) {
  for (const char* experiment : {"sampling", "noisy", "lfsnoise", "sampling-noise", "outliers", "sampling-full"}) {
    std::set<std::string> svg;
    for (const Suite_case& c : suite_cases(*find_suite(experiment)))
      if (input_source(c.input).starts_with("svg:")) svg.insert(std::string(input_source(c.input)));
    EXPECT_EQ(svg, (std::set<std::string>{"svg:data/svg/blob2.svg", "svg:data/svg/complex.svg", "svg:data/svg/simple.svg",
                                          "svg:data/svg/spiral.svg"}))
        << experiment;
  }
}

// Every cell of the main job that yields a rate rests on 30 instances or more; the runtime
// suite (timing, one curve) and the qualitative one (no ground truth) yield none.
TEST(Suites, EveryDefaultCellHasThirtyInstances) {
  for (const std::string_view part : find_suite("default")->parts) {
    if (part == "runtime" || part == "qualitative") continue;
    std::map<std::string, std::size_t> per_level;
    for (const Suite_case& c : suite_cases(*find_suite(part))) ++per_level[c.level];
    for (const auto& [level, instances] : per_level) EXPECT_GE(instances, 30u) << part << ' ' << level;
  }
  for (const std::string_view part : find_suite("full")->parts) {
    std::map<std::string, std::size_t> per_level;
    for (const Suite_case& c : suite_cases(*find_suite(part))) ++per_level[c.level];
    for (const auto& [level, instances] : per_level) EXPECT_GE(instances, 200u) << part << ' ' << level;
  }
}

// The breakdown suite: 1,000 distinct smooth closed curves (the sampling suites' own), each
// at its own requested epsilon, spread evenly over [0.05, 2): every tenth of the range
// holds 100 of them, give or take the golden-ratio sequence's discrepancy.
TEST(Suites, BreakdownSpreadsOneThousandCurvesOverEpsilon) {
  const std::vector<Suite_case> cases = suite_cases(*find_suite("breakdown"));
  ASSERT_EQ(cases.size(), 1000u);
  std::set<std::string> curves;
  std::map<int, std::size_t> per_tenth;
  for (const Suite_case& c : cases) {
    curves.insert(std::string(input_source(c.input)));
    const std::string key = "|epsilon=";
    const std::size_t at = c.input.find(key);
    ASSERT_NE(at, std::string::npos) << c.input;
    const double epsilon = std::stod(c.input.substr(at + key.size()));
    ASSERT_TRUE(epsilon >= 0.05 && epsilon < 2) << c.input;
    ++per_tenth[static_cast<int>((epsilon - 0.05) / 0.195)];
  }
  EXPECT_EQ(curves.size(), 1000u);
  EXPECT_EQ(per_tenth.size(), 10u);
  for (const auto& [tenth, count] : per_tenth) EXPECT_NEAR(static_cast<double>(count), 100, 5) << "tenth " << tenth;
}

// The generated families hold what their names say, measured on their sampled ground truth
// with the project's own combinatorics (curve_topology) and exact predicates: each open
// curve has two ends, each multi-curve input two closed curves (the nested ones nested),
// each crossing input its stated number of crossings, each star its corners.
TEST(Suites, GeneratedFamiliesAreWhatTheirNamesSay) {
  const auto first_level_inputs = [](std::string_view suite_name) {
    const Suite& suite = *find_suite(suite_name);
    std::vector<std::vector<Bench_input>> inputs;
    for (const Suite_case& c : suite_cases(suite))
      if (c.level == std::string(suite.variable) + "=" + std::string(suite.levels.front()))
        inputs.push_back(make_bench_inputs(std::vector<std::string>{c.input}));
    return inputs;
  };
  const auto degrees = [](const Bench_input& input) {
    std::vector<int> degree(input.points.size());
    for (const Edge& e : *input.truth) ++degree[e.first], ++degree[e.second];
    return degree;
  };
  for (const auto& inputs : first_level_inputs("open-curves")) {
    const Bench_input& input = inputs.front();
    const geometry::Curve_topology topology = geometry::curve_topology(input.points.size(), *input.truth);
    EXPECT_EQ(topology.components, 1u) << input.name;
    EXPECT_EQ(topology.open_components, 1u) << input.name;
    EXPECT_EQ(std::ranges::count(degrees(input), 1), 2) << input.name;  // two curve ends
  }
  for (const auto& inputs : first_level_inputs("multiple-curves")) {
    const Bench_input& input = inputs.front();
    const geometry::Curve_topology topology = geometry::curve_topology(input.points.size(), *input.truth);
    EXPECT_EQ(topology.closed_components, 2u) << input.name;
    // The second component inside the first iff the input is nested (exact point location).
    const geometry::Curve curve = geometry::make_curve(input_source(input.name));
    const auto inside = [&](const geometry::Curve_component& outer, const Point& p) {
      const std::vector<Point> polygon = outer.polyline(1e-4);
      return CGAL::bounded_side_2(polygon.begin(), polygon.end(), p) == CGAL::ON_BOUNDED_SIDE;
    };
    EXPECT_EQ(inside(curve.components[0], curve.components[1].point(0)), input.name.starts_with("nested:")) << input.name;
  }
  for (const auto& inputs : first_level_inputs("intersecting")) {
    const Bench_input& input = inputs.front();  // crossings=0: the branches' truth edges cross
    const int a = input.name[input.name.find("a=") + 2] - '0', b = input.name[input.name.find("b=") + 2] - '0';
    const auto& edges = *input.truth;
    int crossing_pairs = 0;
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const auto [p, q] = edges[i];
        const auto [r, t] = edges[j];
        if (p == r || p == t || q == r || q == t) continue;
        crossing_pairs += CGAL::do_intersect(geometry::Kernel::Segment_2(input.points[p], input.points[q]),
                                             geometry::Kernel::Segment_2(input.points[r], input.points[t]));
      }
    EXPECT_EQ(crossing_pairs, 2 * a * b - a - b) << input.name;
    std::string shared = input.name;  // crossings=1: one point of degree 4 per crossing
    shared.replace(shared.size() - 1, 1, "1");
    const Bench_input with_samples = make_bench_inputs(std::vector<std::string>{shared}).front();
    EXPECT_EQ(std::ranges::count(degrees(with_samples), 4), 2 * a * b - a - b) << shared;
    EXPECT_EQ(with_samples.points.size(), input.points.size() + static_cast<std::size_t>(2 * a * b - a - b));
  }
  for (const char* suite : {"sharp-corners", "rounded-corners"})
    for (const Suite_case& c : suite_cases(*find_suite(suite))) {
      const geometry::Curve curve = geometry::make_curve(input_source(c.input));
      const std::size_t corners = curve.components[0].corners().size();
      if (std::string_view(suite) == "sharp-corners")
        EXPECT_EQ(corners, curve.components[0].piece_count()) << c.input;
      else
        EXPECT_EQ(corners, 0u) << c.input;
    }
}

TEST(ResultsTable, RowsSurviveQuotingAndACutOffLastLine) {
  testing::TemporaryDirectory dir;
  std::vector<Result_row> rows(2);
  rows[0][Column::job] = "0";
  rows[0][Column::input] = "svg:a,b.svg|epsilon=0.1";
  rows[0][Column::message] = "said \"no\", twice";
  rows[1][Column::job] = "7";
  rows[1][Column::hausdorff] = format_number(std::numeric_limits<double>::infinity());
  write_results_csv(dir.path() / "results.csv", rows);
  EXPECT_EQ(read_results_csv(dir.path() / "results.csv"), rows);
  std::ofstream(dir.path() / "results.csv", std::ios::app) << "8,sampling,cut";  // no line end
  EXPECT_EQ(read_results_csv(dir.path() / "results.csv"), rows);
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(std::stod(format_number(1.0 / 3)), 1.0 / 3);
  testing::TemporaryDirectory other;
  other.write("results.csv", "job,what\n1,2\n");
  EXPECT_THROW(read_results_csv(other.path() / "results.csv"), std::runtime_error);
}

// Every column but the runtime, which no two runs share.
std::vector<Result_row> without_runtimes(std::vector<Result_row> rows) {
  for (Result_row& row : rows) row[Column::runtime_ms].clear();
  return rows;
}

TEST(Run, SmokeSuiteRowsAndResume) {
  testing::TemporaryDirectory dir;
  Run_options options{.suite = "smoke", .output = dir.path() / "a", .algorithms = {"nn-crust", "emst", "crust"},
                      .jobs = 2, .report = false, .progress = false};
  const Run_summary summary = run_suite(options);
  EXPECT_EQ(summary.jobs, 6u);
  EXPECT_EQ(summary.ok, 6u);
  const std::vector<Result_row> rows = read_results_csv(options.output / "results.csv");
  ASSERT_EQ(rows.size(), 6u);
  for (std::size_t j = 0; j < rows.size(); ++j) {
    EXPECT_EQ(rows[j].job(), j);
    EXPECT_EQ(rows[j][Column::suite], "smoke");
    EXPECT_EQ(rows[j][Column::status], "ok") << rows[j][Column::message];
    EXPECT_TRUE(std::filesystem::exists(options.output / rows[j][Column::picture]));
  }
  // NN-Crust on the dense circle (epsilon 0.1 < 1/3) is exact, with distances below the
  // sagitta of its edges; the EMST of a circle misses one edge: open, not exact.
  EXPECT_EQ(rows[0][Column::algorithm], "nn-crust");
  EXPECT_EQ(rows[0][Column::exact], "1");
  EXPECT_LT(std::stod(rows[0][Column::rms]), 0.01);
  EXPECT_EQ(rows[0][Column::closed_components], "1");
  EXPECT_EQ(rows[1][Column::exact], "0");
  EXPECT_EQ(rows[1][Column::open_components], "1");
  // True topology: one closed curve, as the circle is; the EMST's path is not.
  EXPECT_EQ(rows[0][Column::true_topology], "1");
  EXPECT_EQ(rows[1][Column::true_topology], "0");
  for (const Result_row& row : rows)
    if (row[Column::exact] == "1") {
      EXPECT_EQ(row[Column::true_topology], "1") << "exact implies the true topology";
    }
  // results.json: the same rows, typed.
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(options.output / "results.json"));
  ASSERT_EQ(json.size(), rows.size());
  for (std::size_t j = 0; j < rows.size(); ++j) {
    EXPECT_EQ(json[j]["job"], j);
    EXPECT_EQ(json[j]["algorithm"], rows[j][Column::algorithm]);
    EXPECT_EQ(json[j]["exact"], rows[j][Column::exact] == "1");
    EXPECT_TRUE(json[j]["message"].is_null());
  }

  // Only a simplifier is measured each way; every row counts the points of its output.
  for (const Result_row& row : rows) {
    EXPECT_TRUE(row[Column::hausdorff_to_curve].empty() && row[Column::rms_from_curve].empty()) << row.job();
    EXPECT_EQ(row[Column::output_points], row[Column::n_points]) << row.job();
  }
  // The report learns from algorithms.csv which algorithms simplify.
  std::ifstream table(options.output / "algorithms.csv");
  const std::string text{std::istreambuf_iterator<char>(table), {}};
  EXPECT_EQ(text.rfind("algorithm,simplifies\n", 0), 0u);
  EXPECT_NE(text.find("\noptimal-transport,1\n"), std::string::npos);
  EXPECT_NE(text.find("\nnn-crust,0\n"), std::string::npos);

  // Without --resume an existing run is not overwritten; with it, nothing is left to do.
  EXPECT_THROW(run_suite(options), std::invalid_argument);
  options.resume = true;
  EXPECT_EQ(run_suite(options).resumed, 6u);

  // A run cut off after three rows, mid-line, resumes to the same table.
  const auto cut = dir.path() / "b";
  std::filesystem::create_directories(cut);
  std::vector<Result_row> first(rows.begin(), rows.begin() + 3);
  write_results_csv(cut / "results.csv", first);
  std::ofstream(cut / "results.csv", std::ios::app) << rows[3].csv().substr(0, 20);
  options.output = cut;
  const Run_summary resumed = run_suite(options);
  EXPECT_EQ(resumed.resumed, 3u);
  EXPECT_EQ(resumed.ok, 3u);
  EXPECT_EQ(without_runtimes(read_results_csv(cut / "results.csv")), without_runtimes(rows));

  // Shards 1/2 and 2/2, merged, are the whole run.
  options.resume = false;
  for (const std::size_t shard : {1, 2}) {
    options.output = dir.path() / ("shard" + std::to_string(shard));
    options.shard = shard, options.shards = 2;
    EXPECT_EQ(run_suite(options).jobs, 3u);
  }
  const std::vector<std::filesystem::path> shards{dir.path() / "shard1", dir.path() / "shard2"};
  EXPECT_EQ(merge_runs(shards, dir.path() / "merged", Pictures::some, false), 6u);
  EXPECT_EQ(without_runtimes(read_results_csv(dir.path() / "merged" / "results.csv")), without_runtimes(rows));
}

// Pictures::some: per algorithm and suite, the first 6 failures in job order and the first
// 2 jobs. The EMST is a tree, so it fails on every circle; NN-Crust is exact on each
// (epsilon 0.1 < 1/3). Shards merged keep the same pictures as one run.
// Optimal Transport simplifies: its rows hold its output's size and its distances each way,
// whose larger Hausdorff is the symmetric one when it keeps no isolated vertex.
TEST(Run, ASimplifierIsMeasuredEachWayAndByItsSize) {
  testing::TemporaryDirectory dir;
  const Run_options options{.suite = "smoke", .output = dir.path() / "ot", .algorithms = {"optimal-transport"},
                            .jobs = 2, .report = false, .progress = false};
  run_suite(options);
  const std::vector<Result_row> rows = read_results_csv(options.output / "results.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const Result_row& row : rows) {
    ASSERT_EQ(row[Column::status], "ok") << row[Column::message];
    const std::size_t kept = std::stoul(row[Column::output_points]);
    EXPECT_GT(kept, 0u);
    EXPECT_LE(kept, std::stoul(row[Column::n_points]));
    for (const Column column : {Column::hausdorff_to_curve, Column::rms_to_curve, Column::hausdorff_from_curve,
                                Column::rms_from_curve})
      EXPECT_TRUE(std::isfinite(std::stod(row[column]))) << row.job();
    EXPECT_LE(std::stod(row[Column::rms_to_curve]), std::stod(row[Column::hausdorff_to_curve]));
    EXPECT_LE(std::stod(row[Column::rms_from_curve]), std::stod(row[Column::hausdorff_from_curve]));
    if (row[Column::unconnected] == "0") {
      EXPECT_EQ(std::stod(row[Column::hausdorff]),
                std::max(std::stod(row[Column::hausdorff_to_curve]), std::stod(row[Column::hausdorff_from_curve])));
    }
  }
}

TEST(Run, SomePicturesAreTheFirstFailuresAndJobsPerAlgorithmAndSuite) {
  testing::TemporaryDirectory dir;
  std::vector<Suite_case> cases;
  for (int r = 1; r <= 10; ++r) cases.push_back({"t", "circle:r=" + std::to_string(r) + "|epsilon=0.1", ""});
  const std::vector<const algorithms::Algorithm*> chosen{algorithms::find_algorithm("emst"),
                                                         algorithms::find_algorithm("nn-crust")};
  Run_options options{.suite = "", .output = dir.path() / "one", .jobs = 2, .report = false, .progress = false};
  run_cases(cases, chosen, options);
  const std::vector<Result_row> rows = read_results_csv(options.output / "results.csv");
  ASSERT_EQ(rows.size(), 20u);
  for (const Result_row& row : rows) {
    const std::size_t c = row.job() / 2;
    const bool emst = row[Column::algorithm] == "emst";
    EXPECT_EQ(row[Column::exact], emst ? "0" : "1") << row[Column::input];
    EXPECT_EQ(!row[Column::picture].empty(), c < (emst ? failure_pictures : success_pictures)) << row.job();
  }
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& file : std::filesystem::directory_iterator(options.output / "pictures")) ++files;
  EXPECT_EQ(files, failure_pictures + success_pictures) << "the pictures beyond the cap are deleted";

  std::vector<std::filesystem::path> shards;
  for (const std::size_t shard : {1, 2, 3}) {
    options.output = dir.path() / ("shard" + std::to_string(shard));
    options.shard = shard, options.shards = 3;
    run_cases(cases, chosen, options);
    shards.push_back(options.output);
  }
  merge_runs(shards, dir.path() / "merged", Pictures::some, false);
  EXPECT_EQ(without_runtimes(read_results_csv(dir.path() / "merged" / "results.csv")), without_runtimes(rows));
}

// A shard makes the inputs of its cases only: the cases of one curve (consecutive cases
// of one source) stay in one shard, and the curves are dealt in turn. A run of fewer
// curves than shards deals its jobs, so that no shard is idle.
TEST(Run, ShardsKeepTheCasesOfACurveTogether) {
  testing::TemporaryDirectory dir;
  std::vector<Suite_case> cases;
  for (int r = 1; r <= 6; ++r)
    for (const char* epsilon : {"0.3", "0.5"})
      cases.push_back({"t", "circle:r=" + std::to_string(r) + "|epsilon=" + epsilon, std::string("epsilon=") + epsilon});
  const std::vector<const algorithms::Algorithm*> chosen{algorithms::find_algorithm("emst"),
                                                         algorithms::find_algorithm("nn-crust")};
  Run_options options{.suite = "", .output = {}, .jobs = 1, .pictures = Pictures::none, .report = false, .progress = false};
  std::map<std::string, std::set<std::size_t>> shards_of_curve;
  for (const std::size_t shard : {1, 2, 3}) {
    options.output = dir.path() / ("shard" + std::to_string(shard));
    options.shard = shard, options.shards = 3;
    EXPECT_EQ(run_cases(cases, chosen, options).jobs, 8u) << "2 curves x 2 levels x 2 algorithms";
    for (const Result_row& row : read_results_csv(options.output / "results.csv"))
      shards_of_curve[std::string(input_source(row[Column::input]))].insert(shard);
  }
  ASSERT_EQ(shards_of_curve.size(), 6u);
  for (const auto& [curve, in] : shards_of_curve) EXPECT_EQ(in.size(), 1u) << curve << " is made in one shard only";

  const std::vector<Suite_case> one_curve(cases.begin(), cases.begin() + 2);
  options.output = dir.path() / "few", options.shard = 3;
  EXPECT_EQ(run_cases(one_curve, chosen, options).jobs, 1u) << "4 jobs of one curve, dealt to 3 shards";
}

// The message of the std::invalid_argument that merging `shards` throws, or "".
std::string merge_error(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& output) {
  try {
    merge_runs(shards, output, Pictures::none, false);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

// A merge takes the shards of one run, each once and finished, and names what is wrong:
// the other run, the missing shards by number, the unfinished one. The merged directory is
// then a whole run of its own.
TEST(Run, MergeRefusesOtherRunsAndNamesMissingShards) {
  testing::TemporaryDirectory dir;
  Run_options options{.suite = "smoke", .output = {}, .algorithms = {"nn-crust", "emst"}, .jobs = 1,
                      .pictures = Pictures::none, .report = false, .progress = false};
  const auto shard_dir = [&](std::string name, std::size_t shard, std::size_t shards) {
    options.output = dir.path() / name;
    options.shard = shard, options.shards = shards;
    run_suite(options);
    return options.output;
  };
  std::vector<std::filesystem::path> shards;
  for (std::size_t k = 1; k <= 4; ++k) shards.push_back(shard_dir("s" + std::to_string(k), k, 4));
  const std::filesystem::path out = dir.path() / "merged";

  EXPECT_NE(merge_error({shards[0], shards[1], shards[3]}, out).find("missing shard 3 of 4"), std::string::npos);
  EXPECT_NE(merge_error({shards[1]}, out).find("missing shards 1, 3 and 4 of 4"), std::string::npos);
  EXPECT_NE(merge_error({shards[0], shards[0]}, out).find("shard 1 twice"), std::string::npos);
  const auto half = shard_dir("half", 1, 2);
  EXPECT_NE(merge_error({shards[1], half}, out).find("is of another run"), std::string::npos) << "other shard count";
  options.algorithms = {"nn-crust", "crust"};
  const auto other = shard_dir("other", 3, 4);
  EXPECT_NE(merge_error({shards[0], shards[1], other, shards[3]}, out).find("is of another run"), std::string::npos);
  options.algorithms = {"nn-crust", "emst"};
  // A task killed before its first row: its directory is there, its job is not.
  const auto cut = dir.path() / "cut";
  std::filesystem::copy(shards[2], cut, std::filesystem::copy_options::recursive);
  write_results_csv(cut / "results.csv", {});
  EXPECT_NE(merge_error({shards[0], shards[1], cut, shards[3]}, out).find("shard 3 has 0 of its 1 jobs"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing is written before the shards are checked";

  // Resuming a directory with another run's shard in it is refused too.
  options.output = shards[0], options.shard = 2, options.resume = true;
  EXPECT_THROW(run_suite(options), std::invalid_argument);

  EXPECT_EQ(merge_error(shards, out), "");
  EXPECT_EQ(read_results_csv(out / "results.csv").size(), 4u);
  options.output = out, options.shard = 1, options.shards = 1;
  EXPECT_EQ(run_suite(options).resumed, 4u) << "the merged directory is the whole run, resumable";
}

TEST(Run, RejectsUnknownSuitesAlgorithmsAndShards) {
  testing::TemporaryDirectory dir;
  EXPECT_THROW(run_suite({.suite = "no-such-suite", .output = dir.path()}), std::invalid_argument);
  EXPECT_THROW(run_suite({.suite = "smoke", .output = dir.path(), .algorithms = {"no-such"}}), std::invalid_argument);
  EXPECT_THROW(run_suite({.suite = "smoke", .output = dir.path(), .shard = 3, .shards = 2}), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench::bench
