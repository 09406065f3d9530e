#include "algorithms/gathang.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "algorithms/gathan.h"
#include "graphs/delaunay_triangulation.h"
#include "geometry/exact_sign.h"
#include "geometry/radix_sort.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using graphs::no_vertex;
using graphs::Vertex;

// At most two neighbours per vertex.
class Degree_two_graph {
 public:
  explicit Degree_two_graph(std::size_t n) : adjacent_(n, {no_vertex, no_vertex}) {}

  int degree(Vertex v) const { return (adjacent_[v][0] != no_vertex) + (adjacent_[v][1] != no_vertex); }
  bool has_edge(Vertex a, Vertex b) const { return adjacent_[a][0] == b || adjacent_[a][1] == b; }
  void add(Vertex a, Vertex b) {
    insert(a, b);
    insert(b, a);
  }
  void remove(Vertex a, Vertex b) {
    erase(a, b);
    erase(b, a);
  }
  std::vector<Edge> edges() const {
    std::vector<Edge> result;
    for (Vertex v = 0; v < adjacent_.size(); ++v)
      for (const Vertex w : adjacent_[v])
        if (w != no_vertex && v < w) result.emplace_back(v, w);
    return result;
  }

 private:
  void insert(Vertex a, Vertex b) { (adjacent_[a][0] == no_vertex ? adjacent_[a][0] : adjacent_[a][1]) = b; }
  void erase(Vertex a, Vertex b) {
    if (adjacent_[a][0] == b) {
      adjacent_[a][0] = adjacent_[a][1];
      adjacent_[a][1] = no_vertex;
    } else if (adjacent_[a][1] == b) {
      adjacent_[a][1] = no_vertex;
    }
  }
  std::vector<std::array<Vertex, 2>> adjacent_;
};

// The nearest Delaunay neighbour of v among those `admissible` accepts, or no_vertex.
template <class Admissible>
Vertex nearest_neighbor_where(const graphs::Delaunay_triangulation& dt, Vertex v, Admissible&& admissible) {
  Vertex best = no_vertex;
  for (const Vertex w : dt.neighbors(v))
    if (admissible(w) && (best == no_vertex || graphs::closer(dt.point(v), dt.point(w), w, dt.point(best), best)))
      best = w;
  return best;
}

}  // namespace

