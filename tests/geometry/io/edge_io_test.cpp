#include "geometry/io/edge_io.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "tests/support/expect_parse_error.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::geometry {
namespace {

using testing::BadInput;
using testing::expect_parse_error;
using testing::TemporaryDirectory;

TEST(EdgeIo, ReadsEdgesWithCommentsAndAnyLineEnding) {
  const TemporaryDirectory dir;
  const auto path = dir.write("edges.txt", "# chain\r\n0 1\r\n\r1,2\n2\t3 # last\r");
  EXPECT_EQ(read_edges(path), (std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}}));
  EXPECT_EQ(parse_edge_file("# chain\r\n0 1\r\n\r1,2\n", "e").lines,
            (std::vector<std::size_t>{2, 4}));
}

TEST(EdgeIo, WritesOneEdgePerLine) {
  const TemporaryDirectory dir;
  const auto path = dir.path() / "edges.txt";
  write_edges(path, std::vector<Edge>{{0, 1}, {17, 4}});
  EXPECT_EQ(testing::read_bytes(path), "0 1\n17 4\n");
}

RC_GTEST_PROP(EdgeIo, WriteThenReadGivesTheSameEdges, (const std::vector<Edge>& edges)) {
  const TemporaryDirectory dir;
  const auto path = dir.path() / "edges.txt";
  write_edges(path, edges);
  RC_ASSERT(read_edges(path) == edges);
}

TEST(EdgeIo, MalformedLinesAreParseErrorsOnTheirLine) {
  const BadInput cases[] = {
      {"negative.txt", "0 1\n1 -2\n", 2, "'-2' is negative"},
      {"real.txt", "0 1\n1 2.0\n", 2, "'2.0'"},
      {"crlf.txt", "0 1\r\n\r\n1\r\n", 3, "'1'"},
      {"three.txt", "0 1 2\n", 1, "'0 1 2'"},
      {"letter.txt", "0 x\n", 1, "'x'"},
      {"huge.txt", "0 99999999999999999999999\n", 1, "'99999999999999999999999'"},
  };
  for (const BadInput& bad : cases) {
    SCOPED_TRACE(bad.file_name);
    expect_parse_error([&] { parse_edge_file(bad.text, bad.file_name); }, bad.file_name, bad.line,
                       bad.mention);
  }
}

TEST(GroundTruth, WriteThenReadGivesTheSameGroundTruth) {
  const TemporaryDirectory dir;
  const GroundTruth truth{.points = {Point(0, 0), Point(1, 0.1), Point(-0.0, 1e-300)},
                          .edges = {{0, 1}, {1, 2}, {2, 0}}};
  write_ground_truth(dir.path() / "p.txt", dir.path() / "e.txt", truth);
  const GroundTruth read = read_ground_truth(dir.path() / "p.txt", dir.path() / "e.txt");
  EXPECT_EQ(read.points, truth.points);
  EXPECT_EQ(read.edges, truth.edges);
}

TEST(GroundTruth, InvalidEdgesAreParseErrorsNamingTheEdgeFileLine) {
  const TemporaryDirectory dir;
  const auto points = dir.write("points.txt", "0 0\n1 0\n1 1\n");
  const BadInput cases[] = {
      {"self_loop.txt", "0 1\n# comment\n2 2\n", 3, "self-loop '2 2'"},
      {"out_of_range.txt", "0 1\n1 3\n", 2, "index 3 is out of range"},
      {"first_out_of_range.txt", "\n\n7 0\n", 3, "index 7 is out of range"},
  };
  for (const BadInput& bad : cases) {
    SCOPED_TRACE(bad.file_name);
    const auto edges = dir.write(bad.file_name, bad.text);
    expect_parse_error([&] { read_ground_truth(points, edges); }, edges.string(), bad.line,
                       bad.mention);
  }
}

TEST(GroundTruth, AMissingFileIsAParseErrorOnLineZero) {
  const TemporaryDirectory dir;
  const auto points = dir.write("points.txt", "0 0\n1 0\n");
  const auto missing = dir.path() / "missing.txt";
  expect_parse_error([&] { read_ground_truth(points, missing); }, missing.string(), 0,
                     "cannot open");
  expect_parse_error([&] { read_ground_truth(missing, points); }, missing.string(), 0,
                     "cannot open");
}

}  // namespace
}  // namespace curvebench::geometry
