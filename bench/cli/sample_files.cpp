#include "bench/cli/sample_files.h"

#include <algorithm>
#include <fstream>
#include <utility>

#include "bench/runner/sampling_report.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "geometry/io/svg_picture.h"

namespace curvebench::cli {
namespace {

std::filesystem::path with_extension(std::filesystem::path base, const char* extension) {
  return base += extension;
}

template <class Range, class Write>
void write_lines(const std::filesystem::path& file, const Range& values, Write write) {
  std::ofstream out(file);
  for (const auto& v : values) write(out, v) << '\n';
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

void write_sample(const std::filesystem::path& base, const geometry::Sample& sample) {
  geometry::write_points(with_extension(base, ".xy"), sample.points);
  geometry::write_edges(with_extension(base, ".edges"), sample.edges);
  write_lines(with_extension(base, ".lfs"), sample.lfs, [](std::ostream& out, double lfs) -> std::ostream& {
    return std::isnan(lfs) ? out << "nan" : out << std::setprecision(17) << lfs;
  });
  write_lines(with_extension(base, ".labels"), sample.labels,
              [](std::ostream& out, geometry::Sample_label label) -> std::ostream& {
                return out << (label == geometry::Sample_label::outlier ? "outlier" : "curve");
              });
}

void write_sample_picture(const std::filesystem::path& file, const geometry::Local_feature_size& lfs,
                          const geometry::Sample& sample) {
  geometry::SvgPicture picture;
  picture.set_title(lfs.curve().name + ": " + std::to_string(sample.size()) + " samples");
  const double tolerance = 1e-4 * lfs.bounding_box_diagonal();
  std::string legend = "curve";  // once, however many components
  for (const auto& component : lfs.curve().components) {
    std::vector<geometry::Point> line = component.polyline(tolerance);
    std::vector<geometry::Edge> chain;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) chain.emplace_back(i, i + 1);
    if (component.closed() && line.size() > 2) chain.emplace_back(line.size() - 1, 0);
    picture.add_edges(line, chain, {.colour = "#9db4d8", .width_px = 3, .legend = std::exchange(legend, "")});
  }
  // Outer Voronoi vertices run off to infinity; draw the medial axis near the curve only.
  const auto box = lfs.curve().bounding_box(tolerance);
  const double margin = 0.1 * lfs.bounding_box_diagonal();
  std::vector<geometry::Point> medial;
  for (const auto& p : lfs.medial_axis().points())
    if (p.x() > box.xmin() - margin && p.x() < box.xmax() + margin && p.y() > box.ymin() - margin &&
        p.y() < box.ymax() + margin)
      medial.push_back(p);
  picture.add_points(medial, {.colour = "#2ca02c", .radius_px = 0.6, .legend = "medial axis"});
  picture.add_edges(sample.points, sample.edges, {.colour = "#1f4e99", .width_px = 1, .legend = "ground truth"});
  std::vector<geometry::Point> curve_points, outliers;
  for (std::size_t i = 0; i < sample.size(); ++i)
    (sample.labels[i] == geometry::Sample_label::outlier ? outliers : curve_points).push_back(sample.points[i]);
  picture.add_points(curve_points, {.colour = "#000000", .radius_px = 2, .legend = "samples"});
  if (!outliers.empty()) picture.add_points(outliers, {.colour = "red", .radius_px = 2, .legend = "outliers"});
  picture.write(file);
}

geometry::Sample read_sample(const geometry::Local_feature_size& lfs, const std::filesystem::path& points,
                             const std::filesystem::path& edges) {
  std::vector<geometry::Point> read = geometry::read_point_file(points).points;
  std::vector<geometry::Edge> truth;
  if (!edges.empty()) truth = geometry::read_edges(edges);
  for (const auto& [i, j] : truth)
    if (i >= read.size() || j >= read.size())
      throw std::invalid_argument(edges.string() + ": edge " + std::to_string(i) + " " + std::to_string(j) +
                                  " names a point beyond the " + std::to_string(read.size()) + " of " +
                                  points.string());
  return bench::located_sample(lfs, std::move(read), std::move(truth));
}

}  // namespace curvebench::cli
