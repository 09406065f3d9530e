#include "algorithms/optimal_transport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <boost/heap/d_ary_heap.hpp>

#include "geometry/bounding_box_diagonal.h"
#include "geometry/edge.h"
#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using Kernel = geometry::Kernel;
// A vertex, and a sample: the index of its point in the sorted, merged input.
using Index = std::uint32_t;
constexpr Index none = std::numeric_limits<Index>::max();
using Index_pair = std::pair<Index, Index>;

std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

bool contains(std::span<const Index> list, Index v) { return std::find(list.begin(), list.end(), v) != list.end(); }

// The triangulation of the vertices not yet removed: CGAL's Delaunay triangulation, or the
// chain of consecutive points where the input is collinear (CGAL inserts collinear points
// in quadratic time). CGAL's may itself become a line when removals leave collinear points.
class Mesh {
 public:
  // `points` sorted and distinct.
  explicit Mesh(std::span<const Point> points) : handles_(points.size()) {
    if (graphs::all_collinear(points)) {  // sorted collinear points are in order along their line
      chain_ = true;
      previous_.resize(points.size());
      next_.resize(points.size());
      for (Index i = 0; i < points.size(); ++i) {
        previous_[i] = i == 0 ? none : i - 1;
        next_[i] = i + 1 == points.size() ? none : i + 1;
      }
      return;
    }
    std::vector<std::pair<Point, Index>> indexed;
    indexed.reserve(points.size());
    for (Index i = 0; i < points.size(); ++i) indexed.emplace_back(points[i], i);
    CGAL::spatial_sort(indexed.begin(), indexed.end(),
                       CGAL::Spatial_sort_traits_adapter_2<Kernel, CGAL::First_of_pair_property_map<std::pair<Point, Index>>>());
    Triangulation::Face_handle hint;
    for (const auto& [point, index] : indexed) {
      const auto v = dt_.insert(point, hint);
      v->info() = index;
      handles_[index] = v;
      hint = v->face();
    }
  }

  // Whether the vertices span the plane (else they lie on a line).
  bool planar() const { return !chain_ && dt_.dimension() == 2; }

  // The finite neighbours of v, counterclockwise.
  void neighbours(Index v, std::vector<Index>& out) const {
    out.clear();
    if (chain_) {
      if (previous_[v] != none) out.push_back(previous_[v]);
      if (next_[v] != none) out.push_back(next_[v]);
      return;
    }
    auto c = dt_.incident_vertices(handles_[v]), done = c;
    if (c == nullptr) return;
    do
      if (!dt_.is_infinite(c)) out.push_back(c->info());
    while (++c != done);
  }

  // Where the samples of v's edges can go when v is removed: `ring` lists v's neighbours
  // counterclockwise and `closed` says whether they surround it. On the hull, the chain
  // runs from the neighbour after the outside to the one before it. On a line, v's two
  // neighbours; at an end of the line, its neighbour and that one's other neighbour.
  void link(Index v, std::vector<Index>& ring, bool& closed) const {
    ring.clear();
    closed = false;
    if (!planar()) {
      neighbours(v, ring);
      if (ring.size() == 1) {
        std::vector<Index> beyond;
        neighbours(ring[0], beyond);
        for (const Index w : beyond)
          if (w != v) ring.push_back(w);
      }
      return;
    }
    auto c = dt_.incident_vertices(handles_[v]), done = c;
    std::size_t outside = none;
    do {
      if (dt_.is_infinite(c))
        outside = ring.size();
      else
        ring.push_back(c->info());
    } while (++c != done);
    closed = outside == none;
    if (!closed) std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(outside), ring.end());
  }

  void remove(Index v) {
    if (!chain_) return dt_.remove(handles_[v]);
    if (previous_[v] != none) next_[previous_[v]] = next_[v];
    if (next_[v] != none) previous_[next_[v]] = previous_[v];
  }

  // Appends each edge between two vertices of `ring`, once, smaller index first.
  void edges_among(std::span<const Index> ring, std::vector<Index_pair>& out) const {
    std::vector<Index> around;
    for (const Index w : ring) {
      neighbours(w, around);
      for (const Index x : around)
        if (w < x && contains(ring, x)) out.emplace_back(w, x);
    }
  }

  // Appends the vertices whose link reads edge (a, b) besides a and b: the apexes of its
  // triangles; on a line, the neighbours of a and b (an end reads its neighbour's edge).
  void readers(Index a, Index b, std::vector<Index>& out) const {
    if (!planar()) {
      std::vector<Index> around;
      for (const Index v : {a, b}) {
        neighbours(v, around);
        out.insert(out.end(), around.begin(), around.end());
      }
      return;
    }
    Triangulation::Face_handle face;
    int i = 0;
    if (!dt_.is_edge(handles_[a], handles_[b], face, i)) return;
    for (const auto& apex : {face->vertex(i), dt_.mirror_vertex(face, i)})
      if (!dt_.is_infinite(apex)) out.push_back(apex->info());
  }

 private:
  using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<Index, Kernel>;
  using Triangulation = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vertex_base>>;

  bool chain_ = false;
  Triangulation dt_;
  std::vector<Triangulation::Vertex_handle> handles_;
  std::vector<Index> previous_, next_;  // the chain
};

