#include "bench/cli/annotate_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/annotate/annotate_template.h"
#include "bench/cli/input.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/text_file.h"

namespace curvebench::cli {
namespace {

struct Annotate_options {
  std::filesystem::path points, edges, output;
};

// The page's marker that the point data replaces.
constexpr std::string_view data_marker = "{\"curvebench\":\"data\"}";

// Existing edges, given in the input file's numbering, as pairs of kept points (the page
// works on kept points; it writes the input numbering back when it saves).
std::vector<geometry::Edge> kept_edges(const geometry::PointSet& points, const std::filesystem::path& file) {
  std::vector<geometry::Edge> kept;
  for (const auto& [i, j] : geometry::canonical_edges(geometry::read_edges(file))) {
    if (j >= points.input_size())
      throw std::invalid_argument(file.string() + ": edge " + std::to_string(i) + " " + std::to_string(j) +
                                  " names a point beyond the " + std::to_string(points.input_size()) +
                                  " of the point file");
    const std::size_t a = points.kept_index(i), b = points.kept_index(j);
    if (a == b)
      throw std::invalid_argument(file.string() + ": edge " + std::to_string(i) + " " + std::to_string(j) +
                                  (i == j ? " is a self-loop" : " joins a point to its own duplicate"));
    kept.emplace_back(std::min(a, b), std::max(a, b));
  }
  return geometry::canonical_edges(std::move(kept));
}

// The page's data as JSON: flat coordinates and edges keep 10^5 points small and fast to parse.
nlohmann::json page_data(const Annotate_options& o, const geometry::PointSet& points) {
  std::vector<double> coordinates;
  std::vector<std::size_t> input_index, edges;
  for (std::size_t k = 0; k < points.size(); ++k) {
    coordinates.push_back(points[k].x());
    coordinates.push_back(points[k].y());
    input_index.push_back(points.input_index(k));
  }
  if (!o.edges.empty())
    for (const auto& [a, b] : kept_edges(points, o.edges)) edges.insert(edges.end(), {a, b});
  nlohmann::json data = {{"name", o.points.filename().string()},
                         {"stem", o.points.stem().string()},
                         {"input_points", points.input_size()},
                         {"points", coordinates},
                         {"edges", edges}};
  if (!points.duplicates().empty()) data["input_index"] = input_index;  // else kept index = input index
  return data;
}

std::string fill_template(const nlohmann::json& data) {
  // Inside <script>, "</" could end the element early: "<\/" is the same JSON string.
  std::string json;
  for (const char c : data.dump()) {
    if (c == '/' && !json.empty() && json.back() == '<') json += '\\';
    json += c;
  }
  std::string page(annotate_template);
  const std::size_t at = page.find(data_marker);
  if (at == std::string::npos) throw std::logic_error("annotate.html has no data marker");
  return page.replace(at, data_marker.size(), json);
}

void run_annotate(const Annotate_options& o) {
  const geometry::PointSet points = load_point_set(o.points);
  if (points.empty()) throw std::invalid_argument(o.points.string() + ": no points to annotate");
  const std::string page = fill_template(page_data(o, points));
  std::filesystem::create_directories(o.output);
  const std::filesystem::path html = o.output / (o.points.stem().string() + ".annotate.html");
  geometry::write_text_file(html, [&](std::ostream& out) { out << page; });
  std::cout << html.string() << '\n';
}

}  // namespace

void add_annotate_command(CLI::App& app) {
  auto o = std::make_shared<Annotate_options>();
  CLI::App* command = app.add_subcommand(
      "annotate", "Write an HTML page for drawing a ground truth by clicking points (saves an edge file)");
  command->add_option("-i,--input", o->points, "Point file to annotate (any format of data/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-e,--edges", o->edges, "Existing edges to correct, `i j` per line (input numbering)")
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", o->output, "Directory for STEM.annotate.html")->required();
  command->callback([o] { run_annotate(*o); });
}

}  // namespace curvebench::cli
