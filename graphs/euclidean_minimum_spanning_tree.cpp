#include "graphs/euclidean_minimum_spanning_tree.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <boost/pending/disjoint_sets.hpp>

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {
namespace {

struct Candidate {
  double squared_length;  // rounded: settles almost every comparison without GMP
  Vertex source, target;
};

}  // namespace

Graph euclidean_minimum_spanning_tree(const Delaunay_triangulation& dt) {
  std::vector<Candidate> candidates;
  candidates.reserve(dt.edges().size());
  for (const Delaunay_edge& e : dt.edges())
    candidates.push_back(
        {geometry::squared_distance_approximation(dt.point(e.source), dt.point(e.target)), e.source, e.target});

  const auto shorter = [&](const Candidate& a, const Candidate& b) {
    const auto cached = geometry::certain_sign_of_difference(a.squared_length, b.squared_length);
    const CGAL::Sign s = cached ? *cached
                                : compare_lengths(dt.point(a.source), dt.point(a.target), dt.point(b.source),
                                                  dt.point(b.target));
    return s == CGAL::POSITIVE ||
           (s == CGAL::ZERO && std::tie(a.source, a.target) < std::tie(b.source, b.target));
  };
  // Sorting 3n candidates with the exact comparator costs more than the triangulation:
  // sort by the rounded keys (plain doubles), then put in exact order each run of
  // consecutive keys that the filter cannot tell apart. Where it can, the keys' error
  // intervals k (1 +- 2^-48) are disjoint, and since both ends grow with k, every key
  // before that point is certainly shorter than every key after it: the result is the
  // exact order. (Keys below 2^-900 may carry subnormal error: never split after one.)
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.squared_length < b.squared_length; });
  const auto separated = [](double shorter_key, double longer_key) {
    return shorter_key >= 0x1p-900 && std::isfinite(longer_key) &&
           longer_key - shorter_key > (shorter_key + longer_key) * 0x1p-48;
  };
  for (auto run = candidates.begin(); run != candidates.end();) {
    auto end = std::next(run);
    while (end != candidates.end() && !separated(std::prev(end)->squared_length, end->squared_length)) ++end;
    if (std::distance(run, end) > 1) std::sort(run, end, shorter);
    run = end;
  }

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