// Appends the diagonals of the Delaunay triangulation of a polygon (counterclockwise, its
// closing edge polygon.back() -> polygon.front()), as a Delaunay removal fills a hole: the
// apex over the closing edge is the vertex left of it whose circle through the edge holds
// no other vertex left of it; then each side is filled the same way.
void fill_polygon(std::span<const Point> points, std::span<const Index> polygon, std::vector<Index_pair>& diagonals) {
  if (polygon.size() < 4) return;
  const Point& b = points[polygon.back()];
  const Point& a = points[polygon.front()];
  std::size_t apex = 1;
  for (std::size_t j = 2; j + 1 < polygon.size(); ++j) {
    const Point& candidate = points[polygon[j]];
    if (CGAL::orientation(b, a, candidate) != CGAL::LEFT_TURN) continue;
    if (CGAL::orientation(b, a, points[polygon[apex]]) != CGAL::LEFT_TURN ||
        CGAL::side_of_oriented_circle(b, a, points[polygon[apex]], candidate) == CGAL::ON_POSITIVE_SIDE)
      apex = j;
  }
  if (apex > 1) diagonals.emplace_back(polygon.front(), polygon[apex]);
  if (apex + 2 < polygon.size()) diagonals.emplace_back(polygon[apex], polygon.back());
  fill_polygon(points, polygon.first(apex + 1), diagonals);
  fill_polygon(points, polygon.subspan(apex), diagonals);
}

// Appends the edges a Delaunay removal of a hull vertex adds: the new hull over its chain
// of neighbours (`chain`, counterclockwise around it), and the fill of each pocket
// between that hull and the chain.
void fill_hull_pockets(std::span<const Point> points, std::span<const Index> chain, std::vector<Index_pair>& edges) {
  std::vector<std::size_t> hull;
  for (std::size_t m = 0; m < chain.size(); ++m) {
    while (hull.size() >= 2 && CGAL::orientation(points[chain[hull[hull.size() - 2]]], points[chain[hull.back()]],
                                                 points[chain[m]]) == CGAL::LEFT_TURN)
      hull.pop_back();
    hull.push_back(m);
  }
  for (std::size_t h = 0; h + 1 < hull.size(); ++h) {
    if (hull[h + 1] == hull[h] + 1) continue;  // a chain edge stays on the hull
    edges.emplace_back(chain[hull[h]], chain[hull[h + 1]]);
    fill_polygon(points, chain.subspan(hull[h], hull[h + 1] - hull[h] + 1), edges);
  }
}

// How an edge transports the samples assigned to it (survey, "Non-manifold
// Reconstruction"; de Goes et al.): spread uniformly along it, at the normal plus
// tangential cost, or each to its nearer end, whichever costs less.
struct Edge_plan {
  std::vector<Index> samples;
  double cost = 0;
  double normal = 0;  // the samples' squared distances to the edge's line, by mass
  bool regular = false;
  bool feeds_first = false, feeds_second = false;  // ghost: the smaller / larger end receives mass
};

// The greedy simplification over the sorted, merged input.
class Simplification {
 public:
  using Hole_search = Optimal_transport_options::Hole_search;
  // With `greedy` false, nothing is simulated: the vertices to remove come from replay.
  Simplification(std::span<const Point> points, std::span<const double> masses, Hole_search search, bool greedy = true)
      : points_(points), masses_(masses), mesh_(points), regular_(points.size()), fed_(points.size()),
        alive_(points.size(), true), handles_(points.size()), alive_count_(points.size()), greedy_(greedy),
        search_(search) {
    scale_coordinates();
    assign_to_nearest_neighbours();
    if (greedy_)
      for (Index v = 0; v < points_.size(); ++v) handles_[v] = queue_.push({removal_cost_change(v), v});
  }

  // Removes `vertices` in order, as a greedy run removed them: its state after as many steps.
  void replay(std::span<const Index> vertices) {
    for (const Index v : vertices) remove(v);
  }
  // The vertices run() removed, in order.
  std::span<const Index> removals() const { return removals_; }

