#include "algorithms/discur.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <utility>

#include "graphs/delaunay_triangulation.h"
#include "graphs/exact_length_order.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using graphs::Delaunay_triangulation;
using graphs::no_vertex;
using graphs::Vertex;

// |ab| <= ratio |cd|, exactly: ratio^2 |cd|^2 - |ab|^2 >= 0 with ratio the given double.
bool within_ratio(const Point& a, const Point& b, double ratio, const Point& c, const Point& d) {
  using geometry::difference, geometry::squared_length;
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
           return NT(ratio) * NT(ratio) * squared_length(difference<NT>(d, c)) - squared_length(difference<NT>(b, a));
         }) != CGAL::NEGATIVE;
}

// Whether the path ... w -> p turns at p towards q by more than the angle whose cosine is
// `cosine`: cos(turn) = u.v / (|u||v|) < cosine with u = p - w, v = q - p, squared into a
// polynomial sign (the sign of u.v decides first).
bool turns_sharper(const Point& w, const Point& p, const Point& q, double cosine) {
  using geometry::difference, geometry::dot, geometry::exact_sign, geometry::squared_length;
  const CGAL::Sign dot_sign =
      exact_sign([&]<class NT>(std::type_identity<NT>) { return dot(difference<NT>(p, w), difference<NT>(q, p)); });
  if (cosine == 0) return dot_sign == CGAL::NEGATIVE;
  // (u.v)^2 against cosine^2 |u|^2 |v|^2.
  const CGAL::Sign excess = exact_sign([&]<class NT>(std::type_identity<NT>) {
    const auto u = difference<NT>(p, w), v = difference<NT>(q, p);
    const NT uv = dot(u, v);
    return uv * uv - NT(cosine) * NT(cosine) * squared_length(u) * squared_length(v);
  });
  if (cosine > 0) return dot_sign != CGAL::POSITIVE || excess == CGAL::NEGATIVE;
  return dot_sign == CGAL::NEGATIVE && excess == CGAL::POSITIVE;
}

// Each point's k nearest Delaunay neighbours (exact, ties to the smaller index), padded
// with no_vertex. The nearest neighbours of a point are among its Delaunay neighbours.
std::vector<Vertex> nearest_ranks(const Delaunay_triangulation& dt, std::size_t k) {
  std::vector<Vertex> ranked(dt.size() * k, no_vertex), scratch;
  for (Vertex v = 0; v < dt.size(); ++v) {
    const auto neighbors = dt.neighbors(v);
    scratch.assign(neighbors.begin(), neighbors.end());
    const std::size_t kept = std::min(k, scratch.size());
    std::partial_sort(scratch.begin(), scratch.begin() + kept, scratch.end(), [&](Vertex a, Vertex b) {
      return graphs::closer(dt.point(v), dt.point(a), a, dt.point(b), b);
    });
    std::copy_n(scratch.begin(), kept, ranked.begin() + v * k);
  }
  return ranked;
}

// The growing curves: each point's up to two links, and per path (a union-find root)
// one record of what the acceptance test and link() read, so that reaching a path costs
// one cache miss rather than one per field.
class Paths {
 public:
  explicit Paths(std::size_t n) : links_(n, {no_vertex, no_vertex}), parent_(n), paths_(n) {
    for (Vertex v = 0; v < n; ++v) {
      parent_[v] = v;
      paths_[v] = {.ends = {v, v}, .longest = {no_vertex, no_vertex}, .size = 1, .waited_at = {false, false}};
    }
  }

