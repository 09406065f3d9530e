#include "graphs/proximity_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "graphs/alpha_shape_boundary.h"
#include "graphs/beta_skeleton.h"
#include "graphs/delaunay_graph.h"
#include "graphs/euclidean_minimum_spanning_tree.h"
#include "graphs/gabriel_graph.h"
#include "graphs/k_nearest_neighbor_graph.h"
#include "graphs/relative_neighborhood_graph.h"
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
    {"knn", "k-nearest-neighbour graph (--k)",
     [](const Delaunay_triangulation& dt, const Parameters& p) { return k_nearest_neighbor_graph(dt, p.k); }},
    {"alpha", "alpha-shape boundary (--alpha, squared radius)",
     [](const Delaunay_triangulation& dt, const Parameters& p) {
       return alpha_shape_boundary(dt.points(), p.alpha.value_or(connecting_alpha(dt)));
     }},
};

}  // namespace

std::span<const Proximity_graph> proximity_graphs() { return table; }

const Proximity_graph* find_proximity_graph(std::string_view name) {
  const auto it = std::find_if(std::begin(table), std::end(table), [&](const auto& g) { return g.name == name; });
  return it == std::end(table) ? nullptr : it;
}

double connecting_alpha(const Delaunay_triangulation& dt) {
  const Graph tree = euclidean_minimum_spanning_tree(dt);
  double longest = 0;
  for (const auto e : boost::make_iterator_range(boost::edges(tree)))
    longest = std::max(longest, boost::get(boost::edge_weight, tree, e));
  // The weight is a rounded squared length: step up a few ulps so the edge is surely in.
  double alpha = longest / 4;
  for (int i = 0; i < 4; ++i) alpha = std::nextafter(alpha, std::numeric_limits<double>::infinity());
  return std::min(alpha, std::numeric_limits<double>::max());
}

}  // namespace curvebench::graphs
