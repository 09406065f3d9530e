#include "bench/cli/evaluate_command.h"

#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "bench/runner/bench_input.h"
#include "bench/runner/evaluation.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"

namespace curvebench::cli {
namespace {

struct Evaluate_options {
  std::filesystem::path points, edges, truth;
  std::string curve;
};

// Edges of a file, canonical, each checked against the point count.
std::vector<geometry::Edge> read_checked_edges(const std::filesystem::path& file, std::size_t points) {
  std::vector<geometry::Edge> edges = geometry::canonical_edges(geometry::read_edges(file));
  for (const auto& [i, j] : edges)
    if (j >= points)
      throw std::invalid_argument(file.string() + ": edge " + std::to_string(i) + " " + std::to_string(j) +
                                  " names a point beyond the " + std::to_string(points) + " of the point file");
  return edges;
}

nlohmann::json optional(const std::optional<double>& value) {
  return value ? (std::isfinite(*value) ? nlohmann::json(*value) : nlohmann::json("inf")) : nlohmann::json();
}

void run_evaluate(const Evaluate_options& o) {
  const std::vector<geometry::Point> points = geometry::read_point_file(o.points).points;
  const std::vector<geometry::Edge> edges = read_checked_edges(o.edges, points.size());
  const std::vector<geometry::Edge> truth = read_checked_edges(o.truth, points.size());
  std::optional<bench::Polyline> curve;
  if (!o.curve.empty()) curve = bench::dense_polyline(geometry::Local_feature_size(geometry::make_curve(o.curve)));
  const geometry::Polyline_view truth_view{points, truth};
  const std::optional<geometry::Polyline_view> curve_view = curve ? std::optional(curve->view()) : std::nullopt;
  const bench::Evaluation e = bench::evaluate({points, edges}, true, &truth_view, curve_view ? &*curve_view : nullptr);
  const nlohmann::json report = {
      {"points", points.size()},
      {"edges", edges.size()},
      {"truth_edges", truth.size()},
      {"distances_to", curve ? "curve " + o.curve : std::string("ground truth")},
      {"exact", *e.exact},
      {"hausdorff", optional(e.hausdorff)},
      {"rms", optional(e.rms)},
      {"diagonal", optional(e.diagonal)},
      {"normal_deviation", optional(e.normal_deviation)},
      {"manifold", e.topology.manifold},
      {"max_degree", e.topology.max_degree},
      {"components", e.topology.components},
      {"open_components", e.topology.open_components},
      {"closed_components", e.topology.closed_components},
      {"unconnected", e.topology.unconnected},
  };
  std::cout << report.dump(2) << '\n';
}

}  // namespace

void add_evaluate_command(CLI::App& app) {
  auto o = std::make_shared<Evaluate_options>();
  CLI::App* command = app.add_subcommand("evaluate", "Score one reconstruction against its ground truth (JSON)");
  command->add_option("-i,--input", o->points, "Point file the edges index")->required()->check(CLI::ExistingFile);
  command->add_option("-e,--edges", o->edges, "Reconstructed edges, `i j` per line")->required()->check(CLI::ExistingFile);
  command->add_option("-g,--ground-truth", o->truth, "Ground-truth edges between the same points")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--curve", o->curve, "Measure distances to this curve (spec) instead of the ground truth");
  command->callback([o] { run_evaluate(*o); });
}

}  // namespace curvebench::cli
