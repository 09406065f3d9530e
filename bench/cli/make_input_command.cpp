#include "bench/cli/make_input_command.h"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bench/runner/bench_input.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"

namespace curvebench::cli {
namespace {

struct Make_input_options {
  std::string name;
  std::string base;
};

void run_make_input(const Make_input_options& o) {
  const std::vector<std::string> names{o.name};
  const bench::Bench_input input = bench::make_bench_inputs(names).front();
  geometry::write_points(o.base + ".xy", input.points);
  std::cout << o.base << ".xy: " << input.points.size() << " points\n";
  if (input.truth) {
    geometry::write_edges(o.base + ".edges", *input.truth);
    std::cout << o.base << ".edges: " << input.truth->size() << " ground-truth edges\n";
  }
}

}  // namespace

void add_make_input_command(CLI::App& app) {
  auto o = std::make_shared<Make_input_options>();
  CLI::App* command =
      app.add_subcommand("make-input", "Write a benchmark job's input (results.csv's `input`) as BASE.xy and BASE.edges");
  command->add_option("NAME", o->name, "Input name, e.g. 'fourier:seed=3|epsilon=0.5' (see results.csv)")->required();
  command->add_option("-o,--output", o->base, "BASE of the files to write")->required();
  command->callback([o] { run_make_input(*o); });
}

}  // namespace curvebench::cli
