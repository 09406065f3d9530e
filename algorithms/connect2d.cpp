#include "algorithms/connect2d.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <queue>
#include <tuple>

#include "graphs/delaunay_triangulation.h"
#include "graphs/exact_length_order.h"

namespace curvebench::algorithms {
namespace {

using graphs::Delaunay_edge;
using graphs::Delaunay_triangulation;
using graphs::Edge_id;
using graphs::no_triangle;
using graphs::no_vertex;
using graphs::Vertex;
using Triangle = graphs::Triangle_id;

class Connect2d {
 public:
  // `dt` keeps its triangles (graphs::Keep_triangles::yes) and is not collinear.
  explicit Connect2d(const Delaunay_triangulation& dt)
      : dt_(dt), triangles_(dt.triangles()), rank_(dt.edges().size()), in_region_(triangles_.size(), false),
        region_degree_(dt.size(), 0), degree_(dt.size(), 0), on_hull_(dt.size(), false) {
    rank_edges();
    // A point has as many triangles as edges, one fewer on the hull, where it has two hull
    // edges and a fan between them. (The input is not collinear: see connect2d_reconstruction.)
    for (const Delaunay_edge& e : dt.edges()) {
      ++degree_[e.source], ++degree_[e.target];
      if (e.left == no_vertex || e.right == no_vertex) on_hull_[e.source] = on_hull_[e.target] = true;
    }
    for (Vertex v = 0; v < dt.size(); ++v) degree_[v] -= on_hull_[v];
  }

  void run() {
    mark_inside(boundary_complex());
    inflate();
    sculpt();
  }

  // The region's boundary: one simple cycle.
  std::vector<Edge> boundary() const {
    std::vector<Edge> result;
    for (Triangle t = 0; t < triangles_.size(); ++t)
      if (in_region_[t])
        for (int i = 0; i < 3; ++i)
          if (!in_region(triangles_[t].across[i]))
            result.emplace_back(triangles_[t].corners[(i + 1) % 3], triangles_[t].corners[(i + 2) % 3]);
    return geometry::canonical_edges(std::move(result));
  }

 private:
  // Ranks of the Delaunay edges in exact length order (ties by end indices): the keys of
  // every queue below.
  void rank_edges() {
    by_rank_ = graphs::edge_ids_by_exact_length(dt_.points(), dt_.edges());
    for (std::uint32_t r = 0; r < by_rank_.size(); ++r) rank_[by_rank_[r]] = r;
  }

