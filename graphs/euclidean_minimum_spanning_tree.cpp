#include "graphs/euclidean_minimum_spanning_tree.h"

#include <boost/pending/disjoint_sets.hpp>

#include "graphs/exact_length_order.h"

namespace curvebench::graphs {

Graph euclidean_minimum_spanning_tree(const Delaunay_triangulation& dt) {
  std::vector<Edge_with_length> candidates = with_lengths(dt.points(), dt.edges());
  sort_by_exact_length(dt.points(), candidates);

  std::vector<std::size_t> rank(dt.size()), parent(dt.size());
  boost::disjoint_sets<std::size_t*, std::size_t*> components(rank.data(), parent.data());
  for (std::size_t v = 0; v < dt.size(); ++v) components.make_set(v);

  std::vector<Edge> tree;
  tree.reserve(dt.size());
  for (const Edge_with_length& c : candidates) {
    if (tree.size() + 1 >= dt.size()) break;
    const auto a = components.find_set(c.source), b = components.find_set(c.target);
    if (a == b) continue;
    components.link(a, b);
    tree.emplace_back(c.source, c.target);
  }
  return make_graph(dt.points(), tree);
}

}  // namespace curvebench::graphs
