#include "algorithms/peel.h"

#include <cstdint>
#include <numeric>
#include <utility>

#include "graphs/delaunay_triangulation.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using graphs::Delaunay_triangulation;
using graphs::no_vertex;
using graphs::Vertex;

// True if pq is a longest side of triangle pqc, ties included: |pq| >= |pc| and |pq| >= |qc|.
bool longest_side(const Point& p, const Point& q, const Point& c) {
  return graphs::compare_lengths(p, c, p, q) != CGAL::NEGATIVE && graphs::compare_lengths(q, c, p, q) != CGAL::NEGATIVE;
}

// |ax| < reach |ab|, as the sign of reach^2 |ab|^2 - |ax|^2: exact for the double `reach`.
bool within_reach(const Point& a, const Point& x, const Point& b, double reach) {
  using geometry::difference, geometry::squared_length;
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
           const NT r(reach);
           return r * r * squared_length(difference<NT>(b, a)) - squared_length(difference<NT>(x, a));
         }) == CGAL::POSITIVE;
}

// An undirected graph on the triangulation's vertices as adjacency arrays (the peeled graph
// is fixed once built, and P2 reads each vertex's edges twice).
class Adjacency {
 public:
  Adjacency(std::size_t n, std::span<const std::pair<Vertex, Vertex>> edges) : first_(n + 1, 0) {
    for (const auto& [a, b] : edges) {
      ++first_[a + 1];
      ++first_[b + 1];
    }
    std::partial_sum(first_.begin(), first_.end(), first_.begin());
    neighbors_.resize(first_.back());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (const auto& [a, b] : edges) {
      neighbors_[next[a]++] = b;
      neighbors_[next[b]++] = a;
    }
  }
  std::span<const Vertex> of(Vertex v) const {
    return {neighbors_.data() + first_[v], neighbors_.data() + first_[v + 1]};
  }

 private:
  std::vector<std::size_t> first_;
  std::vector<Vertex> neighbors_;
};

// P2 at v: the edge vw has fewer than two strictly shorter edges beside it iff |vw| is at
// most the second smallest length at v (only one length can lie below that one). Returns
// v's second nearest peeled neighbour (ties to the smaller index; any tie gives the same
// length), or no_vertex if every edge stays (degree <= 2). Two linear scans: a vertex can
// have many peeled edges, so no quadratic count and no sort.
Vertex cutoff_neighbor(const Delaunay_triangulation& dt, Vertex v, std::span<const Vertex> neighbors) {
  if (neighbors.size() <= 2) return no_vertex;
  const Point& p = dt.point(v);
  const auto nearest_except = [&](Vertex excluded) {
    Vertex best = no_vertex;
    for (const Vertex w : neighbors)
      if (w != excluded && (best == no_vertex || graphs::closer(p, dt.point(w), w, dt.point(best), best))) best = w;
    return best;
  };
  return nearest_except(nearest_except(no_vertex));
}

bool stays_at(const Delaunay_triangulation& dt, Vertex v, Vertex w, Vertex cutoff) {
  return cutoff == no_vertex || graphs::compare_distances(dt.point(v), dt.point(w), dt.point(cutoff)) != CGAL::NEGATIVE;
}

// P3 for one end a whose only edge is ab: the nearest Delaunay neighbour x != b (ties to the
// smaller index) if |ax| < reach |ab|, else no_vertex. It depends on a and b only, which
// makes the rounds order-free.
Vertex join_target(const Delaunay_triangulation& dt, Vertex a, Vertex b, double reach) {
  const Point& p = dt.point(a);
  Vertex best = no_vertex;
  for (const Vertex x : dt.neighbors(a))
    if (x != b && (best == no_vertex || graphs::closer(p, dt.point(x), x, dt.point(best), best))) best = x;
  return best != no_vertex && within_reach(p, dt.point(best), dt.point(b), reach) ? best : no_vertex;
}

std::vector<Edge> canonical(std::span<const std::pair<Vertex, Vertex>> edges) {
  std::vector<Edge> result(edges.begin(), edges.end());
  return geometry::canonical_edges(std::move(result));
}

}  // namespace

