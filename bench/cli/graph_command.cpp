#include "bench/cli/graph_command.h"

#include <memory>
#include <string>
#include <vector>

#include "bench/cli/input.h"
#include "geometry/io/edge_io.h"
#include "graphs/proximity_graph.h"

namespace curvebench::cli {
namespace {

struct Graph_options {
  std::string kind;
  std::filesystem::path input, output, svg;
  graphs::Proximity_graph_parameters parameters;
};

void run_graph(const Graph_options& options) {
  const graphs::Proximity_graph& graph = *graphs::find_proximity_graph(options.kind);
  const geometry::PointSet points = load_point_set(options.input);
  const std::vector<geometry::Edge> edges = graphs::build_graph(graph, points.points(), options.parameters);

  geometry::write_edges(options.output, to_input_indices(points, edges));
  if (!options.svg.empty()) write_graph_picture(options.svg, points.points(), edges, graph.name, options.input);
}

}  // namespace

void add_graph_command(CLI::App& app) {
  auto options = std::make_shared<Graph_options>();
  std::vector<std::string> kinds;
  std::string kinds_help = "One of:";
  for (const auto& g : graphs::proximity_graphs()) {
    kinds.emplace_back(g.name);
    kinds_help += "\n  " + std::string(g.name) + ": " + std::string(g.description);
  }

  CLI::App* command = app.add_subcommand("graph", "Build a proximity graph of a point file");
  command->add_option("KIND", options->kind, kinds_help)->required()->check(CLI::IsMember(kinds));
  command->add_option("-i,--input", options->input, "Point file (x y per line, or any format of data/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", options->output,
                      "Edge list to write: 'i j' per line, i < j, 0-based indices of the input file's points "
                      "(a duplicate point is merged into its first occurrence)")
      ->required();
  command->add_option("--beta", options->parameters.beta, "beta for beta-lune and beta-circle (>= 0)")
      ->capture_default_str();
  command->add_option("--k", options->parameters.k, "neighbours per point for knn")->capture_default_str();
  command->add_option("--alpha", options->parameters.alpha,
                      "alpha-shape parameter, the squared eraser radius (default: the smallest alpha whose "
                      "alpha-complex contains the EMST)");
  command->add_option("--svg", options->svg, "Also draw the graph to this SVG picture");
  command->callback([options] { run_graph(*options); });
}

}  // namespace curvebench::cli
