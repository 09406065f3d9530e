// `curvebench hunt` against programs with one planted defect each (tests/bench/programs/):
// it must find the defect, shrink it to at most 4 points and write a replay; and on a
// correct built-in algorithm it must find nothing (every law holds for Crust).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "bench/runner/hunt.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::bench {
namespace {


std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The hunt for the defect planted in tests/bench/programs/NAME, stopped at its first
// finding (within a minute), written under `dir`.
Hunt_finding planted_finding(const std::string& name, const std::filesystem::path& dir) {
  const std::string program = "exec:/usr/bin/python3 " + std::string(CURVEBENCH_SOURCE_DIR) + "/tests/bench/programs/" +
                              name + " {points} {edges}";
  const Hunt_summary summary = hunt({.algorithm = program, .seconds = 60, .output = dir, .stop_after = 1});
  EXPECT_EQ(summary.findings.size(), 1u);
  return summary.findings.empty() ? Hunt_finding{} : summary.findings.front();
}

TEST(Hunt, FindsTheCrashOnCollinearInputAndShrinksIt) {
  testing::TemporaryDirectory dir;
  const Hunt_finding finding = planted_finding("collinear_crash.py", dir.path());
  EXPECT_EQ(finding.kind, "crash");
  EXPECT_NE(finding.message.find("signal 11"), std::string::npos) << finding.message;
  ASSERT_GE(finding.points.size(), 3u);
  EXPECT_LE(finding.points.size(), 4u);
  for (std::size_t i = 2; i < finding.points.size(); ++i)  // the planted defect's trigger, exactly
    EXPECT_TRUE(CGAL::collinear(finding.points[0], finding.points[1], finding.points[i]));
  // The replay names the algorithm and reads the shrunk points, written to the last bit.
  const std::string replay = text_of(finding.directory / "replay.sh");
  EXPECT_NE(replay.find("collinear_crash.py {points} {edges}' -i points.xy"), std::string::npos) << replay;
  std::istringstream written(text_of(finding.directory / "points.xy"));
  for (const geometry::Point& p : finding.points) {
    double x = 0, y = 0;
    written >> x >> y;
    EXPECT_EQ(geometry::Point(x, y), p);
  }
}

TEST(Hunt, FindsTheOrderDependenceAndShrinksIt) {
  testing::TemporaryDirectory dir;
  const Hunt_finding finding = planted_finding("order_dependent.py", dir.path());
  EXPECT_EQ(finding.kind, "not-permutation-invariant");
  EXPECT_LE(finding.points.size(), 4u);
  EXPECT_TRUE(std::filesystem::exists(finding.directory / "variant.xy"));  // the permuted input, to replay
  EXPECT_NE(text_of(finding.directory / "replay.sh").find("variant.xy"), std::string::npos);
}

TEST(Hunt, FindsNothingWrongWithCrust) {
  const Hunt_summary summary = hunt({.algorithm = "crust", .seconds = 3});
  EXPECT_GT(summary.cases, 20u);
  for (const Hunt_finding& f : summary.findings) ADD_FAILURE() << f.kind << ": " << f.message;
  EXPECT_THROW(hunt({.algorithm = "no-such-algorithm", .seconds = 1}), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench::bench
