#include "geometry/io/edge_io.h"

#include <algorithm>
#include <string>
#include <utility>

#include "geometry/io/point_io.h"
#include "geometry/io/text_file.h"
#include "geometry/io/text_records.h"

namespace curvebench::geometry {

EdgeFile parse_edge_file(std::string_view text, std::string_view name) {
  RecordReader reader(text, std::string(name));
  Record record;
  EdgeFile file;
  while (reader.next(record)) {
    if (record.fields.size() != 2) {
      reader.fail(record.line, "expected 2 columns (i j), found " +
                                   std::to_string(record.fields.size()) + ": " +
                                   quoted(record.text));
    }
    const std::size_t i = reader.to_index(record.fields[0], record.line);  // before j: errors
    file.edges.emplace_back(i,
                            reader.to_index(record.fields[1], record.line));  // read left to right
    file.lines.push_back(record.line);
  }
  return file;
}

std::vector<Edge> read_edges(const std::filesystem::path& path) {
  return parse_edge_file(read_text_file(path), path.string()).edges;
}

void write_edges(std::ostream& out, std::span<const Edge> edges) {
  for (const auto& [i, j] : edges) write_number_pair(out, i, j);
}

void write_edges(const std::filesystem::path& path, std::span<const Edge> edges) {
  write_text_file(path, [edges](std::ostream& out) { write_edges(out, edges); });
}

GroundTruth read_ground_truth(const std::filesystem::path& points,
                              const std::filesystem::path& edges) {
  GroundTruth truth{.points = read_point_file(points).points, .edges = {}};
  EdgeFile file = parse_edge_file(read_text_file(edges), edges.string());
  const std::size_t n = truth.points.size();
  for (std::size_t k = 0; k < file.edges.size(); ++k) {
    const auto [i, j] = file.edges[k];
    const auto fail = [&](const std::string& message) {
      throw ParseError(edges.string(), file.lines[k], message);
    };
    if (i == j) fail("self-loop '" + std::to_string(i) + " " + std::to_string(j) + "'");
    if (std::max(i, j) >= n) {
      fail("index " + std::to_string(std::max(i, j)) + " is out of range: " + points.string() +
           " has " + std::to_string(n) + " points");
    }
  }
  truth.edges = std::move(file.edges);
  return truth;
}

void write_ground_truth(const std::filesystem::path& points, const std::filesystem::path& edges,
                        const GroundTruth& truth) {
  write_points(points, truth.points);
  write_edges(edges, truth.edges);
}

}  // namespace curvebench::geometry
