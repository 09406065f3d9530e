#include "bench/cli/evaluate_command.h"

#include <iostream>
#include <memory>

#include "bench/runner/evaluation_report.h"
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

void run_evaluate(const Evaluate_options& o) {
  const std::vector<geometry::Point> points = geometry::read_point_file(o.points).points;
  const std::vector<geometry::Edge> edges = read_checked_edges(o.edges, points.size());
  const std::vector<geometry::Edge> truth = read_checked_edges(o.truth, points.size());
  std::cout << bench::evaluation_report_json(points, edges, truth, o.curve) << '\n';
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