  // Removes vertices, cheapest first, until `options` says stop. The default stop (neither
  // option set) is the first state without isolated vertices; if that state has a
  // branching vertex, the run goes on to the first state with no defect at all, as long as
  // the total cost stays within twice that state's. The caller then goes back to the first
  // state with the fewest defects the run passed through.
  void run(const Optimal_transport_options& options) {
    const double mass = std::accumulate(masses_.begin(), masses_.end(), 0.0);
    const double diagonal = geometry::bounding_box_diagonal(scaled_points_);
    const double budget = options.tolerance * options.tolerance * diagonal * diagonal * mass;
    const bool default_stop = options.vertices == 0 && options.tolerance == 0;
    double settled = -1;  // the cost of the first state without isolated vertices
    fewest_defects_ = defects(), vertices_at_fewest_ = alive_count_;
    while (alive_count_ > 2 && !queue_.empty()) {
      if (options.vertices > 0 && alive_count_ <= options.vertices) break;
      if (default_stop && defects() == 0) break;
      if (default_stop && isolated_ == 0 && settled < 0) settled = total_cost_;
      const Removal next = queue_.top();
      if (!std::isfinite(next.cost_change)) break;
      if (options.tolerance > 0 && total_cost_ + next.cost_change > budget) break;
      if (settled >= 0 && total_cost_ + next.cost_change > 2 * settled) break;
      queue_.pop();
      remove(next.vertex);
      removals_.push_back(next.vertex);
      if (defects() < fewest_defects_) fewest_defects_ = defects(), vertices_at_fewest_ = alive_count_;
    }
  }

  // Of the states run() passed through, the vertex count of the first with the fewest
  // defects.
  std::size_t vertices_at_fewest_defects() const { return vertices_at_fewest_; }
  // Vertices with mass on no regular edge (isolated) or on three or more (branching): the
  // default stop looks for the first state with none.
  std::ptrdiff_t defects() const { return isolated_ + branching_; }

  // The output: the regular edges and the vertices with mass, in index order. With
  // `close_gaps` (the default stop), also the gaps in the regular chains: at the default
  // stop the greedy order has often grown two chains towards each other and stopped with a
  // ghost edge, or no edge that carries samples, between their ends. A gap is an edge of
  // the triangulation between two chain ends (vertices on one regular edge) at most 3/2 as
  // long as the longer chain edge at its ends; gaps are drawn shortest first, each end
  // once. The chord between the two ends of an open arc is longer than that unless the arc
  // almost closes, and stays undrawn. Lengths are compared exactly; equal lengths go to the
  // smaller pair. The bound 3/2 was chosen on the sampling, open-curves, multiple-curves and
  // rounded-corners suites: 2 closed a third more of the open arcs, and joining chains
  // before closing any, or a tighter bound for joining, changed nothing there.
  Reconstruction result(bool close_gaps) const {
    std::vector<Index> renumbered(points_.size(), none);
    Reconstruction out;
    for (Index v = 0; v < points_.size(); ++v)
      if (alive_[v] && (regular_[v] > 0 || fed_[v] > 0)) {
        renumbered[v] = static_cast<Index>(out.points.size());
        out.points.push_back(points_[v]);
      }
    std::vector<Index> neighbour(points_.size(), none);  // a chain end's one regular neighbour
    for (const auto& [key, plan] : plans_)
      if (plan.regular) {
        const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
        out.edges.push_back({renumbered[a], renumbered[b]});
        neighbour[a] = b, neighbour[b] = a;
      }
    if (close_gaps) {
      const auto is_end = [&](Index v) { return alive_[v] && regular_[v] == 1; };
      std::vector<Index_pair> gaps;
      std::vector<Index> around;
      for (Index a = 0; a < points_.size(); ++a) {
        if (!is_end(a)) continue;
        mesh_.neighbours(a, around);
        for (const Index b : around)
          if (a < b && is_end(b) && neighbour[a] != b && gap_fits(a, b, neighbour[a], neighbour[b])) gaps.emplace_back(a, b);
      }
      std::sort(gaps.begin(), gaps.end(), [&](const Index_pair& x, const Index_pair& y) {
        const CGAL::Sign order = graphs::compare_lengths(points_[x.first], points_[x.second], points_[y.first], points_[y.second]);
        return order == CGAL::POSITIVE || (order == CGAL::ZERO && x < y);
      });
      std::vector<int> degree(regular_);
      for (const auto& [a, b] : gaps)
        if (degree[a] == 1 && degree[b] == 1) {
          ++degree[a], ++degree[b];
          out.edges.push_back({renumbered[a], renumbered[b]});
        }
    }
    out.edges = geometry::canonical_edges(std::move(out.edges));
    return out;
  }