std::vector<Edge> gathang_reconstruction(std::span<const Point> points, double alpha_degrees) {
  const std::size_t n = points.size();
  if (n < 2) return {};
  const graphs::Delaunay_triangulation dt(points);

  // S.
  std::vector<std::array<Vertex, 2>> proposed(n);
  for (Vertex v = 0; v < n; ++v) {
    const Vertex nearest = dt.nearest_neighbor(v);
    const Vertex half = nearest_neighbor_where(dt, v, [&](Vertex w) {
      return w != nearest && gathan_rules::at_least_right_angle(dt.point(v), dt.point(nearest), dt.point(w));
    });
    proposed[v] = {nearest, half};
  }
  Degree_two_graph graph(n);
  for (Vertex v = 0; v < n; ++v)
    for (const Vertex w : proposed[v])
      if (w != no_vertex && v < w && (proposed[w][0] == v || proposed[w][1] == v)) graph.add(v, w);

  // C, corner candidates nearest-neighbour distance first: each step changes the graph the
  // next one reads, so an order by index made the output depend on the input's order, and
  // one by position on its orientation (`curvebench hunt`). Two mutual nearest neighbours
  // always tie on that distance: then the nearer to its next Delaunay neighbour goes first,
  // which a rotation, a reflection or a scaling keeps (`curvebench hunt` found the order by
  // position flip under a reflection). Ties left (degenerate input): the lexicographically
  // smaller point first.
  const double cos_alpha = std::cos(alpha_degrees * std::numbers::pi / 180);
  std::vector<Vertex> next_nearest(n);
  for (Vertex v = 0; v < n; ++v)
    next_nearest[v] = nearest_neighbor_where(dt, v, [&](Vertex w) { return w != proposed[v][0]; });
  // |v vn| against |w wn|, exactly; no neighbour counts as farthest. The squared lengths
  // are rounded once per vertex, and a mutual pair's segment equals itself without
  // arithmetic: it ties with its partner on every curve, and the exact fallback of a tie is
  // what the sort would otherwise spend its time in.
  const auto reach = [&](const std::vector<Vertex>& neighbor) {
    std::vector<double> squared(n);
    for (Vertex v = 0; v < n; ++v)
      if (neighbor[v] != no_vertex) squared[v] = geometry::squared_distance_approximation(dt.point(v), dt.point(neighbor[v]));
    return squared;
  };
  std::vector<Vertex> nearest(n);
  for (Vertex v = 0; v < n; ++v) nearest[v] = proposed[v][0];
  const std::vector<double> nearest_reach = reach(nearest), next_reach = reach(next_nearest);
  const auto compare_reach = [&](const std::vector<Vertex>& neighbor, const std::vector<double>& squared, Vertex v,
                                 Vertex w) {
    const Vertex vn = neighbor[v], wn = neighbor[w];
    if (vn == no_vertex || wn == no_vertex) return vn == wn ? CGAL::ZERO : vn == no_vertex ? CGAL::NEGATIVE : CGAL::POSITIVE;
    if ((vn == w && wn == v) || (v == w && vn == wn)) return CGAL::ZERO;
    return graphs::compare_lengths(dt.point(v), dt.point(vn), squared[v], dt.point(w), dt.point(wn), squared[w]);
  };
  const auto before = [&](Vertex v, Vertex w) {
    auto order = compare_reach(nearest, nearest_reach, v, w);  // POSITIVE: v's is shorter
    if (order == CGAL::ZERO) order = compare_reach(next_nearest, next_reach, v, w);
    return order != CGAL::ZERO ? order == CGAL::POSITIVE : dt.point(v) < dt.point(w);
  };
  // Sorted by the rounded distance first, in place: the comparator above reads four points
  // per call, which missed the cache at 10^6 points (as long as the triangulation). Where
  // the filter separates two neighbouring keys, every key before is certainly shorter than
  // every key after (the test is monotone in both), so only the runs it cannot separate
  // need the exact comparator.
  std::vector<std::pair<double, Vertex>> keyed(n);
  for (Vertex v = 0; v < n; ++v) keyed[v] = {nearest_reach[v], v};
  geometry::radix_sort_by_key(std::span(keyed), [](const auto& k) { return k.first; });
  std::vector<Vertex> by_spacing(n);
  for (std::size_t k = 0; k < n; ++k) by_spacing[k] = keyed[k].second;
  for (std::size_t first = 0; first < n;) {
    std::size_t last = first + 1;
    while (last < n && !geometry::certain_sign_of_difference(keyed[last - 1].first, keyed[last].first)) ++last;
    if (last - first > 1) std::sort(by_spacing.begin() + first, by_spacing.begin() + last, before);
    first = last;
  }
  for (const Vertex c : by_spacing) {
    if (proposed[c][1] != no_vertex || graph.degree(c) >= 2) continue;
    const Vertex a = proposed[c][0];
    const Vertex b = nearest_neighbor_where(dt, c, [&](Vertex w) {
      return w != a && gathan_rules::angle_at_least(dt.point(c), dt.point(a), dt.point(w), cos_alpha);
    });
    const auto proposes = [&](Vertex v, Vertex w) { return proposed[v][0] == w || proposed[v][1] == w; };
    if (b != no_vertex && graph.degree(c) == 0 && graph.has_edge(a, b)) {  // C1
      graph.remove(a, b);
      graph.add(a, c);
      graph.add(c, b);
      // C3: the rungs below it, one after the other.
      for (Vertex x = a, y = b; proposes(x, y) && proposes(y, x);) {
        const Vertex next_x = proposed[x][0] == y ? proposed[x][1] : proposed[x][0];
        const Vertex next_y = proposed[y][0] == x ? proposed[y][1] : proposed[y][0];
        if (next_x == no_vertex || next_y == no_vertex || next_x == next_y || !graph.has_edge(next_x, next_y) ||
            graph.has_edge(x, next_x) || graph.has_edge(y, next_y) || graph.degree(x) >= 2 || graph.degree(y) >= 2)
          break;
        graph.remove(next_x, next_y);
        graph.add(x, next_x);
        graph.add(y, next_y);
        x = next_x;
        y = next_y;
      }
      continue;
    }
    if (a != no_vertex && !graph.has_edge(c, a) && graph.degree(c) < 2 && graph.degree(a) < 2) graph.add(c, a);  // C2
    if (b != no_vertex && (proposes(b, c) || proposes(b, a)) && !graph.has_edge(c, b) && graph.degree(c) < 2 &&
        graph.degree(b) < 2)
      graph.add(c, b);
  }
  return graph.edges();
}

Algorithm gathang_algorithm() {
  static const Parameter alpha{.name = "corner_angle", .default_value = 30, .minimum = 1, .maximum = 179,
                               .meaning = "minimum opening angle (degrees) of the sharp corners"};
  return {
      .name = "gathang",
      .title = "GathanG",
      .reference = "Dey, Wenger 2002",
      .category = "Sharp Corners",
      .parameters = {alpha},
      .capabilities = {.non_uniform = Support::yes, .open = Support::yes, .multiple = Support::yes,
                       .sharp = Support::yes, .guarantee = true, .time_complexity = "O(n log n)"},
      // The survey's table; see gathang.h for what is proven and what is measured.
      .condition = {.statement = "epsilon < 0.5, corner angle > 150 degrees",
                    .epsilon_below = 0.5,
                    .corner_angle_above = 150},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        return gathang_reconstruction(points, values[alpha]);
      }),
  };
}

}  // namespace curvebench::algorithms
