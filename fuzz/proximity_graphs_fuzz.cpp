// libFuzzer target for graphs/: every builder of proximity_graphs() on a small,
// deliberately degenerate point set, checked against the laws that tie the graphs
// together (and the kd-tree's nearest neighbours against the triangulation's). The
// decoder only makes valid input (distinct finite points, valid parameters), so a crash,
// an exception or a broken law is a bug in graphs/ or below.
//
// Input: three parameter bytes, then a point program (degenerate_point_program.h):
//   beta  = b / 32, in [0, 8); below 1 the program may draw at most 24 points (O(n^3))
//   k     = b % 9
//   alpha = unset (the table's default) if b = 0, 0 if b = 1, else
//           connecting_alpha * 2^(b % 32 - 16): from far below to far above the scale
//           at which the alpha-shape connects.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "fuzz/degenerate_point_program.h"
#include "fuzz/fuzz_target.h"
#include "geometry/io/point_io.h"
#include "geometry/point_set.h"
#include "graphs/point_kd_tree.h"
#include "graphs/proximity_graph.h"

namespace curvebench::fuzz {
namespace {

using namespace graphs;
using Edges = std::vector<Edge>;
using Parameters = Proximity_graph_parameters;

constexpr std::size_t max_points = 64;
constexpr std::size_t max_points_below_beta_1 = 24;

std::optional<double> decode_alpha(std::uint8_t code, const Delaunay_triangulation& dt) {
  if (code == 0) return std::nullopt;
  if (code == 1) return 0.0;
  return std::min(std::ldexp(connecting_alpha(dt), code % 32 - 16), std::numeric_limits<double>::max());
}

// The case as a person needs it to reproduce a finding: parameters, then the points as
// a point file (shortest round-trip decimals, so exact).
std::string describe(const Delaunay_triangulation& dt, const Parameters& parameters) {
  std::ostringstream out;
  out.precision(17);
  out << "beta " << parameters.beta << ", k " << parameters.k << ", alpha ";
  if (parameters.alpha)
    out << *parameters.alpha;
  else
    out << "unset";
  out << ", " << dt.size() << " distinct points:\n";
  geometry::write_points(out, dt.points());
  return out.str();
}

Parameters with_beta(Parameters parameters, double beta) {
  parameters.beta = beta;
  return parameters;
}

Parameters with_k(Parameters parameters, std::size_t k) {
  parameters.k = k;
  return parameters;
}

bool subset(const Edges& a, const Edges& b) { return std::includes(b.begin(), b.end(), a.begin(), a.end()); }

class Law_checker {
 public:
  Law_checker(const Delaunay_triangulation& dt, const Parameters& parameters) : dt_(dt), parameters_(parameters) {}

  void require(bool holds, std::string_view law) const { FUZZ_CHECK(holds, law, describe(dt_, parameters_)); }

  // The edges of the table's builder `name` with `parameters`, checked to be a graph on
  // the points: vertex i is point i, each edge once as i < j < n.
  Edges build(std::string_view name, const Parameters& parameters) const {
    const Proximity_graph* builder = find_proximity_graph(name);
    require(builder != nullptr, "the laws name a builder of the table");
    const Graph graph = builder->build(dt_, parameters);
    Edges edges = edge_list(graph);
    const std::size_t n = dt_.size();
    require(boost::num_vertices(graph) == n, "a proximity graph has one vertex per point");
    require(std::all_of(edges.begin(), edges.end(),
                        [n](const Edge& e) { return e.first < e.second && e.second < n; }),
            "every edge is a pair i < j of point indices");
    return edges;
  }

