// Files of named external algorithms (algorithm_file.h): every key read and checked, each
// bad declaration a clear error before anything runs, and what a declaration says (formats,
// parameters, timeout, claimed condition) honoured by the runs, `certify` and `hunt`. The
// programs are one-line shell scripts, or this build's curvebench running NN-Crust (whose
// theorem is the oracle) with one defect planted on top.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "bench/runner/algorithm_file.h"
#include "bench/runner/certification.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/hunt.h"
#include "bench/runner/results_table.h"
#include "bench/runner/run.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::bench {
namespace {

using algorithms::Point;

const std::vector<Point> triangle{{0, 0}, {1, 0}, {0, 1}};

// The message of the std::invalid_argument that parsing `text` throws; "" if none.
std::string parse_error(const std::string& text) {
  try {
    parse_algorithm_file(text, "mine.json");
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

// Declares the file's algorithms from `text`, written under `dir`.
std::vector<const algorithms::Algorithm*> load(const testing::TemporaryDirectory& dir, const std::string& text) {
  const std::filesystem::path file = dir.path() / "algorithms.json";
  std::ofstream(file) << text;
  return load_algorithm_file(file);
}

TEST(AlgorithmFile, ReadsEveryKey) {
  const auto declared = parse_algorithm_file(R"({"algorithms": [
      {"name": "mine", "title": "Mine", "command": "prog {points} {edges} {k}", "input_format": "csv", "index_base": 1,
       "parameters": [{"name": "k", "type": "integer", "default": 2, "min": 1, "max": 8, "meaning": "neighbours"}],
       "timeout": 2.5,
       "condition": {"statement": "eps < 1/2", "epsilon_below": 0.5, "uniformity_below": 1.6, "rho_below": 0.9}},
      {"name": "plain", "command": "prog {points} {edges}"}]})",
                                             "mine.json");
  ASSERT_EQ(declared.size(), 2u);
  const External_declaration& d = declared[0];
  EXPECT_EQ(d.name, "mine");
  EXPECT_EQ(d.title, "Mine");
  EXPECT_EQ(d.input_format, External_declaration::Point_format::csv);
  EXPECT_EQ(d.index_base, 1);
  ASSERT_EQ(d.parameters.size(), 1u);
  EXPECT_TRUE(d.parameters[0].integer);
  EXPECT_EQ(d.parameters[0].default_value, 2);
  EXPECT_EQ(d.parameters[0].maximum, 8);
  EXPECT_EQ(d.timeout_seconds, 2.5);
  EXPECT_EQ(d.condition, "eps < 1/2");
  EXPECT_EQ(d.epsilon_below, 0.5);
  EXPECT_EQ(d.uniformity_below, 1.6);
  EXPECT_EQ(d.rho_below, 0.9);
  // What is not said takes the plain program's defaults.
  const External_declaration& plain = declared[1];
  EXPECT_EQ(plain.input_format, External_declaration::Point_format::xy);
  EXPECT_EQ(plain.index_base, 0);
  EXPECT_FALSE(plain.timeout_seconds);
  EXPECT_FALSE(plain.epsilon_below);
}

TEST(AlgorithmFile, EachBadDeclarationNamesTheFileAndTheCulprit) {
  const std::pair<const char*, const char*> cases[] = {
      {"{\"algorithms\": [", "mine.json: not JSON"},
      {"[]", "mine.json: is not a JSON object"},
      {"{}", "mine.json: needs \"algorithms\", a list"},
      {R"({"algorithms": [], "extra": 1})", "mine.json: unknown key 'extra'"},
      {R"({"algorithms": [{"name": "x", "comand": "p {points} {edges}"}]})", "algorithm 1: unknown key 'comand'"},
      {R"({"algorithms": [{"command": "p {points} {edges}"}]})", "algorithm 1: needs \"name\""},
      {R"({"algorithms": [{"name": "x"}]})", "algorithm 'x': needs \"command\""},
      {R"({"algorithms": [{"name": 3, "command": "p"}]})", "\"name\" must be a string"},
      {R"({"algorithms": [{"name": "x", "command": "p", "index_base": 2}]})", "\"index_base\" is 0 or 1"},
      {R"({"algorithms": [{"name": "x", "command": "p", "input_format": "tsv"}]})", "\"input_format\" is xy or csv"},
      {R"({"algorithms": [{"name": "x", "command": "p", "timeout": "60"}]})", "\"timeout\" must be a number"},
      // Every algorithm gives the same output for the same input: a file that says otherwise,
      // or says so, is told why the key went.
      {R"({"algorithms": [{"name": "x", "command": "p", "repeatable": false}]})",
       "algorithm 'x': \"repeatable\" is no longer a key: every algorithm must give the same output for the same input"},
      {R"({"algorithms": [{"name": "x", "command": "p", "repeatable": true}]})", "\"repeatable\" is no longer a key"},
      {R"({"algorithms": [{"name": "x", "command": "p", "parameters": [{"name": "k", "default": 1}]}]})",
       "parameter 1: a parameter needs \"default\", \"min\" and \"max\""},
      {R"({"algorithms": [{"name": "x", "command": "p", "parameters": [{"name": "k", "type": "int", "default": 1, "min": 0, "max": 2}]}]})",
       "\"type\" is real or integer"},
      {R"({"algorithms": [{"name": "x", "command": "p", "condition": {"epsilon": 0.3}}]})",
       "algorithm 'x': condition: unknown key 'epsilon'"},
  };
  for (const auto& [text, message] : cases) {
    const std::string error = parse_error(text);
    EXPECT_NE(error.find(message), std::string::npos) << text << "\n gave: " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;  // one line
  }
}

