#include "bench/cli/input.h"

#include <algorithm>
#include <iostream>

#include "geometry/io/point_io.h"
#include "geometry/io/svg_picture.h"

namespace curvebench::cli {

geometry::PointSet load_point_set(const std::filesystem::path& path) {
  geometry::PointFile file = geometry::read_point_file(path);
  const std::vector<std::size_t> lines = file.lines;
  geometry::PointSet points(std::move(file.points));
  for (const auto& d : points.duplicates())
    std::cerr << path.string() << ':' << lines[d.input_index] << ": duplicate of the point on line "
              << lines[d.first_input_index] << ", merged\n";
  return points;
}

std::vector<geometry::Edge> to_input_indices(const geometry::PointSet& points, std::span<const geometry::Edge> edges) {
  std::vector<geometry::Edge> renumbered;
  renumbered.reserve(edges.size());
  for (const auto& [i, j] : edges) {
    const auto a = points.input_index(i), b = points.input_index(j);
    renumbered.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(renumbered.begin(), renumbered.end());
  return renumbered;
}

void write_graph_picture(const std::filesystem::path& svg, std::span<const geometry::Point> points,
                         std::span<const geometry::Edge> edges, std::string_view what,
                         const std::filesystem::path& input) {
  geometry::SvgPicture picture(points);
  picture.set_title(std::string(what) + " of " + input.filename().string() + ": " + std::to_string(points.size()) +
                    " points, " + std::to_string(edges.size()) + " edges");
  picture.add_edges(edges);
  picture.add_points();
  picture.write(svg);
}

}  // namespace curvebench::cli