Peel_stages peel_stages(std::span<const Point> points, double reach) {
  Peel_stages stages;
  if (points.size() < 2) return stages;
  const Delaunay_triangulation dt(points);
  const std::size_t n = dt.size();

  // P1: one pass over the edges with their apexes; collinear input has none and keeps all.
  std::vector<std::pair<Vertex, Vertex>> peeled;
  peeled.reserve(dt.edges().size());
  for (const graphs::Delaunay_edge& e : dt.edges()) {
    const Point &p = dt.point(e.source), &q = dt.point(e.target);
    const bool longest = (e.left != no_vertex && longest_side(p, q, dt.point(e.left))) ||
                         (e.right != no_vertex && longest_side(p, q, dt.point(e.right)));
    if (!longest) peeled.emplace_back(e.source, e.target);
  }

  // P2: every vertex's cutoff from the peeled graph as a whole, then each edge at both ends.
  const Adjacency peeled_graph(n, peeled);
  std::vector<Vertex> cutoff(n);
  for (Vertex v = 0; v < n; ++v) cutoff[v] = cutoff_neighbor(dt, v, peeled_graph.of(v));
  std::vector<std::pair<Vertex, Vertex>> kept;
  for (const auto& [a, b] : peeled)
    if (stays_at(dt, a, b, cutoff[a]) && stays_at(dt, b, a, cutoff[b])) kept.emplace_back(a, b);

  // P3: rounds of simultaneous joins. An end is a vertex with exactly one edge, `only[v]`.
  std::vector<std::uint32_t> degree(n, 0);
  std::vector<Vertex> only(n, no_vertex);
  const auto count_edge = [&](Vertex v, Vertex w) {
    if (degree[v]++ == 0) only[v] = w;
  };
  for (const auto& [a, b] : kept) {
    count_edge(a, b);
    count_edge(b, a);
  }
  std::vector<std::pair<Vertex, Vertex>> result = kept;
  if (reach > 0) {
    std::vector<Vertex> ends;
    for (Vertex v = 0; v < n; ++v)
      if (degree[v] == 1) ends.push_back(v);
    std::vector<Vertex> target(n, no_vertex);
    std::vector<Vertex> reached, next;
    while (!ends.empty()) {
      for (const Vertex a : ends) target[a] = join_target(dt, a, only[a], reach);
      reached.clear();
      for (const Vertex a : ends) {
        const Vertex x = target[a];
        if (x == no_vertex) continue;
        if (target[x] == a && x < a) continue;  // two ends that chose each other: one edge
        result.emplace_back(a, x);
        ++degree[a];
        if (degree[x]++ == 0) {
          only[x] = a;
          reached.push_back(x);
        }
      }
      // Isolated vertices that received exactly one edge are the next round's ends (in
      // any order: a round's joins do not depend on each other).
      next.clear();
      for (const Vertex x : reached)
        if (degree[x] == 1) next.push_back(x);
      for (const Vertex a : ends) target[a] = no_vertex;
      ends.swap(next);
    }
  }

  stages.peeled = canonical(peeled);
  stages.filtered = canonical(kept);
  stages.result = canonical(result);
  return stages;
}

std::vector<Edge> peel_reconstruction(std::span<const Point> points, double reach) {
  return peel_stages(points, reach).result;
}

Algorithm peel_algorithm() {
  static const Parameter reach{.name = "reach", .default_value = 0, .minimum = 0, .maximum = 10,
                               .meaning = "a vertex left with one edge ab is joined to its nearest other Delaunay "
                                          "neighbour x if |ax| < reach |ab| (restores self-intersections; 0: off)"};
  return {
      .name = "peel",
      .title = "Peel",
      .reference = "Parakkat, Methirumangalath, Muthuganapathy 2018",
      .category = "Non-manifold",
      .parameters = {reach},
      .capabilities = {.non_uniform = Support::yes, .noise = Support::yes, .outliers = Support::yes,
                       .manifold = Support::no, .open = Support::yes, .multiple = Support::yes,
                       .sharp = Support::no, .guarantee = true, .time_complexity = "O(n^2)"},
      .condition = {.statement = "none"},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        return peel_reconstruction(points, values[reach]);
      }),
  };
}

}  // namespace curvebench::algorithms