  // Whether gap ab, between chain ends a and b whose chain neighbours are a2 and b2, is at
  // most 3/2 as long as the longer of edges a a2 and b b2: 4 |ab|^2 <= 9 |cc2|^2, exactly.
  bool gap_fits(Index a, Index b, Index a2, Index b2) const {
    const bool b_longer = graphs::compare_lengths(points_[a], points_[a2], points_[b], points_[b2]) == CGAL::POSITIVE;
    const Point& c = points_[b_longer ? b : a];
    const Point& c2 = points_[b_longer ? b2 : a2];
    using geometry::difference, geometry::squared_length;
    return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
             return NT(9) * squared_length(difference<NT>(c2, c)) - NT(4) * squared_length(difference<NT>(points_[b], points_[a]));
           }) != CGAL::NEGATIVE;
  }

  // The total transport cost, in the input's squared units, summed in edge order.
  double cost() const {
    std::vector<std::pair<std::uint64_t, double>> costs;
    for (const auto& [key, plan] : plans_) costs.emplace_back(key, plan.cost);
    std::sort(costs.begin(), costs.end());
    double total = 0;
    for (const auto& [key, cost] : costs) total += cost;
    return std::ldexp(total, 2 * exponent_);
  }
  std::size_t vertices() const { return alive_count_; }

 private:
  struct Removal {
    double cost_change;
    Index vertex;
  };
  // The top is the smallest cost change, the smaller vertex on equal costs.
  struct Later {
    bool operator()(const Removal& x, const Removal& y) const {
      return x.cost_change > y.cost_change || (x.cost_change == y.cost_change && x.vertex > y.vertex);
    }
  };
  using Queue = boost::heap::d_ary_heap<Removal, boost::heap::arity<4>, boost::heap::mutable_<true>,
                                        boost::heap::compare<Later>>;

  // Costs are computed on the points scaled by a power of two (exact) into [-1, 1]^2, so
  // that squared distances neither overflow nor underflow at any input scale.
  void scale_coordinates() {
    double largest = 0;
    for (const Point& p : points_) largest = std::max({largest, std::abs(p.x()), std::abs(p.y())});
    if (largest > 0) std::frexp(largest, &exponent_);
    scaled_.reserve(points_.size());
    for (const Point& p : points_) scaled_.push_back({std::ldexp(p.x(), -exponent_), std::ldexp(p.y(), -exponent_)});
    for (const auto& [x, y] : scaled_) scaled_points_.emplace_back(x, y);
  }

  // The start: each sample on the edge to its nearest neighbour (exact; the smaller index
  // on a tie), where every edge sends its samples to their own vertices at cost 0.
  void assign_to_nearest_neighbours() {
    std::vector<Index> around;
    for (Index v = 0; v < points_.size(); ++v) {
      mesh_.neighbours(v, around);
      Index nearest = none;
      for (const Index w : around)
        if (nearest == none || CGAL::compare_distance_to_point(points_[v], points_[w], points_[nearest]) == CGAL::SMALLER ||
            (w < nearest && CGAL::compare_distance_to_point(points_[v], points_[w], points_[nearest]) == CGAL::EQUAL))
          nearest = w;
      if (nearest != none) plans_[edge_key(v, nearest)].samples.push_back(v);
    }
    std::vector<std::uint64_t> keys;
    for (const auto& [key, plan] : plans_) keys.push_back(key);
    std::sort(keys.begin(), keys.end());
    for (const std::uint64_t key : keys) {
      Edge_plan& plan = plans_[key];
      evaluate(static_cast<Index>(key >> 32), static_cast<Index>(key & 0xffffffffu), plan, true);
      count(static_cast<Index>(key >> 32), static_cast<Index>(key & 0xffffffffu), plan, +1);
      total_cost_ += plan.cost;
    }
  }

  // Sets plan's cost and kind for edge (a, b), a < b; with `feeds`, which ends a ghost
  // edge sends mass to (exact comparisons; the smaller end on a tie).
  void evaluate(Index a, Index b, Edge_plan& plan, bool feeds) {
    const auto [ax, ay] = scaled_[a];
    const double dx = scaled_[b][0] - ax, dy = scaled_[b][1] - ay;
    const double length = std::sqrt(dx * dx + dy * dy);
    double normal = 0, ghost = 0, mass = 0;
    along_.clear();
    for (const Index s : plan.samples) {
      const double ux = scaled_[s][0] - ax, uy = scaled_[s][1] - ay;
      const double vx = scaled_[s][0] - scaled_[b][0], vy = scaled_[s][1] - scaled_[b][1];
      const double across = (dx * uy - dy * ux) / length;
      normal += masses_[s] * across * across;
      ghost += masses_[s] * std::min(ux * ux + uy * uy, vx * vx + vy * vy);
      mass += masses_[s];
      along_.emplace_back((dx * ux + dy * uy) / length, s);
    }
    // The tangential cost: along the edge, sample i (sorted) takes the interval
    // [c, c + w) of the uniform measure, w = m_i L / M, at cost m_i (x^2 + x w + w^2 / 3)
    // with x = c - t_i, the integral of the squared distance from t_i over it.
    std::sort(along_.begin(), along_.end());
    double tangential = 0, start = 0;
    for (const auto& [t, s] : along_) {
      const double width = masses_[s] * length / mass, x = start - t;
      tangential += masses_[s] * (x * x + x * width + width * width / 3);
      start += width;
    }
    const double regular = normal + tangential;
    plan.normal = normal;
    plan.regular = regular < ghost;
    plan.cost = plan.regular ? regular : ghost;
    plan.feeds_first = plan.feeds_second = false;
    if (!feeds || plan.regular) return;
    for (const Index s : plan.samples)
      (CGAL::compare_distance_to_point(points_[s], points_[a], points_[b]) == CGAL::LARGER ? plan.feeds_second
                                                                                          : plan.feeds_first) = true;
  }

  bool isolated(Index v) const { return alive_[v] && regular_[v] == 0 && fed_[v] > 0; }
  bool branching(Index v) const { return alive_[v] && regular_[v] > 2; }

  // Adds (+1) or takes away (-1) what plan gives its ends: a regular edge, or mass.
  void count(Index a, Index b, const Edge_plan& plan, int sign) {
    isolated_ -= isolated(a) + isolated(b);
    branching_ -= branching(a) + branching(b);
    if (plan.regular) {
      regular_[a] += sign, regular_[b] += sign;
    } else {
      if (plan.feeds_first) fed_[a] += sign;
      if (plan.feeds_second) fed_[b] += sign;
    }
    isolated_ += isolated(a) + isolated(b);
    branching_ += branching(a) + branching(b);
  }

  // The squared distance to segment (a, b) from a point, in scaled coordinates; the
  // segment's differences computed once for the many samples measured against it.
  struct Segment_distance {
    double ax, ay, bx, by, dx, dy, length2;
    Segment_distance(const std::array<double, 2>& a, const std::array<double, 2>& b)
        : ax(a[0]), ay(a[1]), bx(b[0]), by(b[1]), dx(bx - ax), dy(by - ay), length2(dx * dx + dy * dy) {}
    double operator()(const std::array<double, 2>& p) const {
      const double ux = p[0] - ax, uy = p[1] - ay;
      const double dot = dx * ux + dy * uy;
      if (dot <= 0) return ux * ux + uy * uy;
      if (dot >= length2) return (p[0] - bx) * (p[0] - bx) + (p[1] - by) * (p[1] - by);
      const double across = dx * uy - dy * ux;
      return across * across / length2;
    }
  };
  double squared_distance(Index s, Index a, Index b) const { return Segment_distance(scaled_[a], scaled_[b])(scaled_[s]); }

  // Gives each orphan the nearest of `edges_` (the earlier edge on a tie): bucket_[k]
  // lists those of edge k.
  void assign_orphans() {
    buckets_.resize(edges_.size());
    for (auto& bucket : buckets_) bucket.clear();
    segments_.clear();
    for (const auto& [a, b] : edges_) segments_.emplace_back(scaled_[a], scaled_[b]);
    for (const Index s : orphans_) {
      std::size_t best = 0;
      double nearest = INFINITY;
      for (std::size_t k = 0; k < segments_.size(); ++k)
        if (const double d = segments_[k](scaled_[s]); d < nearest) nearest = d, best = k;
      buckets_[best].push_back(s);
    }
  }

  // assign_orphans for the hole of a vertex of many neighbours (ring_, `closed` as link
  // gives it), filled from the Delaunay triangulation of the ring: the hole's triangles are
  // its triangles left of the ring, those whose corners run counterclockwise in ring order,
  // since every ring edge is one of its edges (a Delaunay edge stays one in any subset of
  // the points that holds its ends). Each orphan's nearest hole edge is then found by a
  // best-first walk over the ring's triangles from the one holding it (from outside their
  // hull, the one across the hull edge it sees), nearest triangle first, until the next is
  // farther than the best edge: the triangles within any distance of a point are those
  // meeting a convex set, so they are connected, and the walk misses none. Ties go to the earlier edge, as in
  // assign_orphans. This replaces an O(d^2) fill and O(d) edges per orphan where the fans
  // of long edges across a convex arc give a ring hundreds of vertices. False, with nothing
  // set, where cocircular points leave a ring edge out of the ring's triangulation; the
  // caller then fills the hole by fill_polygon or fill_hull_pockets.
  bool assign_in_ring_triangulation(bool closed) {
    using Face = Ring_triangulation::Face_handle;
    const auto d = static_cast<Index>(ring_.size());
    ring_points_.clear();
    for (Index i = 0; i < d; ++i) ring_points_.emplace_back(points_[ring_[i]], i);
    Ring_triangulation dt(ring_points_.begin(), ring_points_.end());
    if (dt.dimension() != 2) return false;
    std::vector<Ring_triangulation::Vertex_handle> at(d);
    for (const auto v : dt.finite_vertex_handles()) at[v->info()] = v;
    for (Index i = 0; i + 1 < d || (closed && i < d); ++i)
      if (!dt.is_edge(at[i], at[(i + 1) % d])) return false;
    const auto in_hole = [&](Face f) {
      if (dt.is_infinite(f)) return false;
      const Index i = f->vertex(0)->info(), j = f->vertex(1)->info(), k = f->vertex(2)->info();
      return (j + d - i) % d < (k + d - i) % d;
    };
    // Edge e of face f: between its corners e + 1 and e + 2, opposite corner e (CGAL's numbering).
    const auto edge = [&](Face f, int e) {
      return std::minmax(ring_[f->vertex((e + 1) % 3)->info()], ring_[f->vertex((e + 2) % 3)->info()]);
    };
    // A side is a hole edge if a triangle on either side of it is in the hole, or it is a
    // ring edge (on the hull, a chain edge can bound no triangle of the hole).
    for (const Face f : dt.finite_face_handles()) f->info() = {in_hole(f), 0};
    const auto is_hole_edge = [&](Face f, int e) {
      const Face g = f->neighbor(e);
      if (f->info().in_hole || (!dt.is_infinite(g) && g->info().in_hole)) return true;
      const Index i = f->vertex((e + 1) % 3)->info(), j = f->vertex((e + 2) % 3)->info();
      const Index low = std::min(i, j), high = std::max(i, j);
      return high == low + 1 || (closed && low == 0 && high == d - 1);
    };
    Face hint;
    std::size_t stamp = 0;
    std::vector<std::pair<double, Face>> frontier;  // a min-heap on distance
    const auto farther = [](const auto& x, const auto& y) { return x.first > y.first; };
    assigned_.clear();
    for (const Index s : orphans_) {
      Ring_triangulation::Locate_type type;
      int li = 0;
      Face start = dt.locate(points_[s], type, li, hint);
      hint = start;
      const bool holds = !dt.is_infinite(start);
      if (!holds) start = start->neighbor(start->index(dt.infinite_vertex()));
      ++stamp;
      Index_pair best{none, none};
      double nearest = INFINITY;
      // Visits face f: offers its hole edges, and returns its distance from the sample.
      // Ties go to the smaller edge (pairs of indices, smaller first), as in assign_orphans.
      const auto visit = [&](Face f) {
        f->info().visited = stamp;
        double distance = INFINITY;
        for (int e = 0; e < 3; ++e) {
          const Index_pair pair = edge(f, e);
          const double to_edge = squared_distance(s, pair.first, pair.second);
          distance = std::min(distance, to_edge);
          if ((to_edge < nearest || (to_edge == nearest && pair < best)) && is_hole_edge(f, e)) nearest = to_edge, best = pair;
        }
        return distance;
      };
      frontier.clear();
      const double start_distance = visit(start);
      frontier.emplace_back(holds ? 0.0 : start_distance, start);
      while (!frontier.empty() && frontier.front().first <= nearest) {
        std::pop_heap(frontier.begin(), frontier.end(), farther);
        const Face f = frontier.back().second;
        frontier.pop_back();
        for (int e = 0; e < 3; ++e) {
          const Face g = f->neighbor(e);
          if (dt.is_infinite(g) || g->info().visited == stamp) continue;
          frontier.emplace_back(visit(g), g);
          std::push_heap(frontier.begin(), frontier.end(), farther);
        }
      }
      assigned_.emplace_back(best, s);
    }
    // edges_ and buckets_ as assign_orphans leaves them, for the edges that receive samples.
    std::stable_sort(assigned_.begin(), assigned_.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    edges_.clear();
    for (const auto& [receiving, sample] : assigned_) {
      if (edges_.empty() || edges_.back() != receiving) {
        edges_.push_back(receiving);
        if (buckets_.size() < edges_.size()) buckets_.emplace_back();
        buckets_[edges_.size() - 1].clear();
      }
      buckets_[edges_.size() - 1].push_back(sample);
    }
    buckets_.resize(edges_.size());
    return true;
  }

  // Collects the samples of v's edges into orphans_ (the link in ring_), with their cost.
  double gather_orphans(Index v) {
    orphans_.clear();
    double cost = 0;
    for (const Index w : ring_)
      if (const auto it = plans_.find(edge_key(v, w)); it != plans_.end()) {
        orphans_.insert(orphans_.end(), it->second.samples.begin(), it->second.samples.end());
        cost += it->second.cost;
      }
    return cost;
  }

  // Sorts and dedupes edges_ (each smaller index first) so that ties go to the smaller edge.
  void canonical_edge_list() {
    for (auto& [a, b] : edges_)
      if (a > b) std::swap(a, b);
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  }

  // The change of total cost if v were removed: its edges' samples going to the nearest
  // edge of its hole filled as a Delaunay removal fills it, or of the neighbours' chain.
  // Infinite where the samples would have nowhere to go.
  double removal_cost_change(Index v) {
    bool closed = false;
    mesh_.link(v, ring_, closed);
    const double old_cost = gather_orphans(v);
    if (orphans_.empty()) return 0;
    edges_.clear();
    for (std::size_t i = 0; i + 1 < ring_.size(); ++i) edges_.emplace_back(ring_[i], ring_[i + 1]);
    if (closed && ring_.size() >= 3) edges_.emplace_back(ring_.back(), ring_.front());
    if (!(search_ == Hole_search::ring_triangulation && ring_.size() > small_ring && mesh_.planar() &&
          assign_in_ring_triangulation(closed))) {
      if (mesh_.planar()) (closed ? fill_polygon : fill_hull_pockets)(points_, ring_, edges_);
      if (edges_.empty()) return INFINITY;
      canonical_edge_list();
      assign_orphans();
    }
    double change = -old_cost;
    for (std::size_t k = 0; k < edges_.size(); ++k) {
      if (buckets_[k].empty()) continue;
      const auto it = plans_.find(edge_key(edges_[k].first, edges_[k].second));
      trial_.samples = buckets_[k];
      if (it != plans_.end()) {
        trial_.samples.insert(trial_.samples.end(), it->second.samples.begin(), it->second.samples.end());
        change -= it->second.cost;
      }
      evaluate(edges_[k].first, edges_[k].second, trial_, false);
      change += trial_.cost;
    }
    return change;
  }

  // Removes v: the samples of its edges go to the nearest edge between its neighbours in
  // the triangulation without it; then the removals whose cost read a changed edge are
  // simulated again.
  void remove(Index v) {
    bool closed = false;
    mesh_.link(v, ring_, closed);
    std::vector<Index> ring = ring_;
    gather_orphans(v);
    for (const Index w : ring)
      if (const auto it = plans_.find(edge_key(v, w)); it != plans_.end()) {
        count(std::min(v, w), std::max(v, w), it->second, -1);
        total_cost_ -= it->second.cost;
        plans_.erase(it);
      }
    const bool was_planar = mesh_.planar();
    mesh_.remove(v);
    alive_[v] = false;
    --alive_count_;

    edges_.clear();
    mesh_.edges_among(ring, edges_);
    canonical_edge_list();
    std::vector<Index> affected = ring;
    if (!edges_.empty()) {
      assign_orphans();
      for (std::size_t k = 0; k < edges_.size(); ++k) {
        if (buckets_[k].empty()) continue;
        const auto [a, b] = edges_[k];
        Edge_plan& plan = plans_[edge_key(a, b)];
        if (!plan.samples.empty()) count(a, b, plan, -1);  // else a new plan: nothing counted yet
        total_cost_ -= plan.cost;
        plan.samples.insert(plan.samples.end(), buckets_[k].begin(), buckets_[k].end());
        evaluate(a, b, plan, true);
        count(a, b, plan, +1);
        total_cost_ += plan.cost;
        mesh_.readers(a, b, affected);
      }
    }
    if (!greedy_) return;
    if (was_planar && !mesh_.planar()) {  // now on a line: every link changed
      affected.clear();
      for (Index w = 0; w < points_.size(); ++w)
        if (alive_[w]) affected.push_back(w);
    }
    std::sort(affected.begin(), affected.end());
    affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
    for (const Index w : affected)
      if (alive_[w]) queue_.update(handles_[w], {removal_cost_change(w), w});
  }

  std::span<const Point> points_;
  std::span<const double> masses_;
  Mesh mesh_;
  int exponent_ = 0;
  std::vector<std::array<double, 2>> scaled_;
  std::vector<Point> scaled_points_;
  std::unordered_map<std::uint64_t, Edge_plan> plans_;  // the edges that carry samples
  std::vector<int> regular_, fed_;  // per vertex: its regular edges, the ghost edges that feed it
  std::vector<bool> alive_;
  Queue queue_;
  std::vector<Queue::handle_type> handles_;
  std::size_t alive_count_ = 0;
  std::ptrdiff_t isolated_ = 0;  // vertices with mass on no regular edge
  std::ptrdiff_t branching_ = 0;  // vertices on three or more regular edges
  std::ptrdiff_t fewest_defects_ = std::numeric_limits<std::ptrdiff_t>::max();
  std::size_t vertices_at_fewest_ = 0;
  double total_cost_ = 0;
  bool greedy_ = true;
  Hole_search search_;
  std::vector<Index> removals_;

  // Rings above this size are filled by assign_in_ring_triangulation.
  static constexpr std::size_t small_ring = 16;
  using Ring_vertex_base = CGAL::Triangulation_vertex_base_with_info_2<Index, Kernel>;  // the position in the ring
  struct Ring_face_info {
    bool in_hole;         // whether the face is a triangle of the hole
    std::size_t visited;  // the last search that reached the face
  };
  using Ring_face_base = CGAL::Triangulation_face_base_with_info_2<Ring_face_info, Kernel>;
  using Ring_triangulation =
      CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Ring_vertex_base, Ring_face_base>>;

  // Scratch space, kept between calls.
  std::vector<Index> ring_, orphans_;
  std::vector<std::pair<Point, Index>> ring_points_;
  std::vector<Index_pair> edges_;
  std::vector<std::vector<Index>> buckets_;
  std::vector<std::pair<Index_pair, Index>> assigned_;
  std::vector<Segment_distance> segments_;
  std::vector<std::pair<double, Index>> along_;
  Edge_plan trial_;
};

}  // namespace

