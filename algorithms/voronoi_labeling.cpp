#include "algorithms/voronoi_labeling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_edge_index.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using geometry::Error_bounded_double;
using geometry::Vector2;
using graphs::Delaunay_edge;
using graphs::Delaunay_triangulation;
using graphs::no_vertex;
using graphs::Vertex;
using Id = std::uint32_t;
constexpr Id no_id = std::numeric_limits<Id>::max();
using Triangle = std::array<Vertex, 3>;  // counterclockwise

// ---- Exact predicates on circle centres, written on the triangles' own points ----------

// With a the origin, the circumcentre of (a, b, c) counterclockwise is W / (2 D), where
// u = b - a, v = c - a, D = u x v > 0 and W = (|u|^2 v_y - |v|^2 u_y, |v|^2 u_x - |u|^2 v_x).
template <class NT>
struct Centre {
  Vector2<NT> w;  // W
  NT d;           // D
};
template <class NT>
Centre<NT> centre_from(const Point& a, const Point& b, const Point& c) {
  const auto u = geometry::difference<NT>(b, a), v = geometry::difference<NT>(c, a);
  const NT uu = geometry::squared_length(u), vv = geometry::squared_length(v);
  return {{uu * v.y - vv * u.y, vv * u.x - uu * v.x}, geometry::cross(u, v)};
}

// The side of the directed line x -> y on which the circumcentre of t lies: POSITIVE on
// the left. orientation(x, y, a + W/(2D)) has the sign of 2D (y-x)x(a-x) + (y-x)xW.
CGAL::Sign centre_side(const Point& x, const Point& y, const Point& a, const Point& b, const Point& c) {
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
    const Centre<NT> m = centre_from<NT>(a, b, c);
    const auto e = geometry::difference<NT>(y, x);
    return NT(2) * m.d * geometry::cross(e, geometry::difference<NT>(a, x)) + geometry::cross(e, m.w);
  });
}

// The sign of (c1 - s).(c2 - s), c1 and c2 the circumcentres of the counterclockwise
// triangles (s, q1, r1) and (s, q2, r2): both D > 0, so it is the sign of W1.W2.
CGAL::Sign centre_dot(const Point& s, const Point& q1, const Point& r1, const Point& q2, const Point& r2) {
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
    const Centre<NT> m1 = centre_from<NT>(s, q1, r1), m2 = centre_from<NT>(s, q2, r2);
    return geometry::dot(m1.w, m2.w);
  });
}

// Squared circumradius |ab|^2 |bc|^2 |ca|^2 / (4 D^2) as N / (4 D^2).
template <class NT>
std::pair<NT, NT> radius_terms(const Point& a, const Point& b, const Point& c) {
  using geometry::difference, geometry::squared_length;
  const NT n = squared_length(difference<NT>(a, b)) * squared_length(difference<NT>(b, c)) *
               squared_length(difference<NT>(c, a));
  return {n, geometry::cross(difference<NT>(b, a), difference<NT>(c, a))};
}

// A rounded squared circumradius with a bound on its relative error (infinite when the
// rounding cannot bound it: near-degenerate triangles, overflow, underflow).
struct Radius {
  double value = 0;
  double relative_error = std::numeric_limits<double>::infinity();
};
Radius rounded_radius(const Point& a, const Point& b, const Point& c) {
  const auto [n, d] = radius_terms<Error_bounded_double>(a, b, c);
  Radius r;
  if (!d.sign_is_certain() || !n.sign_is_certain()) return r;
  const double value = n.value() / (4 * d.value() * d.value());
  if (!std::isfinite(value) || !(value >= 0x1p-900) || value > 0x1p900) return r;
  // (1 + en) / (1 - ed)^2 <= 1 + E + 2 E^2 with E = en + 2 ed small; plus the roundings
  // of this quotient and of the comparisons made with it.
  const double first_order = n.error() / n.value() + 2 * std::abs(d.error() / d.value());
  if (first_order < 0x1p-20) r = {value, first_order + 2 * first_order * first_order + 0x1p-48};
  return r;
}

// The sign of R(t1)^2 - R(t2)^2.
CGAL::Sign compare_radii(const Point& a1, const Point& b1, const Point& c1, const Radius& r1, const Point& a2,
                         const Point& b2, const Point& c2, const Radius& r2) {
  if (std::isfinite(r1.relative_error) && std::isfinite(r2.relative_error)) {
    if (r1.value * (1 - r1.relative_error) > r2.value * (1 + r2.relative_error)) return CGAL::POSITIVE;
    if (r2.value * (1 - r2.relative_error) > r1.value * (1 + r1.relative_error)) return CGAL::NEGATIVE;
  }
  return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
    const auto [n1, d1] = radius_terms<NT>(a1, b1, c1);
    const auto [n2, d2] = radius_terms<NT>(a2, b2, c2);
    return n1 * d2 * d2 - n2 * d1 * d1;
  });
}