TEST(AlgorithmFile, BadProgramsAndNamesAreErrorsBeforeAnyRun) {
  testing::TemporaryDirectory dir;
  const auto error_of = [&](const std::string& text) {
    try {
      load(dir, text);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of(R"({"algorithms": [{"name": "a1", "command": "no-such-program-here {points} {edges}"}]})")
                .find("algorithm 'a1': exec: no program 'no-such-program-here'"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"algorithms": [{"name": "a2", "command": "cat {points} {edges} {k}"}]})").find("unknown placeholder {k}"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"algorithms": [{"name": "crust", "command": "cat {points} {edges}"}]})")
                .find("'crust' is a built-in algorithm's name"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"algorithms": [{"name": "a3", "command": "cat {points} {edges}", "parameters":
                [{"name": "k", "default": 9, "min": 0, "max": 2}]}]})")
                .find("parameter k's default is not in [minimum, maximum]"),
            std::string::npos);
  load(dir, R"({"algorithms": [{"name": "twice", "command": "cat {points} {edges}"}]})");
  EXPECT_NE(error_of(R"({"algorithms": [{"name": "twice", "command": "cat {points} {edges}"}]})").find("two external algorithms are named 'twice'"),
            std::string::npos);
  try {
    load_algorithm_file(dir.path() / "missing.json");
    ADD_FAILURE() << "a missing file must be an error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("missing.json: cannot read the file"), std::string::npos);
  }
}

// The program's view of a declaration: the input format, the parameters in its command,
// its numbering, and {dir}.
TEST(AlgorithmFile, FormatsParametersNumberingAndDirReachTheProgram) {
  testing::TemporaryDirectory dir;
  std::ofstream(dir.path() / "edge.sh") << "printf '%s %s\\n' \"$2\" \"$3\" > \"$1\"\n";
  const auto declared = load(dir, R"({"algorithms": [
      {"name": "csv-reader", "input_format": "csv",
       "command": "sh -c 'test \"$(cat \"$1\")\" = \"x,y\n0,0\n1,0\n0,1\" && printf \"0 2\" > \"$2\"' sh {points} {edges}"},
      {"name": "one-based", "index_base": 1, "command": "sh {dir}/edge.sh {edges} {i} {j} {points}",
       "parameters": [{"name": "i", "type": "integer", "default": 1, "min": 0, "max": 9},
                      {"name": "j", "type": "integer", "default": 3, "min": 0, "max": 9}]}]})");
  ASSERT_EQ(declared.size(), 2u);
  EXPECT_EQ(find_any_algorithm("csv-reader"), declared[0]);
  EXPECT_EQ(algorithms::reconstruct(*declared[0], triangle).edges, (std::vector<geometry::Edge>{{0, 2}}));
  // Points 1 and 3, numbered from 1, are the first and the last.
  EXPECT_EQ(algorithms::reconstruct(*declared[1], triangle).edges, (std::vector<geometry::Edge>{{0, 2}}));
  EXPECT_EQ(algorithms::reconstruct(*declared[1], triangle, {{"i", 2}}).edges, (std::vector<geometry::Edge>{{1, 2}}));
  // 0 is no point when numbering starts at 1; 4 is past the last.
  EXPECT_THROW(algorithms::reconstruct(*declared[1], triangle, {{"i", 0}}), Invalid_output);
  EXPECT_THROW(algorithms::reconstruct(*declared[1], triangle, {{"j", 4}}), Invalid_output);
  EXPECT_THROW(algorithms::reconstruct(*declared[1], triangle, {{"j", 10}}), std::invalid_argument);  // out of its range
  EXPECT_EQ(external_declaration(*declared[1])->file, std::filesystem::absolute(dir.path() / "algorithms.json"));
  EXPECT_EQ(external_declaration(*algorithms::find_algorithm("crust")), nullptr);
}