Optimal_transport_run optimal_transport_run(std::span<const Point> input, const Optimal_transport_options& options) {
  for (const Point& p : input)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw std::invalid_argument("optimal transport: a point has a non-finite coordinate");
  if (!(options.tolerance >= 0)) throw std::invalid_argument("optimal transport: the tolerance is negative");
  if (input.size() >= none) throw std::invalid_argument("optimal transport: too many points");

  // Sorted, so that every tie broken by index is broken the same for any input order;
  // equal points merged into one sample of their multiplicity.
  std::vector<Point> points(input.begin(), input.end());
  std::sort(points.begin(), points.end());
  std::vector<double> masses;
  std::size_t distinct = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (distinct > 0 && points[i] == points[distinct - 1]) {
      masses.back() += 1;
      continue;
    }
    points[distinct++] = points[i];
    masses.push_back(1);
  }
  points.resize(distinct);
  if (points.size() < 2) return {{{}, points}, 0, points.size()};

  Simplification simplification(points, masses, options.hole_search);
  simplification.run(options);
  const bool default_stop = options.vertices == 0 && options.tolerance == 0;  // which also draws gaps
  if (default_stop && simplification.vertices_at_fewest_defects() != simplification.vertices()) {
    // The run ended past the first state with the fewest defects: go back to it, replaying
    // the greedy order's removals.
    Simplification again(points, masses, options.hole_search, false);
    again.replay(simplification.removals().first(points.size() - simplification.vertices_at_fewest_defects()));
    return {again.result(true), again.cost(), again.vertices()};
  }
  return {simplification.result(default_stop), simplification.cost(), simplification.vertices()};
}