// ---- The triangulation as triangles, their adjacency and their Voronoi vertices --------

Id find_root(std::vector<Id>& parent, Id x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// One pass of the labelling on a triangulation of dimension 2.
class Labeling {
 public:
  explicit Labeling(const Delaunay_triangulation& dt) : dt_(dt), edges_(dt.edges()) {
    build_triangles();
    build_vertices();
    find_hull();
  }

  // The pass's edges, in the triangulation's indices.
  std::vector<Edge> run() {
    std::vector<Edge> result;
    if (std::all_of(on_hull_.begin(), on_hull_.end(), [](bool b) { return b; })) {
      for (const Delaunay_edge& e : edges_)
        if (e.left == no_vertex || e.right == no_vertex) result.emplace_back(e.source, e.target);
      return result;
    }
    label();
    for (Id f = 0; f < edges_.size(); ++f) {
      const auto [left, right] = edge_triangles_[f];
      const bool interior = left != no_id && right != no_id;
      if (interior ? cell_[left] != cell_[right] && outer_[cell_[left]] != outer_[cell_[right]]
                   : !outer_[cell_[left != no_id ? left : right]])
        result.emplace_back(edges_[f].source, edges_[f].target);
    }
    return result;
  }

 private:
  const Point& point(Vertex v) const { return dt_.point(v); }

  // Triangles from the edges' apexes (each once: from its edge opposite its largest
  // vertex), the triangles on either side of every edge, and each vertex's triangles.
  void build_triangles() {
    for (const Delaunay_edge& e : edges_) {
      if (e.left != no_vertex && e.left > e.target) triangles_.push_back({e.source, e.target, e.left});
      if (e.right != no_vertex && e.right > e.target) triangles_.push_back({e.target, e.source, e.right});
    }
    const graphs::Delaunay_edge_index lookup(dt_);
    edge_triangles_.assign(edges_.size(), {no_id, no_id});
    first_triangle_.assign(dt_.size() + 1, 0);
    for (Id t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const Vertex x = triangles_[t][k], y = triangles_[t][(k + 1) % 3];
        const Id f = lookup.find(x, y);
        edge_triangles_[f][edges_[f].source == x ? 0 : 1] = t;  // x -> y has t on its left
        ++first_triangle_[x + 1];
      }
    std::partial_sum(first_triangle_.begin(), first_triangle_.end(), first_triangle_.begin());
    incident_.resize(first_triangle_.back());
    std::vector<std::size_t> next(first_triangle_.begin(), first_triangle_.end() - 1);
    for (Id t = 0; t < triangles_.size(); ++t)
      for (const Vertex v : triangles_[t]) incident_[next[v]++] = t;
  }

  std::span<const Id> triangles_at(Vertex v) const {
    return {incident_.data() + first_triangle_[v], incident_.data() + first_triangle_[v + 1]};
  }

  // Voronoi vertices: triangles joined across every edge whose four points are cocircular.
  void build_vertices() {
    std::vector<Id> parent(triangles_.size());
    std::iota(parent.begin(), parent.end(), Id{0});
    for (Id f = 0; f < edges_.size(); ++f) {
      const auto [left, right] = edge_triangles_[f];
      if (left == no_id || right == no_id) continue;
      const Triangle& t = triangles_[left];
      if (CGAL::side_of_oriented_circle(point(t[0]), point(t[1]), point(t[2]), point(edges_[f].right)) ==
          CGAL::ON_ORIENTED_BOUNDARY)
        parent[find_root(parent, left)] = find_root(parent, right);
    }
    cell_.assign(triangles_.size(), no_id);
    for (Id t = 0; t < triangles_.size(); ++t) {
      const Id root = find_root(parent, t);
      if (cell_[root] == no_id) {
        cell_[root] = Id(representative_.size());
        representative_.push_back(root);
        key_.push_back({no_vertex, no_vertex, no_vertex});
      }
      cell_[t] = cell_[root];
    }
    // Key: the three smallest point indices of the cell (two cells share at most an edge).
    for (Id t = 0; t < triangles_.size(); ++t) {
      auto& key = key_[cell_[t]];
      for (const Vertex v : triangles_[t]) {
        if (std::find(key.begin(), key.end(), v) != key.end() || v >= key[2]) continue;
        key[2] = v;
        std::sort(key.begin(), key.end());
      }
    }
    for (const Id t : representative_) {
      const Triangle& r = triangles_[t];
      radius_.push_back(rounded_radius(point(r[0]), point(r[1]), point(r[2])));
    }
    first_member_.assign(representative_.size() + 1, 0);
    for (Id t = 0; t < triangles_.size(); ++t) ++first_member_[cell_[t] + 1];
    std::partial_sum(first_member_.begin(), first_member_.end(), first_member_.begin());
    members_.resize(triangles_.size());
    std::vector<std::size_t> next(first_member_.begin(), first_member_.end() - 1);
    for (Id t = 0; t < triangles_.size(); ++t) members_[next[cell_[t]]++] = t;
  }

  // Points on the hull's boundary, and the hull's corners counterclockwise.
  void find_hull() {
    on_hull_.assign(dt_.size(), false);
    std::vector<Vertex> next(dt_.size(), no_vertex);
    Vertex start = no_vertex;
    for (const Delaunay_edge& e : edges_) {
      if (e.left != no_vertex && e.right != no_vertex) continue;
      on_hull_[e.source] = on_hull_[e.target] = true;
      // The triangle lies left of the counterclockwise direction.
      if (e.right == no_vertex) next[e.source] = e.target;
      else next[e.target] = e.source;
      start = e.source;
    }
    std::vector<Vertex> cycle{start};
    for (Vertex v = next[start]; v != start; v = next[v]) cycle.push_back(v);
    for (std::size_t i = 0; i < cycle.size(); ++i) {
      const Vertex previous = cycle[(i + cycle.size() - 1) % cycle.size()], following = cycle[(i + 1) % cycle.size()];
      if (CGAL::orientation(point(previous), point(cycle[i]), point(following)) == CGAL::LEFT_TURN)
        corners_.push_back(cycle[i]);
    }
  }

  // Whether the circle centre of triangle t lies strictly outside the convex hull: outside
  // the cone at corner h0 spanned by its two hull sides, or, in the fan triangle
  // (h0, h_i, h_i+1) found by binary search, strictly right of the side h_i h_i+1.
  bool centre_outside_hull(Id t) const {
    const Triangle& tri = triangles_[t];
    const Point &a = point(tri[0]), &b = point(tri[1]), &c = point(tri[2]);
    // A non-obtuse triangle holds its circle centre.
    if (graphs::angle_sign(b, c, a) != CGAL::NEGATIVE && graphs::angle_sign(c, a, b) != CGAL::NEGATIVE &&
        graphs::angle_sign(a, b, c) != CGAL::NEGATIVE)
      return false;
    const auto side = [&](Vertex x, Vertex y) { return centre_side(point(x), point(y), a, b, c); };
    const std::size_t m = corners_.size();
    const Vertex h0 = corners_[0];
    if (side(h0, corners_[1]) == CGAL::NEGATIVE || side(h0, corners_[m - 1]) == CGAL::POSITIVE) return true;
    std::size_t low = 1, high = m - 1;  // side(h0, h_low) >= 0 >= side(h0, h_high)
    while (high - low > 1) {
      const std::size_t middle = (low + high) / 2;
      (side(h0, corners_[middle]) != CGAL::NEGATIVE ? low : high) = middle;
    }
    return side(corners_[low], corners_[high]) == CGAL::NEGATIVE;
  }

  // Heap order ("less"): cell a is treated after cell b if its circle is smaller, or as
  // large with a larger key.
  bool treated_after(Id a, Id b) const {
    const Triangle &ta = triangles_[representative_[a]], &tb = triangles_[representative_[b]];
    const CGAL::Sign s = compare_radii(point(ta[0]), point(ta[1]), point(ta[2]), radius_[a], point(tb[0]),
                                       point(tb[1]), point(tb[2]), radius_[b]);
    return s == CGAL::NEGATIVE || (s == CGAL::ZERO && key_[a] > key_[b]);
  }

  // Triangle t with vertex s first, counterclockwise.
  Triangle from(Id t, Vertex s) const {
    Triangle r = triangles_[t];
    while (r[0] != s) std::rotate(r.begin(), r.begin() + 1, r.end());
    return r;
  }

  // Seeds (circle centre outside the hull) and outer vertices wait in one heap, largest
  // circle first; each is queued once. A popped vertex v is the outer pole of each of its
  // sites s not yet treated and not on the hull: s's tangent is the line through s
  // perpendicular to v - s, and every vertex of s's cell strictly on v's side is outer
  // (v itself included). A seed is a pole, not yet a label: one whose sites are all on
  // the hull or treated already stays inner, as in the authors' code.
  void label() {
    const std::size_t cells = representative_.size();
    outer_.assign(cells, false);
    std::vector<bool> queued(cells, false);
    std::vector<Id> heap;
    for (Id v = 0; v < cells; ++v)
      if (centre_outside_hull(representative_[v])) {
        queued[v] = true;
        heap.push_back(v);
      }
    const auto after = [this](Id a, Id b) { return treated_after(a, b); };
    std::make_heap(heap.begin(), heap.end(), after);
    std::vector<bool> treated(dt_.size(), false);
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), after);
      const Id v = heap.back();
      heap.pop_back();
      for (std::size_t k = first_member_[v]; k < first_member_[v + 1]; ++k) {
        const Id pole_triangle = members_[k];
        for (const Vertex s : triangles_[pole_triangle]) {
          if (treated[s] || on_hull_[s]) continue;
          treated[s] = true;
          const Triangle pole = from(pole_triangle, s);
          for (const Id t : triangles_at(s)) {
            const Id w = cell_[t];
            if (outer_[w]) continue;
            const Triangle other = from(t, s);
            if (centre_dot(point(s), point(pole[1]), point(pole[2]), point(other[1]), point(other[2])) !=
                CGAL::POSITIVE)
              continue;
            outer_[w] = true;
            if (queued[w]) continue;
            queued[w] = true;
            heap.push_back(w);
            std::push_heap(heap.begin(), heap.end(), after);
          }
        }
      }
    }
  }

  const Delaunay_triangulation& dt_;
  std::span<const Delaunay_edge> edges_;
  std::vector<Triangle> triangles_;
  std::vector<std::array<Id, 2>> edge_triangles_;  // left, right of source -> target
  std::vector<std::size_t> first_triangle_;
  std::vector<Id> incident_;  // triangles by vertex
  std::vector<Id> cell_;      // triangle -> Voronoi vertex (Delaunay cell)
  std::vector<Id> representative_;
  std::vector<std::array<Vertex, 3>> key_;
  std::vector<Radius> radius_;
  std::vector<std::size_t> first_member_;
  std::vector<Id> members_;  // triangles by cell
  std::vector<bool> on_hull_;
  std::vector<Vertex> corners_;
  std::vector<bool> outer_;
};

}  // namespace

