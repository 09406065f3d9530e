#include "algorithms/crawl.h"

#include <algorithm>

#include "graphs/delaunay_triangulation.h"
#include "graphs/exact_length_order.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using graphs::Delaunay_triangulation;
using graphs::no_vertex;
using graphs::Vertex;

// Every point's Delaunay neighbours, nearest first (exact, ties to the smaller index),
// and a cursor per point past the neighbours already visited.
class Ranked_neighbors {
 public:
  explicit Ranked_neighbors(const Delaunay_triangulation& dt) : first_(dt.size() + 1), cursor_(dt.size()) {
    for (Vertex v = 0; v < dt.size(); ++v) first_[v + 1] = first_[v] + dt.neighbors(v).size();
    ranked_.reserve(first_.back());
    for (Vertex v = 0; v < dt.size(); ++v) {
      const Point& p = dt.point(v);
      const auto neighbors = dt.neighbors(v);
      const auto begin = ranked_.insert(ranked_.end(), neighbors.begin(), neighbors.end());
      std::sort(begin, ranked_.end(),
                [&](Vertex a, Vertex b) { return graphs::closer(p, dt.point(a), a, dt.point(b), b); });
      cursor_[v] = first_[v];
    }
  }

  std::span<const Vertex> of(Vertex v) const { return {ranked_.data() + first_[v], ranked_.data() + first_[v + 1]}; }

  bool among_two_nearest(Vertex v, Vertex w) const {
    const auto ranked = of(v);
    return (!ranked.empty() && ranked[0] == w) || second_nearest(v, w);
  }
  bool second_nearest(Vertex v, Vertex w) const {
    const auto ranked = of(v);
    return ranked.size() > 1 && ranked[1] == w;
  }

  bool closes(Vertex a, Vertex b, Crawl_closing closing) const {
    if (closing == Crawl_closing::authors) return second_nearest(a, b) || second_nearest(b, a);
    return among_two_nearest(a, b) && among_two_nearest(b, a);
  }

  // v's nearest unvisited neighbour, or no_vertex. Amortised O(1): visits only grow.
  Vertex nearest_unvisited(Vertex v, const std::vector<bool>& visited) {
    std::size_t& k = cursor_[v];
    while (k < first_[v + 1] && visited[ranked_[k]]) ++k;
    return k < first_[v + 1] ? ranked_[k] : no_vertex;
  }

 private:
  std::vector<std::size_t> first_, cursor_;
  std::vector<Vertex> ranked_;
};

}  // namespace

std::vector<Edge> crawl_reconstruction(std::span<const Point> points, Crawl_closing closing) {
  const Delaunay_triangulation dt(points);
  Ranked_neighbors neighbors(dt);

  std::vector<graphs::Delaunay_edge> seed_edges;
  for (const graphs::Delaunay_edge& e : dt.edges())
    if (neighbors.of(e.source)[0] == e.target || neighbors.of(e.target)[0] == e.source) seed_edges.push_back(e);
  std::vector<graphs::Edge_with_length> seeds = graphs::with_lengths(dt.points(), seed_edges);
  graphs::sort_by_exact_length(dt.points(), seeds);

  std::vector<Edge> edges;
  std::vector<bool> visited(dt.size(), false);
  for (const graphs::Edge_with_length& seed : seeds) {
    Vertex a = seed.source, b = seed.target;
    if (visited[a] || visited[b]) continue;
    visited[a] = visited[b] = true;
    edges.emplace_back(a, b);
    for (int grown = 0;; ++grown) {
      if (grown >= 4 && neighbors.closes(a, b, closing)) {
        edges.emplace_back(a, b);
        break;
      }
      const Vertex next_a = neighbors.nearest_unvisited(a, visited), next_b = neighbors.nearest_unvisited(b, visited);
      if (next_a == no_vertex && next_b == no_vertex) break;
      const bool grow_a =
          next_b == no_vertex || (next_a != no_vertex && graphs::compare_lengths(dt.point(a), dt.point(next_a),
                                                                                 dt.point(b), dt.point(next_b)) ==
                                                             CGAL::POSITIVE);
      Vertex& end = grow_a ? a : b;
      const Vertex next = grow_a ? next_a : next_b;
      visited[next] = true;
      edges.emplace_back(end, next);
      end = next;
    }
  }
  return geometry::canonical_edges(std::move(edges));
}

Algorithm crawl_algorithm() {
  static const Parameter mutual_closing{
      .name = "mutual_closing", .type = Parameter_type::integer, .default_value = 0, .minimum = 0, .maximum = 1,
      .meaning = "0: close a path when either end is the other's second nearest (the authors'); 1: only when "
                 "each end is among the other's two nearest (keeps more open curves open)"};
  return {
      .name = "crawl",
      .title = "Crawl",
      .reference = "Parakkat, Muthuganapathy 2016",
      .category = "Graph Based",
      .parameters = {mutual_closing},
      .capabilities = {.non_uniform = Support::yes, .outliers = Support::yes, .open = Support::yes,
                       .multiple = Support::yes, .time_complexity = "O(n log n)"},
      .condition = {.statement = "none"},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        return crawl_reconstruction(points, values[mutual_closing] == 1 ? Crawl_closing::mutual : Crawl_closing::authors);
      }),
  };
}

}  // namespace curvebench::algorithms