Reconstruction optimal_transport_reconstruction(std::span<const Point> points, const Optimal_transport_options& options) {
  return optimal_transport_run(points, options).reconstruction;
}

Algorithm optimal_transport_algorithm() {
  static const Parameter vertices{.name = "vertices", .type = Parameter_type::integer, .default_value = 0,
                                  .minimum = 0, .maximum = 1e9,
                                  .meaning = "stop when this many vertices remain (0: unset)"};
  static const Parameter tolerance{.name = "tolerance", .default_value = 0, .minimum = 0, .maximum = 1,
                                   .meaning = "stop before the Wasserstein distance exceeds this fraction of the "
                                              "bounding-box diagonal (0: unset; neither set: stop when every "
                                              "vertex with mass lies on one or two edges, see the header)"};
  return {
      .name = "optimal-transport",
      .title = "Optimal Transport",
      .reference = "de Goes, Cohen-Steiner, Alliez, Desbrun 2011",
      .category = "Non-manifold",
      .parameters = {vertices, tolerance},
      .capabilities = {.non_uniform = Support::yes, .noise = Support::yes, .outliers = Support::yes,
                       .manifold = Support::no, .open = Support::yes, .multiple = Support::yes,
                       .sharp = Support::no, .guarantee = true, .time_complexity = "O(n log n)"},
      .condition = {.statement = "none"},
      .reconstruct = [](std::span<const Point> points, const Parameter_values& values) {
        return optimal_transport_reconstruction(
            points, {.vertices = static_cast<std::size_t>(values[vertices]), .tolerance = values[tolerance]});
      },
      .simplifies = true,
  };
}

}  // namespace curvebench::algorithms