std::vector<Edge> voronoi_labeling_reconstruction(std::span<const Point> points) {
  std::vector<Edge> result;
  {
    const Delaunay_triangulation dt(points);  // validates the input
    if (graphs::all_collinear(points)) {
      for (const Delaunay_edge& e : dt.edges()) result.emplace_back(e.source, e.target);
      return geometry::canonical_edges(std::move(result));
    }
    for (const Edge& e : Labeling(dt).run()) result.push_back(e);
  }
  // Peels: the points on no edge yet, while more than two are left, not all collinear, and
  // the last pass connected some.
  std::vector<bool> used(points.size(), false);
  for (;;) {
    for (const auto& [i, j] : result) used[i] = used[j] = true;
    std::vector<std::size_t> left;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (!used[i]) left.push_back(i);
    std::vector<Point> subset;
    for (const std::size_t i : left) subset.push_back(points[i]);
    if (subset.size() < 3 || graphs::all_collinear(subset)) break;
    const Delaunay_triangulation dt(subset);
    const std::vector<Edge> pass = Labeling(dt).run();
    if (pass.empty()) break;
    for (const auto& [i, j] : pass) result.emplace_back(left[i], left[j]);
  }
  return geometry::canonical_edges(std::move(result));
}

Algorithm voronoi_labeling_algorithm() {
  return {
      .name = "voronoi-labeling",
      .title = "Voronoi Labeling",
      .reference = "Peethambaran, Parakkat, Tagliasacchi, Wang, Muthuganapathy 2019",
      .category = "Graph Based",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .outliers = Support::yes, .manifold = Support::yes,
                       .multiple = Support::yes, .sharp = Support::yes, .guarantee = true,
                       .time_complexity = "O(n log n)"},
      // Proven for simple closed smooth curves with "bi-tangent neighbourhood convergence"
      // (a variant of divergent concavity; survey, "Graph Based"); the survey gives no
      // epsilon bound for it.
      .condition = {.statement = "bi-tangent neighbourhood convergence"},
      .reconstruct = edges_on_input(voronoi_labeling_reconstruction),
  };
}

}  // namespace curvebench::algorithms
