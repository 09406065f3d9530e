#include "graphs/beta_skeleton.h"

#include <cmath>
#include <stdexcept>

#include "graphs/delaunay_region_search.h"

namespace curvebench::graphs {
namespace {

std::vector<Edge> pairs_with_empty_region(std::span<const Point> points, double beta) {
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      bool empty = true;
      for (std::size_t k = 0; k < points.size() && empty; ++k)
        empty = k == i || k == j || !blocks(points[i], points[j], points[k], beta, Beta_region::lune);
      if (empty) edges.emplace_back(i, j);
    }
  return edges;
}

}  // namespace

Graph beta_skeleton(const Delaunay_triangulation& dt, double beta, Beta_region region) {
  if (!std::isfinite(beta) || beta < 0)
    throw std::invalid_argument("beta-skeleton: beta must be a finite number >= 0");
  const auto points = dt.points();
  if (beta < 1) return make_graph(points, pairs_with_empty_region(points, beta));

  const auto opposite_blocks = [&](const Delaunay_edge& e, Vertex r) {
    return r != no_vertex && blocks(dt.point(e.source), dt.point(e.target), dt.point(r), beta, region);
  };
  const bool search_lune = region == Beta_region::lune && beta > 1;
  Delaunay_region_search search(dt);

  std::vector<Edge> edges;
  for (const Delaunay_edge& e : dt.edges()) {
    if (opposite_blocks(e, e.left) || opposite_blocks(e, e.right)) continue;
    const Point& p = dt.point(e.source);
    const Point& q = dt.point(e.target);
    if (search_lune && search.find_if(
                           e.source, [&](Vertex v) { return in_lune_hull(p, q, dt.point(v), beta); },
                           [&](Vertex v) { return v != e.target && blocks(p, q, dt.point(v), beta, region); }))
      continue;
    edges.emplace_back(e.source, e.target);
  }
  return make_graph(points, edges);
}

}  // namespace curvebench::graphs
