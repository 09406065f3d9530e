#include "graphs/proximity_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/pending/disjoint_sets.hpp>

#include "geometry/point_set.h"
#include "geometry/radix_sort.h"
#include "graphs/alpha_shape_boundary.h"
#include "graphs/beta_skeleton.h"
#include "graphs/delaunay_graph.h"
#include "graphs/euclidean_minimum_spanning_tree.h"
#include "graphs/gabriel_graph.h"
#include "graphs/k_nearest_neighbor_graph.h"
#include "graphs/relative_neighborhood_graph.h"
#include "graphs/sphere_of_influence_delaunay_graph.h"
#include "graphs/sphere_of_influence_graph.h"

namespace curvebench::graphs {
namespace {

using Parameters = Proximity_graph_parameters;

constexpr Proximity_graph table[] = {
    {"delaunay", "Delaunay triangulation edges",
     [](const Delaunay_triangulation& dt, const Parameters&) { return delaunay_graph(dt); }},
    {"emst", "Euclidean minimum spanning tree",
     [](const Delaunay_triangulation& dt, const Parameters&) { return euclidean_minimum_spanning_tree(dt); }},
    {"rng", "relative neighbourhood graph (lune-based 2-skeleton)",
     [](const Delaunay_triangulation& dt, const Parameters&) { return relative_neighborhood_graph(dt); }},
    {"gabriel", "Gabriel graph (1-skeleton)",
     [](const Delaunay_triangulation& dt, const Parameters&) { return gabriel_graph(dt); }},
    {"beta-lune", "lune-based beta-skeleton (--beta)",
     [](const Delaunay_triangulation& dt, const Parameters& p) { return beta_skeleton(dt, p.beta, Beta_region::lune); }},
    {"beta-circle", "circle-based beta-skeleton (--beta)",
     [](const Delaunay_triangulation& dt, const Parameters& p) {
       return beta_skeleton(dt, p.beta, Beta_region::circle);
     }},
    {"sig", "sphere-of-influence graph",
     [](const Delaunay_triangulation& dt, const Parameters&) { return sphere_of_influence_graph(dt); }},
    {"sigdt", "sphere-of-influence graph within the Delaunay triangulation (SIGDT)",
     [](const Delaunay_triangulation& dt, const Parameters&) { return sphere_of_influence_delaunay_graph(dt); }},
    {"knn", "k-nearest-neighbour graph (--k)",
     [](const Delaunay_triangulation& dt, const Parameters& p) { return k_nearest_neighbor_graph(dt, p.k); }},
    {"alpha", "alpha-shape boundary (--alpha, squared radius)",
     [](const Delaunay_triangulation& dt, const Parameters& p) {
       return alpha_shape_boundary(dt, p.alpha ? *p.alpha : connecting_alpha(dt));
     }},
};

}  // namespace

std::span<const Proximity_graph> proximity_graphs() { return table; }

const Proximity_graph* find_proximity_graph(std::string_view name) {
  const auto it = std::find_if(std::begin(table), std::end(table), [&](const auto& g) { return g.name == name; });
  return it == std::end(table) ? nullptr : it;
}

std::vector<geometry::Edge> build_graph(const Proximity_graph& graph, std::span<const geometry::Point> points,
                                        const Proximity_graph_parameters& parameters) {
  const geometry::PointSet distinct(std::vector<geometry::Point>(points.begin(), points.end()));
  const Delaunay_triangulation dt(distinct.points());
  std::vector<geometry::Edge> edges = edge_list(graph.build(dt, parameters));
  for (auto& [i, j] : edges) i = distinct.input_index(i), j = distinct.input_index(j);
  return geometry::canonical_edges(std::move(edges));
}

double connecting_alpha(const Delaunay_triangulation& dt) {
  // The longest EMST edge is the bottleneck: the shortest length at which the Delaunay
  // edges connect every point. Rounding is monotone, so Kruskal on the rounded squared
  // lengths, in any order of ties, stops at the rounded bottleneck, the value the exact
  // EMST would give; no exact order is needed for a value that only sets a parameter.
  std::vector<std::pair<double, std::uint32_t>> by_length;
  by_length.reserve(dt.edges().size());
  for (std::uint32_t k = 0; k < dt.edges().size(); ++k) {
    const Delaunay_edge& e = dt.edges()[k];
    by_length.emplace_back(CGAL::squared_distance(dt.point(e.source), dt.point(e.target)), k);
  }
  // Stable, so ties stay in edge order: the order std::sort by (length, k) gave, in linear
  // time (geometry/radix_sort.h has its speed against std::sort).
  geometry::radix_sort_by_key(std::span(by_length), [](const auto& edge) { return edge.first; });
  std::vector<std::size_t> rank(dt.size()), parent(dt.size());
  boost::disjoint_sets<std::size_t*, std::size_t*> components(rank.data(), parent.data());
  for (std::size_t v = 0; v < dt.size(); ++v) components.make_set(v);
  double longest = 0;
  std::size_t joined = 0;
  for (const auto& [length, k] : by_length) {
    if (joined + 1 >= dt.size()) break;
    const auto a = components.find_set(dt.edges()[k].source), b = components.find_set(dt.edges()[k].target);
    if (a == b) continue;
    components.link(a, b), ++joined, longest = length;
  }
  // The weight is a rounded squared length: step up a few ulps so the edge is surely in.
  double alpha = longest / 4;
  for (int i = 0; i < 4; ++i) alpha = std::nextafter(alpha, std::numeric_limits<double>::infinity());
  return std::min(alpha, std::numeric_limits<double>::max());
}

}  // namespace curvebench::graphs