  // Starts loading what degree() and find() read of v. Edges come in length order, so
  // their ends are scattered and each first read of one would wait on memory.
  void prefetch(Vertex v) const {
    __builtin_prefetch(&links_[v]);
    __builtin_prefetch(&parent_[v]);
  }
  // The second stage, once prefetch(v) has had time: the record of v's parent, which after
  // path halving is mostly its root.
  void prefetch_path(Vertex v) const {
    __builtin_prefetch(&paths_[parent_[v]]);
    __builtin_prefetch(&parent_[parent_[v]]);
  }
  int degree(Vertex v) const { return (links_[v][0] != no_vertex) + (links_[v][1] != no_vertex); }
  Vertex end_neighbor(Vertex v) const { return links_[v][0]; }  // the one link of a degree-1 point
  Vertex find(Vertex v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  std::size_t size(Vertex root) const { return paths_[root].size; }
  const std::array<Vertex, 2>& ends(Vertex root) const { return paths_[root].ends; }
  const std::array<Vertex, 2>& longest(Vertex root) const { return paths_[root].longest; }  // no_vertex if none

  // Notes that edges wait at v, an end of its path (a point of degree 0 or 1).
  void mark_waiting(Vertex v) {
    Path& path = paths_[find(v)];
    for (int i : {0, 1})
      if (path.ends[i] == v) path.waited_at[i] = true;
  }
  // Whether edges wait at end i of root's path, which stops being so: the caller wakes them.
  bool take_waiting(Vertex root, int i) { return std::exchange(paths_[root].waited_at[i], false); }

  // Links a and b, which are ends of different paths or of the same one (closing it);
  // `longer` says whether edge ab is longer than an edge given as two points. Returns
  // the root of the merged path.
  template <class Longer>
  Vertex link(Vertex a, Vertex b, const Longer& longer) {
    links_[a][degree(a)] = b;
    links_[b][degree(b)] = a;
    const Vertex ra = find(a), rb = find(b);
    const Path &path_a = paths_[ra], &path_b = paths_[rb];
    std::array<Vertex, 2> longest = path_a.longest;
    if (longest[0] == no_vertex || (path_b.longest[0] != no_vertex && longer(path_b.longest, longest)))
      longest = path_b.longest;
    if (longest[0] == no_vertex || longer(std::array<Vertex, 2>{a, b}, longest)) longest = {a, b};
    if (ra == rb) {  // a cycle: no ends left
      paths_[ra] = {
          .ends = {no_vertex, no_vertex}, .longest = longest, .size = path_a.size, .waited_at = {false, false}};
      return ra;
    }
    // The merged path's ends: the far end of a's path, then that of b's.
    const int far_a = path_a.ends[0] == a ? 1 : 0, far_b = path_b.ends[0] == b ? 1 : 0;
    const Path merged{.ends = {path_a.ends[far_a], path_b.ends[far_b]},
                      .longest = longest,
                      .size = path_a.size + path_b.size,
                      .waited_at = {path_a.waited_at[far_a], path_b.waited_at[far_b]}};
    const auto [root, child] = path_a.size >= path_b.size ? std::pair{ra, rb} : std::pair{rb, ra};
    parent_[child] = root;
    paths_[root] = merged;
    return root;
  }

 private:
  struct alignas(32) Path {
    std::array<Vertex, 2> ends;        // no_vertex once closed
    std::array<Vertex, 2> longest;     // its longest edge, no_vertex if none
    Vertex size;                       // points
    std::array<bool, 2> waited_at;     // whether edges wait at ends[i]
  };
  std::vector<std::array<Vertex, 2>> links_;
  std::vector<Vertex> parent_;
  std::vector<Path> paths_;  // by root
};

void check(const Curve_growth_rules& rules) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!positive(rules.proximity_ratio) || rules.closing_rank < 1 || rules.closing_rank > 64 ||
      !(rules.turning_angle_degrees >= 0 && rules.turning_angle_degrees <= 180) ||
      (rules.turning_angle_degrees < 180 && !positive(rules.corner_ratio)))
    throw std::invalid_argument("grow_curves: rule out of range");
}

}  // namespace

