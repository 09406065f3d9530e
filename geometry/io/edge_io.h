// Reading and writing edge lists and ground truths. A ground truth is a point file plus
// an edge-list file beside it: `i j` per line, the 0-based indices of two points of the
// point file. Edge lists follow the lexical rules of text_records.h (LF / CRLF / CR line
// endings, `#` comments, blank lines, space / tab / comma separators).
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string_view>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"
#include "geometry/io/parse_error.h"

namespace curvebench::geometry {

// An edge list as read, with where each edge stands in the file.
struct EdgeFile {
  std::vector<Edge> edges;  // in file order, as written (not canonical_edges)
  std::vector<std::size_t> lines;  // 1-based source line of each edge, for messages
};

// Throws ParseError on a line that is not two non-negative integers, and with line 0 if
// the file cannot be read. Indices are not checked against any point set here.
std::vector<Edge> read_edges(const std::filesystem::path& path);
// The same from memory, keeping the line of each edge; `name` stands for the path in
// messages.
EdgeFile parse_edge_file(std::string_view text, std::string_view name);

// One "i j\n" line per edge; the path version throws std::filesystem::filesystem_error
// if the file cannot be written.
void write_edges(const std::filesystem::path& path, std::span<const Edge> edges);
// The same to a stream.
void write_edges(std::ostream& out, std::span<const Edge> edges);

// A curve given as the edges of a polyline on points: a point file and an edge file.
struct GroundTruth {
  std::vector<Point> points;  // in the point file's order
  std::vector<Edge> edges;  // indices into `points`, in file order
};

// Reads both files and checks that every edge joins two distinct points of the point
// file; a violation is a ParseError naming the line of the edge file.
GroundTruth read_ground_truth(const std::filesystem::path& points,
                              const std::filesystem::path& edges);
// write_points to `points` and write_edges to `edges`. Throws
// std::invalid_argument for a non-finite coordinate (before either file is written) and
// std::filesystem::filesystem_error if a file cannot be written.
void write_ground_truth(const std::filesystem::path& points, const std::filesystem::path& edges,
                        const GroundTruth& truth);

}  // namespace curvebench::geometry
