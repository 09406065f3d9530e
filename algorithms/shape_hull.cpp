#include "algorithms/shape_hull.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <tuple>

#include "graphs/delaunay_edge_index.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using graphs::Delaunay_edge;
using graphs::Delaunay_triangulation;
using graphs::no_vertex;
using graphs::Vertex;
using Edge_id = graphs::Delaunay_edge_index::Edge_id;

// A boundary edge waiting in the queue.
struct Queued {
  double squared_length;  // rounded: settles almost every comparison
  Edge_id edge;
};

// The queue's order, as a heap's "less": a is served after b if it is shorter (exact
// squared length), or as long with a larger (source, target).
class Served_after {
 public:
  explicit Served_after(const Delaunay_triangulation& dt) : dt_(&dt) {}
  bool operator()(const Queued& a, const Queued& b) const {
    const Delaunay_edge &ea = dt_->edges()[a.edge], &eb = dt_->edges()[b.edge];
    const CGAL::Sign s = graphs::compare_lengths(dt_->point(ea.source), dt_->point(ea.target), a.squared_length,
                                                 dt_->point(eb.source), dt_->point(eb.target), b.squared_length);
    return s == CGAL::POSITIVE || (s == CGAL::ZERO && std::tie(ea.source, ea.target) > std::tie(eb.source, eb.target));
  }

 private:
  const Delaunay_triangulation* dt_;
};

// Which triangles of an edge are still in the region: one bit per side.
enum Side : std::uint8_t { left_side = 1, right_side = 2 };

class Sculpture {
 public:
  explicit Sculpture(const Delaunay_triangulation& dt)
      : dt_(dt), edges_(dt.edges()), index_(dt), sides_(edges_.size(), 0), on_boundary_(dt.size(), false),
        served_after_(dt) {
    for (Edge_id id = 0; id < edges_.size(); ++id) {
      const Delaunay_edge& e = edges_[id];
      sides_[id] = (e.left != no_vertex ? left_side : 0) | (e.right != no_vertex ? right_side : 0);
    }
    for (Edge_id id = 0; id < edges_.size(); ++id)
      if (is_boundary(id)) {
        on_boundary_[edges_[id].source] = on_boundary_[edges_[id].target] = true;
        queue_if_obtuse(id);
      }
    std::make_heap(queue_.begin(), queue_.end(), served_after_);
  }

  void run() {
    while (!queue_.empty()) {
      std::pop_heap(queue_.begin(), queue_.end(), served_after_);
      const Edge_id id = queue_.back().edge;
      queue_.pop_back();
      // Still a boundary edge with the same triangle (see the header): only the apex can
      // have changed, by joining the boundary, and then the edge stays for good.
      const Vertex r = remaining_apex(id);
      if (!on_boundary_[r]) remove_triangle(id, r);
    }
  }

  // The region's boundary edges; collinear input (no triangle at all) gives its chain.
  std::vector<Edge> boundary() const {
    const bool collinear = std::none_of(edges_.begin(), edges_.end(),
                                        [](const Delaunay_edge& e) { return e.left != no_vertex || e.right != no_vertex; });
    std::vector<Edge> result;
    for (Edge_id id = 0; id < edges_.size(); ++id)
      if (collinear || is_boundary(id)) result.emplace_back(edges_[id].source, edges_[id].target);
    return geometry::canonical_edges(std::move(result));
  }

 private:
  bool is_boundary(Edge_id id) const { return sides_[id] == left_side || sides_[id] == right_side; }
  Vertex remaining_apex(Edge_id id) const { return sides_[id] == left_side ? edges_[id].left : edges_[id].right; }

  // Appends boundary edge `id` to the queue's array if the angle at its remaining
  // triangle's apex is obtuse (the geometric criterion, which cannot change while the edge
  // waits); true if it did.
  bool queue_if_obtuse(Edge_id id) {
    const Delaunay_edge& e = edges_[id];
    const Point &p = dt_.point(e.source), &q = dt_.point(e.target);
    if (graphs::angle_sign(p, q, dt_.point(remaining_apex(id))) != CGAL::NEGATIVE) return false;
    queue_.push_back({geometry::squared_distance_approximation(p, q), id});
    return true;
  }

  // Removes triangle pqr through boundary edge `id` = pq; r is interior, so pr and qr had
  // both their triangles and now keep one.
  void remove_triangle(Edge_id id, Vertex r) {
    sides_[id] = 0;
    const Vertex p = edges_[id].source, q = edges_[id].target;
    for (const auto& [end, third] : {std::pair{p, q}, std::pair{q, p}}) {
      const Edge_id f = index_.find(end, r);
      sides_[f] &= edges_[f].left == third ? right_side : left_side;
      if (queue_if_obtuse(f)) std::push_heap(queue_.begin(), queue_.end(), served_after_);
    }
    on_boundary_[r] = true;
  }

  const Delaunay_triangulation& dt_;
  std::span<const Delaunay_edge> edges_;
  graphs::Delaunay_edge_index index_;
  std::vector<std::uint8_t> sides_;
  std::vector<bool> on_boundary_;
  Served_after served_after_;
  std::vector<Queued> queue_;  // a heap by served_after_
};

}  // namespace

std::vector<Edge> shape_hull_reconstruction(std::span<const Point> points) {
  const Delaunay_triangulation dt(points);
  Sculpture sculpture(dt);
  sculpture.run();
  return sculpture.boundary();
}

Algorithm shape_hull_algorithm() {
  return {
      .name = "shape-hull",
      .title = "Shape-hull graph",
      .reference = "Peethambaran, Muthuganapathy 2015",
      .category = "Graph Based",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::yes, .sharp = Support::yes,
                       .time_complexity = "O(n log n)"},
      .condition = {.statement = "none"},
      .reconstruct = edges_on_input(shape_hull_reconstruction),
  };
}

}  // namespace curvebench::algorithms
