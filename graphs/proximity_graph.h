// Every proximity graph by name: the table the command line, the benchmarks and the
// fuzzer iterate, so adding a builder is one header plus one row here.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/graph.h"

namespace curvebench::graphs {

// The parameters of the builders that take one; each builder reads only its own.
struct Proximity_graph_parameters {
  double beta = 1.5;           // beta-lune, beta-circle
  std::size_t k = 2;           // knn
  std::optional<double> alpha;  // alpha (squared radius); default: connecting_alpha(dt)
};

// A row of the table: one builder and how it is named.
struct Proximity_graph {
  std::string_view name;         // as typed on the command line
  std::string_view description;  // one line for --help
  // Builds the graph on the triangulation's points; reads only its own parameters.
  Graph (*build)(const Delaunay_triangulation&, const Proximity_graph_parameters&);
};

// Every builder, in a fixed order: delaunay, emst, rng, gabriel, beta-lune, beta-circle,
// sig, sigdt, knn, alpha. The table is static.
std::span<const Proximity_graph> proximity_graphs();
// The row named `name` in proximity_graphs(), or nullptr if there is none.
const Proximity_graph* find_proximity_graph(std::string_view name);

// Builds `graph` on any point list, as algorithms/registry.h's reconstruct() runs an
// algorithm: exact duplicates are merged into their first occurrence, which alone gets
// edges (geometry::PointSet), and the edges, canonical, are between input indices. Throws
// std::invalid_argument for a non-finite coordinate, and passes on the builder's errors.
std::vector<geometry::Edge> build_graph(const Proximity_graph& graph, std::span<const geometry::Point> points,
                                        const Proximity_graph_parameters& parameters = {});

// The smallest alpha whose alpha-complex contains the EMST, so it is connected:
// (longest EMST edge / 2)^2, rounded up. A scale-free default for the alpha-shape.
double connecting_alpha(const Delaunay_triangulation& dt);

}  // namespace curvebench::graphs
