#include "geometry/io/point_io.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/expect_parse_error.h"
#include "tests/support/finite_double.h"
#include "tests/support/temporary_directory.h"

namespace curvebench::geometry {
namespace {

using testing::BadInput;
using testing::expect_parse_error;
using testing::finite_double;
using testing::TemporaryDirectory;

using Coordinates = std::vector<std::pair<double, double>>;
using Lines = std::vector<std::size_t>;

Coordinates coordinates(const PointFile& file) {
  Coordinates out;
  for (const Point& p : file.points) out.emplace_back(p.x(), p.y());
  return out;
}

// Each file, written to disk and read, is a ParseError naming its line and token.
void expect_each_read_fails(std::span<const BadInput> cases) {
  const TemporaryDirectory dir;
  for (const BadInput& bad : cases) {
    SCOPED_TRACE(bad.file_name);
    const auto path = dir.write(bad.file_name, bad.text);
    expect_parse_error([&] { read_point_file(path); }, path.string(), bad.line, bad.mention);
  }
}

TEST(PointIo, ReadsPlainPointsWithCommentsBlankLinesTabsAndCommas) {
  const PointFile file = parse_point_file(
      "# a comment line\n"
      "1 2\n"
      "\n"
      "  3.5\t-4   # trailing comment\n"
      "5,6\n"
      "7 , 8e-1\n"
      "+9 .5\n",
      "points.txt");
  EXPECT_EQ(coordinates(file), (Coordinates{{1, 2}, {3.5, -4}, {5, 6}, {7, 0.8}, {9, 0.5}}));
  EXPECT_EQ(file.lines, (Lines{2, 4, 5, 6, 7}));
  EXPECT_TRUE(file.values.empty());
}

TEST(PointIo, KeepsTheThirdColumnAsValues) {
  const PointFile file = parse_point_file("1 2 0.5\n3 4 1.0 \n", "points.xym");
  EXPECT_EQ(coordinates(file), (Coordinates{{1, 2}, {3, 4}}));
  EXPECT_EQ(file.values, (std::vector<double>{0.5, 1.0}));
}

TEST(PointIo, CountsLinesAlikeForLfCrlfAndCrEndings) {
  for (const std::string ending : {"\n", "\r\n", "\r"}) {
    SCOPED_TRACE("ending of " + std::to_string(ending.size()) + " byte(s), first " +
                 std::to_string(ending[0]));
    const std::string text = "1 2" + ending + "#" + ending + ending + "3 4" + ending + "5 6";
    const PointFile file = parse_point_file(text, "points.txt");
    EXPECT_EQ(coordinates(file), (Coordinates{{1, 2}, {3, 4}, {5, 6}}));
    EXPECT_EQ(file.lines, (Lines{1, 4, 5}));
  }
  // Mixed, as in some of the Crawl files: "\n\r" is two line ends, "\r\n" one.
  EXPECT_EQ(parse_point_file("1 2\n\r3 4\r\n5 6", "mixed.txt").lines, (Lines{1, 3, 4}));
}

TEST(PointIo, AcceptsALeadingCountLine) {
  const PointFile file = parse_point_file("# n\n3\n1 2\n3 4\n5 6\n", "counted.txt");
  EXPECT_EQ(coordinates(file), (Coordinates{{1, 2}, {3, 4}, {5, 6}}));
  EXPECT_EQ(file.lines, (Lines{3, 4, 5}));
  EXPECT_TRUE(parse_point_file("0\n", "none.txt").points.empty());
}

// Files as spreadsheets, editors and pandas save them: a UTF-8 byte-order mark, a header
// line of column names (quoted or not, any case), pandas' unnamed index column. Each must
// read as the plain file with the same numbers.
TEST(PointIo, ReadsByteOrderMarksAndCsvHeadersAsThePlainFile) {
  const PointFile plain = parse_point_file("0.5 1\n-2 3e-2\n4 5\n", "plain.txt");
  const std::string variants[] = {
      "\xEF\xBB\xBF" "0.5 1\n-2 3e-2\n4 5\n",
      "x,y\n0.5,1\n-2,3e-2\n4,5\n",
      "\xEF\xBB\xBF" "x,y\r\n0.5,1\r\n-2,3e-2\r\n4,5\r\n",
      "\"x\",\"y\"\n0.5,1\n-2,3e-2\n4,5\n",
      "X Y\n0.5 1\n-2 3e-2\n4 5\n",
      ",x,y\n0,0.5,1\n1,-2,3e-2\n2,4,5\n",      // pandas' DataFrame.to_csv with its index
      "y,x\n1,0.5\n3e-2,-2\n5,4\n",            // named columns in any order
      "lon,lat\n0.5,1\n-2,3e-2\n4,5\n",        // other names: x y by position
      "# exported\n\"x (m)\",\"y, \"\"north\"\" #1\"\n0.5,1\n-2,3e-2\n4,5\n",
  };
  for (const std::string& text : variants) {
    SCOPED_TRACE(text);
    const PointFile file = parse_point_file(text, "variant.csv");
    EXPECT_EQ(coordinates(file), coordinates(plain));
    EXPECT_TRUE(file.values.empty());
  }
  const PointFile valued = parse_point_file(",w,X,y\n0,7,0.5,1\n1,8,-2,3e-2\n2,9,4,5\n", "valued.csv");
  EXPECT_EQ(coordinates(valued), coordinates(plain));
  EXPECT_EQ(valued.values, (std::vector<double>{7, 8, 9}));
  EXPECT_EQ(valued.lines, (Lines{2, 3, 4}));
  EXPECT_TRUE(parse_point_file("x,y\n", "header_only.csv").points.empty());
}

// A header is the first data line only, and its columns bind every line after it.
TEST(PointIo, MalformedHeadersAndHeaderLikeLinesAreErrorsNamingTheirLine) {
  const BadInput cases[] = {
      {"middle.csv", "x,y\n1,2\nx,y\n3,4\n", 3, "'x'"},
      {"middle_plain.txt", "1 2\nx y\n", 2, "'x'"},
      {"wider.csv", "x,y\n1,2\n3,4,5\n", 3, "'3,4,5'"},
      {"narrower.csv", ",x,y\n0,1,2\n1,2\n", 3, "header on line 1"},
      {"too_many_names.csv", "x,y,a,b\n1,2,3,4\n", 1, "'x,y,a,b'"},
      {"one_name.csv", "x\n1\n", 1, "'x'"},
      {"unclosed_quote.csv", "\"x,y\n1,2\n", 1, "closing"},
      {"after_quote.csv", "\"x\"z,y\n1,2\n", 1, "'\"x\"'"},
      {"empty_data_field.csv", "x,y\n1,\n", 2, "','"},
      {"empty_first_field.txt", ",1,2\n", 1, "','"},
      {"quoted_number.csv", "x,y\n\"1\",2\n", 2, "'\"1\"'"},
      {"skipped_column.csv", ",x,y\nzero,1,2\n", 2, "'zero'"},
  };
  expect_each_read_fails(cases);
}

// Whatever the points, a CSV with a header (random case and quoting, maybe a byte-order
// mark and an index column) reads back the bits written, as the plain file does.
RC_GTEST_PROP(PointIo, CsvWithAHeaderReadsBackBitExact, ()) {
  const auto points = *rc::gen::container<std::vector<Point>>(rc::gen::construct<Point>(finite_double(), finite_double()));
  const bool bom = *rc::gen::arbitrary<bool>(), index = *rc::gen::arbitrary<bool>();
  const std::string x = *rc::gen::element<std::string>("x", "X", "\"x\""), y = *rc::gen::element<std::string>("y", "Y", "\"Y\"");
  std::ostringstream plain;
  write_points(plain, points);
  std::string csv = std::string(bom ? "\xEF\xBB\xBF" : "") + (index ? "," : "") + x + "," + y + "\n";
  std::istringstream lines(plain.str());
  std::size_t row = 0;
  for (std::string line; std::getline(lines, line); ++row) {
    line[line.find(' ')] = ',';
    csv += (index ? std::to_string(row) + "," : "") + line + "\n";
  }
  const PointFile file = parse_point_file(csv, "points.csv");
  RC_ASSERT(file.points.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    RC_ASSERT(std::bit_cast<std::uint64_t>(file.points[i].x()) == std::bit_cast<std::uint64_t>(points[i].x()));
    RC_ASSERT(std::bit_cast<std::uint64_t>(file.points[i].y()) == std::bit_cast<std::uint64_t>(points[i].y()));
  }
}

TEST(PointIo, EmptyFilesHaveNoPoints) {
  for (const char* text : {"", "\n\r\n", "# nothing here\n  \t \n"}) {
    EXPECT_TRUE(parse_point_file(text, "empty.txt").points.empty());
  }
}

TEST(PointIo, ReadsTriangleNodeFilesWithAttributesAndMarkers) {
  const PointFile file = parse_point_file(
      "# Triangle\n"
      "3 2 1 1\n"
      "  1\t10 20 0.5 1\n"
      "  2\t11 21 0.5 0\n"
      "  3\t12 22 0.5 -1\n",
      "mesh.node");
  EXPECT_EQ(coordinates(file), (Coordinates{{10, 20}, {11, 21}, {12, 22}}));
  EXPECT_EQ(file.lines, (Lines{3, 4, 5}));
  EXPECT_TRUE(file.values.empty());
}

TEST(PointIo, RecognisesATriangleHeaderWhateverTheExtension) {
  const PointFile file = parse_point_file("2 2 0 0\n0 1 2\n1 3 4\n", "mesh.txt");
  EXPECT_EQ(coordinates(file), (Coordinates{{1, 2}, {3, 4}}));
}

TEST(PointIo, UnreadableFilesAreParseErrorsOnLineZero) {
  const TemporaryDirectory dir;
  expect_parse_error([&] { read_point_file(dir.path() / "missing.txt"); },
                     (dir.path() / "missing.txt").string(), 0, "No such file");
  expect_parse_error([&] { read_point_file(dir.path()); }, dir.path().string(), 0,
                     "is a directory");
}

TEST(PointIo, MalformedFilesAreParseErrorsNamingFileLineAndToken) {
  const BadInput cases[] = {
      {"nan.txt", "1 2\nnan 3\n", 2, "'nan'"},
      {"inf.txt", "1 2\n\n3 -inf\n", 3, "'-inf'"},
      {"huge.txt", "1 2\n1e999 3\n", 2, "'1e999'"},
      {"tiny.txt", "1e-400 2\n", 1, "'1e-400'"},
      {"letter.txt", "1 2\n3 x\n", 2, "'x'"},
      {"suffix.txt", "1 2\n3 4.5.6\n", 2, "'4.5.6'"},
      {"missing.txt", "1 2\n3 4\n5\n", 3, "'5'"},
      {"more.txt", "1 2\n3 4 5\n", 2, "'3 4 5'"},
      {"fewer.txt", "1 2 3\n3 4\n", 2, "'3 4'"},
      {"one_column.txt", "1.5\n", 1, "'1.5'"},
      {"four_columns.txt", "1 2 3 4.5\n", 1, "'1 2 3 4.5'"},
      {"stray_comma.txt", "1,,2\n", 1, "','"},
      {"trailing_comma.txt", "1 2\n3,4,\n", 2, "','"},
      {"count_too_big.txt", "# header\n3\n1 2\n3 4\n", 2, "3"},
      {"count_too_small.txt", "1\n1 2\n3 4\n", 1, "1"},
      {"count_overflows.txt", "99999999999999999999999\n1 2\n", 1, "'99999999999999999999999'"},
      {"crlf.txt", "1 2\r\n3 4\r\nx 5\r\n", 3, "'x'"},
      {"cr.txt", "1 2\r3 4\rx 5", 3, "'x'"},
      {"control.txt", "1 2\n3 \x01\n", 2, "'\\x01'"},
      {"header.node", "1 2\n", 1, "'1 2'"},
      {"dimension.node", "2 3 0 0\n", 1, "'3'"},
      {"markers.node", "2 2 0 2\n", 1, "'2'"},
      {"first_index.node", "2 2 0 0\n2 1 1\n3 2 2\n", 2, "'2'"},
      {"index_gap.node", "3 2 0 0\n0 1 1\n1 2 2\n3 3 3\n", 4, "'3'"},
      {"too_many.node", "1 2 0 0\n0 1 1\n1 2 2\n", 3, "1"},
      {"too_few.node", "\n3 2 0 0\n0 1 1\n", 2, "3"},
      {"no_marker.node", "1 2 0 1\n0 1 1\n", 2, "'0 1 1'"},
      {"bad_marker.node", "1 2 0 1\n0 1 1 0.5\n", 2, "'0.5'"},
      {"bogus.node", "18446744073709551615 2 18446744073709551615 1\n0 1 2\n", 2, "'0 1 2'"},
  };
  expect_each_read_fails(cases);
}

RC_GTEST_PROP(PointIo, WriteThenReadIsBitExact, ()) {
  const auto points = *rc::gen::container<std::vector<Point>>(
      rc::gen::construct<Point>(finite_double(), finite_double()));
  const TemporaryDirectory dir;
  const auto path = dir.path() / "points.txt";
  write_points(path, points);
  const PointFile file = read_point_file(path);
  RC_ASSERT(file.points.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    RC_ASSERT(std::bit_cast<std::uint64_t>(file.points[i].x()) ==
              std::bit_cast<std::uint64_t>(points[i].x()));
    RC_ASSERT(std::bit_cast<std::uint64_t>(file.points[i].y()) ==
              std::bit_cast<std::uint64_t>(points[i].y()));
  }
}

TEST(PointIo, WritingANonFinitePointThrows) {
  std::ostringstream out;
  const std::vector<Point> points{Point(0, std::numeric_limits<double>::infinity())};
  EXPECT_THROW(write_points(out, points), std::invalid_argument);
}

// Parsing arbitrary bytes either succeeds with finite points on increasing lines or
// throws ParseError. The second generator draws from the bytes the grammar cares about,
// to reach deep into it rather than fail on the first byte.
void check_parse_is_safe(const std::string& text, const std::string& name) {
  try {
    const PointFile file = parse_point_file(text, name);
    RC_ASSERT(file.lines.size() == file.points.size());
    RC_ASSERT(file.values.empty() || file.values.size() == file.points.size());
    for (std::size_t i = 0; i < file.points.size(); ++i) {
      RC_ASSERT(std::isfinite(file.points[i].x()) && std::isfinite(file.points[i].y()));
      if (i > 0) RC_ASSERT(file.lines[i - 1] < file.lines[i]);  // not ||: RC_ASSERT evaluates both
    }
  } catch (const ParseError& error) {
    RC_ASSERT(std::string(error.what()).starts_with(name + ":"));
  }
}

RC_GTEST_PROP(PointIo, ParsingArbitraryBytesNeverCrashes, (const std::string& text)) {
  check_parse_is_safe(text, "arbitrary.txt");
}

RC_GTEST_PROP(PointIo, ParsingTokenSoupNeverCrashes, ()) {
  const auto text = *rc::gen::container<std::string>(
      rc::gen::elementOf(std::string("0123456789 .,-+eEinfa#\t\r\n")));
  const auto name = *rc::gen::element<std::string>("soup.txt", "soup.node");
  check_parse_is_safe(text, name);
}

}  // namespace
}  // namespace curvebench::geometry