  // Step 1: the EMST (Kruskal), then every edge, shortest first, with an end of valence < 2.
  std::vector<bool> boundary_complex() const {
    const auto edges = dt_.edges();
    std::vector<Vertex> parent(dt_.size());
    for (Vertex v = 0; v < dt_.size(); ++v) parent[v] = v;
    const auto root = [&](Vertex v) {
      while (parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    std::vector<bool> in_bc(edges.size(), false);
    std::vector<std::uint32_t> valence(dt_.size(), 0);
    const auto add = [&](Edge_id id) {
      in_bc[id] = true;
      ++valence[edges[id].source], ++valence[edges[id].target];
    };
    in_length_order(parent, [&](Edge_id id) {
      const Vertex a = root(edges[id].source), b = root(edges[id].target);
      if (a != b) parent[a] = b, add(id);
    });
    in_length_order(valence, [&](Edge_id id) {
      if (!in_bc[id] && (valence[edges[id].source] < 2 || valence[edges[id].target] < 2)) add(id);
    });
    return in_bc;
  }

  // Calls visit(id) for every edge, shortest first. In that order the edges, and then
  // their ends, are scattered: it starts loading the edge 16 ranks ahead, and what
  // `by_point` holds for the ends of the one 8 ahead. (The prefetches sit in this loop, not
  // in a lambda of their own: GCC deletes a call to a function that only prefetches.)
  template <class Visit>
  void in_length_order(const std::vector<std::uint32_t>& by_point, Visit visit) const {
    const auto edges = dt_.edges();
    const std::size_t count = by_rank_.size();
    for (std::size_t r = 0; r < count; ++r) {
      if (r + 16 < count) __builtin_prefetch(&edges[by_rank_[r + 16]]);
      if (r + 8 < count) {
        const Delaunay_edge& ahead = edges[by_rank_[r + 8]];
        __builtin_prefetch(&by_point[ahead.source]);
        __builtin_prefetch(&by_point[ahead.target]);
      }
      visit(by_rank_[r]);
    }
  }

  // Step 2: flood the triangles from the unbounded face across non-BC edges; the rest are
  // inside.
  void mark_inside(const std::vector<bool>& in_bc) {
    inside_.assign(triangles_.size(), true);
    std::vector<Triangle> stack;
    const auto reach = [&](Triangle t) {
      if (inside_[t]) inside_[t] = false, stack.push_back(t);
    };
    for (Triangle t = 0; t < triangles_.size(); ++t)
      for (int i = 0; i < 3; ++i)
        if (triangles_[t].across[i] == no_triangle && !in_bc[triangles_[t].sides[i]]) reach(t);
    while (!stack.empty()) {
      const Triangle t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Triangle u = triangles_[t].across[i];
        if (u != no_triangle && !in_bc[triangles_[t].sides[i]]) reach(u);
      }
    }
  }

  bool in_region(Triangle t) const { return t != no_triangle && in_region_[t]; }
  bool reached(Vertex v) const { return region_degree_[v] > 0; }
  bool interior(Vertex v) const { return !on_hull_[v] && region_degree_[v] == degree_[v]; }

  // The ranks of a triangle's sides, longest first: a key unique to the triangle (two
  // triangles share at most one side), so no tie depends on how triangles are numbered.
  using Sides = std::array<std::uint32_t, 3>;
  Sides sides_by_length(Triangle t) const {
    Sides r{rank_[triangles_[t].sides[0]], rank_[triangles_[t].sides[1]], rank_[triangles_[t].sides[2]]};
    std::sort(r.begin(), r.end(), std::greater<>());
    return r;
  }

  // How a triangle outside the region may join it: class 0 inside (either way below), 1
  // through one boundary edge with an apex new to the region, 2 through two consecutive
  // boundary edges (a notch); no_class if it would pinch the region or does not touch it.
  static constexpr int no_class = 3;
  int join_class(Triangle t) const {
    int touching = 0, side = 0;
    for (int i = 0; i < 3; ++i)
      if (in_region(triangles_[t].across[i])) ++touching, side = i;
    if (touching == 0 || touching == 3) return no_class;
    if (touching == 1 && reached(triangles_[t].corners[side])) return no_class;  // a pinch
    return inside_[t] ? 0 : touching;
  }

  // (class, sides longest first, triangle): smallest first.
  using Join = std::tuple<int, Sides, Triangle>;

  void offer(Triangle t, std::priority_queue<Join, std::vector<Join>, std::greater<>>& queue) const {
    if (t == no_triangle || in_region_[t]) return;
    if (const int c = join_class(t); c != no_class) queue.emplace(c, sides_by_length(t), t);
  }

  // Step 3.
  void inflate() {
    if (triangles_.size() == 0) return;
    Triangle seed = 0;
    for (Triangle t = 1; t < triangles_.size(); ++t)
      if (std::make_pair(!inside_[t], sides_by_length(t)) < std::make_pair(!inside_[seed], sides_by_length(seed)))
        seed = t;
    std::size_t outside = dt_.size();
    std::priority_queue<Join, std::vector<Join>, std::greater<>> queue;
    const auto add = [&](Triangle t) {
      in_region_[t] = true;
      for (int i = 0; i < 3; ++i)
        if (region_degree_[triangles_[t].corners[i]]++ == 0) --outside;
      for (int i = 0; i < 3; ++i) offer(triangles_[t].across[i], queue);
    };
    add(seed);
    while (!queue.empty()) {
      const auto [stored, key, t] = queue.top();
      if (outside == 0 && stored != 0) break;
      queue.pop();
      if (in_region_[t]) continue;
      // Entries go stale as the region grows: an apex joins (class 1 becomes a pinch) or a
      // second side touches (class 1 becomes 2). Take the current class.
      const int now = join_class(t);
      if (now == stored) {
        add(t);
      } else if (now != no_class) {
        queue.emplace(now, key, t);
      }
    }
  }

  // Step 4: (boundary edge rank, triangle, side), longest first.
  void sculpt() {
    using Cut = std::tuple<std::uint32_t, Triangle, int>;
    std::priority_queue<Cut> queue;
    std::size_t interior_points = 0;
    for (Vertex v = 0; v < dt_.size(); ++v) interior_points += interior(v);
    const auto offer_cut = [&](Triangle t, int i) {
      if (interior(triangles_[t].corners[i])) queue.emplace(rank_[triangles_[t].sides[i]], t, i);
    };
    for (Triangle t = 0; t < triangles_.size(); ++t)
      if (in_region_[t])
        for (int i = 0; i < 3; ++i)
          if (!in_region(triangles_[t].across[i])) offer_cut(t, i);
    while (interior_points > 0 && !queue.empty()) {
      const auto [key, t, i] = queue.top();
      queue.pop();
      // Once outside, a triangle stays outside, so the side stays a boundary edge; the apex
      // can only have reached the boundary meanwhile, and then stays there.
      if (!in_region_[t] || !interior(triangles_[t].corners[i])) continue;
      in_region_[t] = false;
      for (int k = 0; k < 3; ++k) --region_degree_[triangles_[t].corners[k]];
      --interior_points;  // the apex; the other two corners were on the boundary
      for (const int k : {(i + 1) % 3, (i + 2) % 3}) {
        const Triangle u = triangles_[t].across[k];  // in the region: the apex was interior
        for (int j = 0; j < 3; ++j)
          if (triangles_[u].across[j] == t) offer_cut(u, j);
      }
    }
  }

  const Delaunay_triangulation& dt_;
  std::span<const graphs::Delaunay_triangle> triangles_;
  std::vector<std::uint32_t> rank_;  // by edge id
  std::vector<Edge_id> by_rank_;
  std::vector<bool> inside_;     // by triangle
  std::vector<bool> in_region_;  // by triangle
  std::vector<std::uint32_t> region_degree_, degree_;  // region / all triangles at a point
  std::vector<bool> on_hull_;
};

}  // namespace

std::vector<Edge> connect2d_reconstruction(std::span<const Point> points) {
  const Delaunay_triangulation dt(points, graphs::Keep_triangles::yes);
  const bool collinear = std::none_of(dt.edges().begin(), dt.edges().end(),
                                      [](const Delaunay_edge& e) { return e.left != no_vertex || e.right != no_vertex; });
  if (collinear) {  // the chain (or nothing): no polygon exists
    std::vector<Edge> chain;
    for (const Delaunay_edge& e : dt.edges()) chain.emplace_back(e.source, e.target);
    return geometry::canonical_edges(std::move(chain));
  }
  Connect2d connect(dt);
  connect.run();
  return connect.boundary();
}

Algorithm connect2d_algorithm() {
  return {
      .name = "connect2d",
      .title = "Connect2D",
      .reference = "Ohrhallinger, Mudur 2013",
      .category = "Graph Based",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .noise = Support::yes, .outliers = Support::no,
                       .manifold = Support::yes, .open = Support::no, .multiple = Support::no,
                       .sharp = Support::yes, .guarantee = true, .time_complexity = "O(n log n)"},
      .condition = {.statement = "epsilon < 1/2, u < 1.609", .epsilon_below = 0.5, .uniformity_below = 1.609},
      .reconstruct = edges_on_input(connect2d_reconstruction),
  };
}

}  // namespace curvebench::algorithms
