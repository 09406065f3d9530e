// Reading and writing point files: every point-set format found in the public data sets
// curvebench uses, and one canonical format for writing.
//
// Formats read (the lexical rules, shared with edge lists, are in text_records.h: LF /
// CRLF / CR line endings, `#` comments, blank lines, space / tab / comma separators):
//
//  - plain: one point per line, `x y`, or `x y value` with the third column kept in
//    PointFile::values. Every line has the same number of columns. An optional first
//    line holding a single integer N announces the number of points, which must then
//    equal N.
//  - Triangle .node (and .gtn, the same format): a header `N 2 nattr nbound`
//    (nbound 0 or 1), then `index x y [nattr attributes] [marker]` per vertex; indices
//    start at 0 or 1 and go up by one; there must be exactly N vertices. Attributes and
//    markers are checked, not kept.
//
// Which format: a file named *.node or *.gtn (any case) is a Triangle file, whose first
// data line must be the header. Any other file is a Triangle file if its first data
// line is exactly four non-negative integers (a plain file never has four columns, so
// no valid plain file is misread), and a plain file otherwise. A file without data
// lines holds 0 points, whatever its format.
//
// Writing always uses plain `x y` with the shortest decimal that reads back to the
// same double, so write_points then read_point_file is bit-exact.
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string_view>
#include <vector>

#include "geometry/kernel.h"
#include "geometry/io/parse_error.h"

namespace curvebench::geometry {

// A point file as read: the points, any third column, and where each point stands.
struct PointFile {
  std::vector<Point> points;  // in file order, duplicates kept (PointSet merges them)
  std::vector<double> values;      // the third column; empty if the file has two
  std::vector<std::size_t> lines;  // 1-based source line of each point, for messages
};

// Throws ParseError ("FILE:LINE: what is wrong") on any malformed or non-finite input,
// and with line 0 if the file cannot be read. 0 points is valid.
PointFile read_point_file(const std::filesystem::path& path);

// The same from memory; `name` stands for the path (in messages and for the extension
// rule). Safe on arbitrary bytes: memory use is bounded by the size of `text`, whatever
// count a header claims.
PointFile parse_point_file(std::string_view text, std::string_view name);

// One "x y\n" line per point. Throws std::invalid_argument on a non-finite coordinate
// (it could not be read back), and the path version std::filesystem::filesystem_error
// if the file cannot be written.
void write_points(const std::filesystem::path& path, std::span<const Point> points);
// The same to a stream.
void write_points(std::ostream& out, std::span<const Point> points);

}  // namespace curvebench::geometry