std::vector<Edge> grow_curves(std::span<const Point> points, const Curve_growth_rules& rules) {
  check(rules);
  const Delaunay_triangulation dt(points);
  const std::size_t n = dt.size(), k = static_cast<std::size_t>(rules.closing_rank);
  const std::vector<Vertex> ranked = nearest_ranks(dt, k);
  const auto among_nearest = [&](Vertex v, Vertex w) {
    return std::find(ranked.begin() + v * k, ranked.begin() + (v + 1) * k, w) != ranked.begin() + (v + 1) * k;
  };

  // The Delaunay edges shortest first, sorted a stretch at a time and each time without
  // those that can no longer be taken (an end of degree two keeps it): on a sampled curve
  // the first n settle almost every point, and little of the other 2n is ever sorted.
  std::vector<graphs::Edge_with_length> sorted = graphs::with_lengths(dt.points(), dt.edges());
  std::size_t sorted_end = 0;
  const auto& at = [&](Vertex v) -> const Point& { return dt.point(v); };
  const auto longer = [&](const std::array<Vertex, 2>& e, const std::array<Vertex, 2>& f) {
    return graphs::compare_lengths(at(f[0]), at(f[1]), at(e[0]), at(e[1])) == CGAL::POSITIVE;
  };

  // A turn sharper than the rule's angle; its cosine is the double nearest cos(angle),
  // exactly 0 at 90 degrees.
  const bool continuity = rules.turning_angle_degrees < 180;
  const double cosine = rules.turning_angle_degrees == 90 ? 0.0 : std::cos(rules.turning_angle_degrees * std::numbers::pi / 180);

  Paths paths(n);
  // The criterion at end p of a path for the new edge pq: continuation (VICUR) only; the
  // proximity part is tested once for both ends.
  const auto continues = [&](Vertex p, Vertex q) {
    if (!continuity || paths.degree(p) != 1) return true;
    const Vertex w = paths.end_neighbor(p);
    return !turns_sharper(at(w), at(p), at(q), cosine) || within_ratio(at(p), at(q), rules.corner_ratio, at(w), at(p));
  };
  const auto near_enough = [&](Vertex p, Vertex q, Vertex root) {
    const auto& l = paths.longest(root);
    return l[0] != no_vertex && within_ratio(at(p), at(q), rules.proximity_ratio, at(l[0]), at(l[1]));
  };
  const auto accepts = [&](Vertex a, Vertex b) {
    const Vertex ra = paths.find(a), rb = paths.find(b);
    if (ra == rb) {  // closing a path into a cycle
      return paths.size(ra) >= 4 && among_nearest(a, b) && among_nearest(b, a) && near_enough(a, b, ra) &&
             continues(a, b) && continues(b, a);
    }
    if (paths.degree(a) == 0 && paths.degree(b) == 0) return true;  // nearest free points join
    return (near_enough(a, b, ra) || near_enough(a, b, rb)) && continues(a, b) && continues(b, a);
  };

  // Rejected edges wait at both ends, in intrusive lists of edge slots (2 e + side).
  std::vector<std::uint32_t> pending_head(n, no_vertex), pending_next(2 * sorted.size(), no_vertex);
  std::vector<bool> waiting(2 * sorted.size(), false);
  const auto wait = [&](std::uint32_t e) {
    for (const std::uint32_t side : {0u, 1u}) {
      const std::uint32_t slot = 2 * e + side;
      if (waiting[slot]) continue;
      const Vertex v = side == 0 ? sorted[e].source : sorted[e].target;
      waiting[slot] = true;
      pending_next[slot] = pending_head[v];
      pending_head[v] = slot;
      paths.mark_waiting(v);
    }
  };
  // Retried edges are shorter than every edge not yet taken, so they go first.
  std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<>> retry;
  const auto wake = [&](Vertex v) {
    for (std::uint32_t slot = pending_head[v]; slot != no_vertex; slot = pending_next[slot]) {
      waiting[slot] = false;
      retry.push(slot / 2);
    }
    pending_head[v] = no_vertex;
  };

  std::vector<Edge> edges;
  std::vector<bool> taken(sorted.size(), false);
  for (std::uint32_t next = 0;;) {
    std::uint32_t e;
    if (!retry.empty()) {
      e = retry.top();
      retry.pop();
    } else {
      if (next == sorted_end) {
        const auto closed = [&](const graphs::Edge_with_length& c) {
          return paths.degree(c.source) == 2 || paths.degree(c.target) == 2;
        };
        sorted.erase(std::remove_if(sorted.begin() + next, sorted.end(), closed), sorted.end());
        if (next == sorted.size()) break;
        sorted_end = graphs::sort_shortest_by_exact_length(dt.points(), sorted, next, std::max<std::size_t>(next, n));
      }
      e = next++;
      if (const std::uint32_t ahead = e + 16; ahead < sorted_end) {
        paths.prefetch(sorted[ahead].source);
        paths.prefetch(sorted[ahead].target);
        __builtin_prefetch(&at(sorted[ahead].source));
        __builtin_prefetch(&at(sorted[ahead].target));
      }
      if (const std::uint32_t ahead = e + 8; ahead < sorted_end) {
        paths.prefetch_path(sorted[ahead].source);
        paths.prefetch_path(sorted[ahead].target);
      }
    }
    const Vertex a = sorted[e].source, b = sorted[e].target;
    if (taken[e] || paths.degree(a) == 2 || paths.degree(b) == 2) continue;
    if (!accepts(a, b)) {
      wait(e);
      continue;
    }
    taken[e] = true;
    edges.emplace_back(a, b);
    const auto old_a = paths.longest(paths.find(a)), old_b = paths.longest(paths.find(b));
    const Vertex root = paths.link(a, b, longer);
    // An end whose path got a longer longest edge may now accept what it rejected. The
    // merged path's ends are (the far end of a's path, the far end of b's path).
    const auto [end_a, end_b] = paths.ends(root);
    // Paths know which of their ends have edges waiting, so a far end with none (most of
    // them) is not read: it would be a cache miss per link.
    if (end_a != no_vertex && paths.longest(root) != old_a && paths.take_waiting(root, 0)) wake(end_a);
    if (end_b != no_vertex && paths.longest(root) != old_b && paths.take_waiting(root, 1)) wake(end_b);
  }
  return geometry::canonical_edges(std::move(edges));
}

std::vector<Edge> discur_reconstruction(std::span<const Point> points) { return grow_curves(points, {}); }

Algorithm discur_algorithm() {
  return {
      .name = "discur",
      .title = "DISCUR",
      .reference = "Zeng, Nguyen, Yan, Li 2008",
      .category = "HVS Based",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::yes, .open = Support::yes,
                       .multiple = Support::yes, .sharp = Support::yes, .guarantee = true,
                       .time_complexity = "O(n log n)"},
      // The survey's table: a condition stated through the paper's vision function, with
      // no epsilon bound.
      .condition = {.statement = "vision function"},
      .reconstruct = edges_on_input(discur_reconstruction),
  };
}

}  // namespace curvebench::algorithms
