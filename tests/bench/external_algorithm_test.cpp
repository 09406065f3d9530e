// External algorithms (exec:COMMAND): declarations checked before any run, the program's
// output read strictly with a distinct error per defect, and runs that record each defect
// as its own status. The programs are one-line shell scripts, so each test states exactly
// what the program does.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/results_table.h"
#include "bench/runner/run.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::bench {
namespace {

using algorithms::Point;

// A program that writes `text` to the edge file, as a declaration.
std::string writing(const std::string& text) {
  return "exec:sh -c 'printf \"%b\" \"" + text + "\" > \"$1\"' sh {edges} {points}";
}

algorithms::Reconstruction run(const std::string& name, std::vector<Point> points) {
  return algorithms::reconstruct(*find_any_algorithm(name), points);
}

const std::vector<Point> triangle{{0, 0}, {1, 0}, {0, 1}};

TEST(ExternalAlgorithm, BadDeclarationsAreClearErrorsBeforeAnyRun) {
  EXPECT_THROW(find_any_algorithm("exec:cat {points} {edgs}"), std::invalid_argument);  // unknown placeholder
  EXPECT_THROW(find_any_algorithm("exec:cat {points}"), std::invalid_argument);         // no {edges}
  EXPECT_THROW(find_any_algorithm("exec:no-such-program-here {points} {edges}"), std::invalid_argument);
  EXPECT_THROW(find_any_algorithm("exec:/no/such/dir/prog {points} {edges}"), std::invalid_argument);
  EXPECT_EQ(find_any_algorithm("no-such-algorithm"), nullptr);
  EXPECT_EQ(find_any_algorithm("crust"), algorithms::find_algorithm("crust"));
  // One algorithm per declaration, kept: a run's jobs all point at the same one.
  const std::string name = writing("0 1\\n");
  EXPECT_EQ(find_any_algorithm(name), find_any_algorithm(name));
  EXPECT_EQ(find_any_algorithm(name)->name, name);
}

TEST(ExternalAlgorithm, ItsEdgesAreReadCanonical) {
  // Both orders of one edge, blank lines and trailing blanks: one edge each, i < j, sorted.
  const auto result = run(writing("2 0\\n\\n1 0  \\n0 1\\n"), triangle);
  EXPECT_EQ(result.edges, (std::vector<geometry::Edge>{{0, 1}, {0, 2}}));
  EXPECT_TRUE(result.points.empty());
  // The points the program reads are the ones given, to the last bit (the shortest decimal
  // that reads back to the same double, as every file curvebench writes).
  const std::vector<Point> awkward{{0.1, 1e-300}, {-3.0000000000000004, 1e300}};
  const auto echoed = run("exec:sh -c 'test \"$(cat \"$1\")\" = \"0.1 1e-300\n"
                          "-3.0000000000000004 1e+300\" && printf \"0 1\" > \"$2\"' sh {points} {edges}",
                          awkward);
  EXPECT_EQ(echoed.edges.size(), 1u);
}

TEST(ExternalAlgorithm, EachOutputDefectIsInvalidOutputNamingItsLine) {
  const auto message = [](const std::string& name) {
    try {
      run(name, triangle);
    } catch (const Invalid_output& error) {
      return std::string(error.what());
    }
    return std::string("no Invalid_output");
  };
  EXPECT_EQ(message(writing("0 1\\n0 3\\n")), "edges:2: index 3 out of range (3 points)");
  EXPECT_EQ(message(writing("1 1\\n")), "edges:1: a self-loop at 1");
  EXPECT_EQ(message(writing("0 1 2\\n")), "edges:1: expected 2 columns (i j), found 3: '0 1 2'");
  EXPECT_EQ(message(writing("zero one\\n")), "edges:1: 'zero' is not a non-negative integer (or too large)");
  EXPECT_EQ(message(writing("-1 2\\n")), "edges:1: '-1' is negative: expected a non-negative integer");
  EXPECT_EQ(message("exec:true {points} {edges}"), "the program wrote no edges file");
}

TEST(ExternalAlgorithm, ACrashAndAFailureAreToldApart) {
  EXPECT_THROW(run("exec:sh -c 'kill -SEGV $$' {points} {edges}", triangle), Program_crashed);
  try {
    run("exec:sh -c 'echo cannot read \"$1\" >&2; exit 3' sh {points} {edges}", triangle);
    FAIL() << "no error";
  } catch (const Invalid_output&) {
    FAIL() << "a failure, not an invalid output";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).substr(0, 30), "program exit status 3: cannot ");
  }
}

TEST(ExternalAlgorithm, MovedPointsComeFromPointsOut) {
  // A program that replaces the input by two points of its own and joins them.
  const auto result =
      run("exec:sh -c 'printf \"0.5 0.5\\n2 2\\n\" > \"$1\"; printf \"0 1\\n\" > \"$2\"' sh {points_out} {edges} {points}",
          triangle);
  ASSERT_EQ(result.points.size(), 2u);
  EXPECT_EQ(result.points[1], Point(2, 2));
  EXPECT_EQ(result.edges, (std::vector<geometry::Edge>{{0, 1}}));
  EXPECT_THROW(run("exec:sh -c 'printf \"nan 1\\n\" > \"$1\"; printf \"\" > \"$2\"' sh {points_out} {edges} {points}",
                   triangle),
               Invalid_output);
}

// In a run, each defect is a row with its own status and message, and the run goes on.
TEST(ExternalAlgorithm, RunRecordsInvalidOutputAndCrashesAsStatuses) {
  testing::TemporaryDirectory dir;
  Run_options options{.suite = "smoke",
                      .output = dir.path() / "run",
                      .algorithms = {writing("0 99999\\n"), "exec:sh -c 'kill -KILL $$' {points} {edges}", "crust"},
                      .jobs = 2,
                      .report = false,
                      .progress = false};
  const Run_summary summary = run_suite(options);
  EXPECT_EQ(summary.invalid_output, 2u);
  EXPECT_EQ(summary.crashed, 2u);
  EXPECT_EQ(summary.ok, 2u);
  const std::vector<Result_row> rows = read_results_csv(options.output / "results.csv");
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0][Column::status], "invalid-output");
  EXPECT_NE(rows[0][Column::message].find("out of range"), std::string::npos);
  EXPECT_EQ(rows[1][Column::status], "crashed");
  EXPECT_EQ(rows[1][Column::message], "program killed by signal 9 (Killed)");  // as its shell reports it
  EXPECT_EQ(rows[2][Column::status], "ok");
}

}  // namespace
}  // namespace curvebench::bench