 private:
  const Delaunay_triangulation& dt_;
  const Parameters& parameters_;
};

void check_proximity_graph_laws(const Delaunay_triangulation& dt, const Parameters& parameters) {
  const Law_checker laws(dt, parameters);
  std::map<std::string_view, Edges> graph;
  for (const Proximity_graph& builder : proximity_graphs())
    graph[builder.name] = laws.build(builder.name, parameters);

  const auto table_graph = [&](std::string_view name) -> const Edges& {
    const auto it = graph.find(name);
    laws.require(it != graph.end(), "the laws name a builder of the table");
    return it->second;
  };

  const std::size_t n = dt.size();
  const Edges &emst = table_graph("emst"), &rng = table_graph("rng"), &gabriel = table_graph("gabriel"),
              &delaunay = table_graph("delaunay");
  laws.require(emst.size() == (n == 0 ? 0 : n - 1), "the EMST of n points has n - 1 edges");
  laws.require(subset(emst, rng), "EMST is a subgraph of the RNG");
  laws.require(subset(rng, gabriel), "RNG is a subgraph of the Gabriel graph");
  laws.require(subset(gabriel, delaunay), "the Gabriel graph is a subgraph of the Delaunay graph");
  laws.require(n < 3 || delaunay.size() <= 3 * n - 6, "a planar graph on n >= 3 points has at most 3n - 6 edges");

  laws.require(laws.build("beta-lune", with_beta(parameters, 1)) == gabriel,
               "the lune-based 1-skeleton is the Gabriel graph");
  laws.require(laws.build("beta-lune", with_beta(parameters, 2)) == rng, "the lune-based 2-skeleton is the RNG");
  laws.require(laws.build("beta-circle", with_beta(parameters, 1)) == gabriel,
               "the circle-based 1-skeleton is the Gabriel graph");
  const Edges &lune = table_graph("beta-lune"), &circle = table_graph("beta-circle");
  const double beta = parameters.beta;
  laws.require(beta < 1 || subset(circle, lune), "for beta >= 1 the circle-based skeleton is in the lune-based one");
  laws.require(beta <= 1 ? subset(gabriel, lune) : subset(lune, gabriel),
               "the lune-based skeleton loses edges as beta grows (against beta = 1)");
  laws.require(beta <= 2 ? subset(rng, lune) : subset(lune, rng),
               "the lune-based skeleton loses edges as beta grows (against beta = 2)");

  // Each point's nearest neighbour (ties to the smaller index) is its cheapest edge in the
  // EMST's exact order, and lies on the boundary of the point's sphere of influence.
  const Edges nearest_neighbor = laws.build("knn", with_k(parameters, 1));
  laws.require(subset(nearest_neighbor, emst), "the nearest-neighbour graph is a subgraph of the EMST");
  laws.require(subset(nearest_neighbor, table_graph("sig")), "the nearest-neighbour graph is a subgraph of the SIG");
  const Edges& sigdt = table_graph("sigdt");
  Edges sig_within_delaunay;
  std::set_intersection(table_graph("sig").begin(), table_graph("sig").end(), delaunay.begin(), delaunay.end(),
                        std::back_inserter(sig_within_delaunay));
  laws.require(sigdt == sig_within_delaunay, "SIGDT is the SIG's part of the Delaunay triangulation");
  laws.require(subset(nearest_neighbor, sigdt), "the nearest-neighbour graph is a subgraph of SIGDT");
  laws.require(parameters.k == 0 || subset(nearest_neighbor, table_graph("knn")), "the k-NN graphs grow with k");

  // The kd-tree's exact search (point_kd_tree.h) names every point's nearest neighbour as
  // the triangulation does, where the tree declares itself usable.
  if (Point_kd_tree::usable(dt.points())) {
    Point_kd_tree tree(dt.points());
    for (Point_kd_tree::Index rank = 0; rank < n; ++rank) {
      const auto found = tree.nearest(rank, [](Point_kd_tree::Index) { return true; }, [](const Kd_box&) { return false; });
      laws.require(found == dt.nearest_neighbor(tree.leaf_order()[rank]),
                   "the kd-tree's nearest neighbour is the triangulation's");
    }
  }
}

}  // namespace
}  // namespace curvebench::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvebench;
  fuzz::Fuzz_input input(data, size);
  graphs::Proximity_graph_parameters parameters;
  parameters.beta = input.byte() / 32.0;
  parameters.k = input.byte() % 9;
  const std::uint8_t alpha_code = input.byte();
  const geometry::PointSet points(fuzz::decode_degenerate_points(
      input, parameters.beta < 1 ? fuzz::max_points_below_beta_1 : fuzz::max_points));
  const graphs::Delaunay_triangulation dt(points.points());
  parameters.alpha = fuzz::decode_alpha(alpha_code, dt);
  fuzz::check_proximity_graph_laws(dt, parameters);
  return 0;
}
