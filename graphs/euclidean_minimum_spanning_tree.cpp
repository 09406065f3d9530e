#include "graphs/euclidean_minimum_spanning_tree.h"

#include <algorithm>

#include <boost/pending/disjoint_sets.hpp>

#include "geometry/exact_sign.h"

namespace curvebench::graphs {
namespace {

using geometry::Error_bounded_double;

struct Candidate {
  Error_bounded_double squared_length;  // settles almost every comparison without GMP
  Vertex source, target;
};

}  // namespace

Graph euclidean_minimum_spanning_tree(const Delaunay_triangulation& dt) {
  using geometry::difference, geometry::squared_length;
  std::vector<Candidate> candidates;
  candidates.reserve(dt.edges().size());
  for (const Delaunay_edge& e : dt.edges())
    candidates.push_back(
        {squared_length(difference<Error_bounded_double>(dt.point(e.target), dt.point(e.source))), e.source,
         e.target});

  const auto shorter = [&](const Candidate& a, const Candidate& b) {
    const CGAL::Sign s =
        geometry::exact_sign(b.squared_length - a.squared_length, [&]<class NT>(std::type_identity<NT>) {
          return squared_length(difference<NT>(dt.point(b.target), dt.point(b.source))) -
                 squared_length(difference<NT>(dt.point(a.target), dt.point(a.source)));
        });
    return s == CGAL::POSITIVE ||
           (s == CGAL::ZERO && std::tie(a.source, a.target) < std::tie(b.source, b.target));
  };
  std::sort(candidates.begin(), candidates.end(), shorter);

  std::vector<std::size_t> rank(dt.size()), parent(dt.size());
  boost::disjoint_sets<std::size_t*, std::size_t*> components(rank.data(), parent.data());
  for (std::size_t v = 0; v < dt.size(); ++v) components.make_set(v);

  std::vector<Edge> tree;
  tree.reserve(dt.size());
  for (const Candidate& c : candidates) {
    if (tree.size() + 1 >= dt.size()) break;
    const auto a = components.find_set(c.source), b = components.find_set(c.target);
    if (a == b) continue;
    components.link(a, b);
    tree.emplace_back(c.source, c.target);
  }
  return make_graph(dt.points(), tree);
}

}  // namespace curvebench::graphs
