#include "bench/cli/reconstruct_command.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "bench/runner/external_algorithm.h"
#include "bench/cli/algorithm_options.h"
#include "bench/cli/input.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"

namespace curvebench::cli {
namespace {

struct Reconstruct_options {
  std::string algorithm;
  std::string parameters;
  std::filesystem::path input, output, points_out, svg;
  bool quiet = false;
};

void run_reconstruct(const Reconstruct_options& options) {
  const algorithms::Algorithm& algorithm = *bench::find_any_algorithm(options.algorithm);
  const auto values = algorithms::Parameter_values::parse(options.parameters);
  const geometry::PointSet points = load_point_set(options.input);
  const auto start = std::chrono::steady_clock::now();
  const algorithms::Reconstruction result = algorithms::reconstruct(algorithm, points.points(), values);
  const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;

  // An algorithm that moves or drops points indexes its own points; an interpolating one
  // indexes the input file's, and those are its output points.
  const bool own_points = !result.points.empty();
  if (own_points && options.points_out.empty())
    throw std::invalid_argument(std::string(algorithm.name) +
                                " moves or drops points: name a file for them with --points-out");
  if (!options.points_out.empty()) {
    std::vector<geometry::Point> input_points;  // as in the file, duplicates too: the edges index these
    for (std::size_t i = 0; i < points.input_size(); ++i) input_points.push_back(points[points.kept_index(i)]);
    geometry::write_points(options.points_out, own_points ? result.points : input_points);
  }
  geometry::write_edges(options.output, own_points ? result.edges : to_input_indices(points, result.edges));
  if (!options.quiet)
    std::cerr << algorithm.name << ": " << points.size() << " points, " << result.edges.size() << " edges, "
              << elapsed.count() << " ms\n";
  if (!options.svg.empty())
    write_graph_picture(options.svg, own_points ? std::span<const geometry::Point>(result.points) : points.points(),
                        result.edges, algorithm.title, options.input);
}

}  // namespace

void add_reconstruct_command(CLI::App& app) {
  auto options = std::make_shared<Reconstruct_options>();
  CLI::App* command = app.add_subcommand("reconstruct", "Reconstruct a curve from a point file");
  command->add_option("-a,--algorithm", options->algorithm,
                      "Algorithm name (see `curvebench list`); NAME+outlier-filter drops outliers first; "
                      "exec:COMMAND runs a program, e.g. 'exec:python3 mine.py {points} {edges}'; or a name from --algorithm-file")
      ->required()
      ->check(CLI::Validator(
          [](const std::string& name) {
            try {
              return bench::find_any_algorithm(name) ? std::string() : "no algorithm named " + name;
            } catch (const std::invalid_argument& error) {
              return std::string(error.what());
            }
          },
          "ALGORITHM"));
  add_algorithm_file_option(command);
  command->add_option("-p,--parameters", options->parameters,
                      "Parameter values as name=value,... (defaults in `curvebench list`)");
  command->add_option("-i,--input", options->input, "Point file (x y per line, or any format of data/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", options->output,
                      "Edge list to write: 'i j' per line, i < j, 0-based indices of the input file's points "
                      "(a duplicate point is merged into its first occurrence), or of --points-out's")
      ->required();
  command->add_option("--points-out", options->points_out,
                      "Write the output points here ('x y' per line): the input file's points for an "
                      "interpolating algorithm, the moved or kept points for one that denoises or filters");
  command->add_option("--svg", options->svg, "Also draw the reconstruction to this SVG picture");
  command->add_flag("-q,--quiet", options->quiet, "Do not print the summary line to stderr");
  command->callback([options] { run_reconstruct(*options); });
}

}  // namespace curvebench::cli