TEST(AlgorithmFile, ATimeoutStopsTheProgramAndARunRecordsIt) {
  testing::TemporaryDirectory dir;
  const auto declared = load(dir, R"({"algorithms": [
      {"name": "sleeper", "timeout": 0.3, "command": "sh -c 'sleep 30' sh {points} {edges}"},
      {"name": "slow-start", "command": "sh -c 'sleep 0.2; printf \"0 1\" > \"$1\"' sh {edges} {points}"}]})");
  EXPECT_THROW(algorithms::reconstruct(*declared[0], triangle), Program_timed_out);
  // Start-up is the wall time on no points: at least the program's own sleep.
  EXPECT_GE(startup_milliseconds(*declared[1]), 200);
  EXPECT_EQ(startup_milliseconds(*algorithms::find_algorithm("crust")), 0);
  Run_options options{.suite = "smoke", .output = dir.path() / "run", .algorithms = {"sleeper", "slow-start", "crust"},
                      .jobs = 2, .report = false, .progress = false};
  const Run_summary summary = run_suite(options);
  EXPECT_EQ(summary.timed_out, 2u);
  const std::vector<Result_row> rows = read_results_csv(options.output / "results.csv");
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0][Column::status], "timeout");
  EXPECT_NE(rows[0][Column::message].find("timeout of 0.3 s"), std::string::npos) << rows[0][Column::message];
  EXPECT_GE(std::stod(rows[1][Column::startup_ms]), 200);
  EXPECT_GE(std::stod(rows[1][Column::runtime_ms]), 200);  // start-up is part of the runtime
  EXPECT_EQ(rows[2][Column::startup_ms], "");              // built in: no start-up
}

// The built-in NN-Crust as a program (this build's curvebench, called as an external
// one), declared with NN-Crust's theorem, and the same with a defect planted: it drops its
// first edge above 30 points. `certify` passes the first on every case and catches the
// second; `hunt` finds the second's broken claim, with the measured epsilon, shrunk to a
// sampling of few points.
std::string nn_crust_file(bool planted, const std::string& name) {
  const std::string reconstruct = std::string(CURVEBENCH_BINARY) + " reconstruct -a nn-crust -q -i";
  const std::string command = planted ? "sh -c '" + reconstruct + " \\\"$0\\\" -o \\\"$1\\\" && "
                                        "if [ $(wc -l < \\\"$0\\\") -gt 30 ]; then sed -i 1d \\\"$1\\\"; fi' {points} {edges}"
                                      : reconstruct + " {points} -o {edges}";
  return R"({"algorithms": [{"name": ")" + name +
         R"(", "command": ")" + command + R"(", "condition": {"epsilon_below": 0.3333333333333333}}]})";
}

TEST(AlgorithmFile, CertifyChecksTheClaimedCondition) {
  testing::TemporaryDirectory dir;
  const algorithms::Algorithm& faithful = *load(dir, nn_crust_file(false, "wrapped-nn-crust")).front();
  Certify_options options;
  options.count = 12, options.level = 0.15;
  options.run.output = dir.path() / "faithful", options.run.jobs = 2, options.run.progress = false;
  const Certify_summary passed = certify_algorithm(faithful, options);
  EXPECT_EQ(passed.cases, 12u);
  EXPECT_EQ(passed.passed + passed.inconclusive + passed.hypothesis_violations, 12u);
  EXPECT_EQ(passed.failures, 0u);
  EXPECT_GT(passed.passed, 0u);

  std::filesystem::create_directories(dir.path() / "planted");
  const std::filesystem::path file = dir.path() / "planted" / "algorithms.json";
  std::ofstream(file) << nn_crust_file(true, "planted-nn-crust");
  const algorithms::Algorithm& planted = *load_algorithm_file(file).front();
  options.run.output = dir.path() / "planted-run";
  const Certify_summary caught = certify_algorithm(planted, options);
  EXPECT_GT(caught.failures, 0u);
  ASSERT_FALSE(caught.counterexamples.empty());
  EXPECT_GT(caught.counterexamples.front().points, 30u);  // the planted trigger
  // The replay declares the algorithm again from its file.
  std::ifstream replay(caught.counterexamples.front().directory / "replay.sh");
  const std::string text{std::istreambuf_iterator<char>(replay), std::istreambuf_iterator<char>()};
  EXPECT_NE(text.find("--algorithm-file '" + std::filesystem::absolute(file).string() + "'"), std::string::npos) << text;
}

TEST(AlgorithmFile, HuntFindsABrokenClaimWithItsMeasuredEpsilon) {
  testing::TemporaryDirectory dir;
  std::filesystem::create_directories(dir.path() / "planted");
  std::ofstream(dir.path() / "planted" / "algorithms.json") << nn_crust_file(true, "hunted-nn-crust");
  load_algorithm_file(dir.path() / "planted" / "algorithms.json");
  const Hunt_summary summary =
      hunt({.algorithm = "hunted-nn-crust", .seconds = 60, .output = dir.path() / "hunt", .stop_after = 1});
  ASSERT_EQ(summary.findings.size(), 1u);
  const Hunt_finding& finding = summary.findings.front();
  EXPECT_EQ(finding.kind, "not-exact-under-condition");
  ASSERT_TRUE(finding.epsilon);
  EXPECT_LT(*finding.epsilon, 1.0 / 3);
  EXPECT_GT(finding.points.size(), 30u);
  EXPECT_NE(finding.message.find("1 missing"), std::string::npos) << finding.message;
  EXPECT_TRUE(finding.curve.starts_with("fourier:seed=")) << finding.curve;
  EXPECT_TRUE(std::filesystem::exists(finding.directory / "truth.edges"));
}

}  // namespace
}  // namespace curvebench::bench
