#include "algorithms/crust.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using geometry::cross;
using geometry::difference;
using geometry::dot;
using geometry::exact_sign;
using geometry::squared_length;
using geometry::Vector2;
using graphs::no_vertex;
using graphs::Vertex;

// A Voronoi vertex: the circumcentre of a Delaunay triangle of S, given by its corners.
using Triangle = std::array<Vertex, 3>;

// The circumcentre c of triangle abc relative to p, without division: c - p = y / d.
template <class NT>
struct Centre {
  Vector2<NT> y;
  NT d;
};

template <class NT>
Centre<NT> centre_relative_to(const Point& p, const Point& a, const Point& b, const Point& c) {
  const auto ba = difference<NT>(b, a), ca = difference<NT>(c, a), ap = difference<NT>(a, p);
  const NT d = NT(2) * cross(ba, ca);
  const NT bb = squared_length(ba), cc = squared_length(ca);
  return {{d * ap.x + (bb * ca.y - cc * ba.y), d * ap.y + (cc * ba.x - bb * ca.x)}, d};
}

// The edge p -> q under test, and its constraints t_y = A / B (see crust.h).
class Edge_test {
 public:
  Edge_test(std::span<const Point> points, Vertex p, Vertex q) : points_(points), p_(points[p]), q_(points[q]) {}

  template <class NT>
  std::pair<NT, NT> constraint(const Triangle& t) const {
    const Centre<NT> c = centre_relative_to<NT>(p_, points_[t[0]], points_[t[1]], points_[t[2]]);
    const auto u = difference<NT>(q_, p_);
    return {squared_length(c.y) - c.d * dot(c.y, u), NT(2) * c.d * cross(u, c.y)};
  }

  // POSITIVE if the circumcentre lies left of p -> q, ZERO on the line.
  CGAL::Sign side(const Triangle& t) const {
    return exact_sign([&]<class NT>(std::type_identity<NT>) { return constraint<NT>(t).second; });
  }

  // True if the circumcentre lies in the closed disk of circle `circle` through p and q.
  bool in_closed_disk(const Triangle& t, double circle) const {
    return exact_sign([&]<class NT>(std::type_identity<NT>) {
             const auto [a, b] = constraint<NT>(t);
             return a - NT(circle) * b;
           }) != CGAL::POSITIVE;
  }

  // The sign of t_1 - t_2, for circumcentres off the line on the given sides.
  CGAL::Sign compare(const Triangle& t1, CGAL::Sign side1, const Triangle& t2, CGAL::Sign side2) const {
    const CGAL::Sign s = exact_sign([&]<class NT>(std::type_identity<NT>) {
      const auto [a1, b1] = constraint<NT>(t1);
      const auto [a2, b2] = constraint<NT>(t2);
      return a1 * b2 - a2 * b1;
    });
    return s * side1 * side2;
  }

  // True if point v lies in the closed disk that holds every triangle whose circumcentre
  // lies in the closed disk of circle `circle` (crust.h, step 4):
  // |v - x|^2 <= |pq|^2 (2 + 10 t^2), written with X = 2 (x - p) = (q - p) + 2 t n.
  bool in_search_disk(const Point& v, double circle) const {
    return exact_sign([&]<class NT>(std::type_identity<NT>) {
             const auto u = difference<NT>(q_, p_), w = difference<NT>(v, p_);
             const NT t(circle);
             const Vector2<NT> x{u.x - NT(2) * t * u.y, u.y + NT(2) * t * u.x};
             const Vector2<NT> r{NT(2) * w.x - x.x, NT(2) * w.y - x.y};
             return NT(4) * squared_length(u) * (NT(2) + NT(10) * t * t) - squared_length(r);
           }) != CGAL::NEGATIVE;
  }

  // t_y rounded, for choosing circles only; computed on coordinates relative to p scaled
  // by a power of two so that nothing overflows. NaN or infinite if it cannot be.
  double approximate(const Triangle& t) const {
    int exponent = 0;
    std::frexp(std::max(std::abs(q_.x() - p_.x()), std::abs(q_.y() - p_.y())), &exponent);
    const auto scaled = [&](const Point& v) {
      return Point(std::ldexp(v.x() - p_.x(), -exponent), std::ldexp(v.y() - p_.y(), -exponent));
    };
    const Point origin(0, 0), q = scaled(q_);
    const Centre<double> c =
        centre_relative_to<double>(origin, scaled(points_[t[0]]), scaled(points_[t[1]]), scaled(points_[t[2]]));
    const double a = c.y.x * c.y.x + c.y.y * c.y.y - c.d * (c.y.x * q.x() + c.y.y * q.y());
    const double b = 2 * c.d * (q.x() * c.y.y - q.y() * c.y.x);
    return a / b;
  }

 private:
  std::span<const Point> points_;
  Point p_, q_;
};

// The triangles of a Delaunay triangulation and, per vertex, the triangles around it.
class Triangles {
 public:
  explicit Triangles(const graphs::Delaunay_triangulation& dt) {
    // Each triangle once: from the edge opposite its largest vertex.
    for (const graphs::Delaunay_edge& e : dt.edges()) {
      if (e.left != no_vertex && e.left > e.target) triangles_.push_back({e.source, e.target, e.left});
      if (e.right != no_vertex && e.right > e.target) triangles_.push_back({e.target, e.source, e.right});
    }
    first_.assign(dt.size() + 1, 0);
    for (const Triangle& t : triangles_)
      for (const Vertex v : t) ++first_[v + 1];
    for (std::size_t v = 0; v < dt.size(); ++v) first_[v + 1] += first_[v];
    around_.resize(first_.back());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (std::size_t f = 0; f < triangles_.size(); ++f)
      for (const Vertex v : triangles_[f]) around_[next[v]++] = static_cast<std::uint32_t>(f);
  }

  std::span<const Triangle> all() const { return triangles_; }
  std::span<const std::uint32_t> around(Vertex v) const {
    return {around_.data() + first_[v], around_.data() + first_[v + 1]};
  }

 private:
  std::vector<Triangle> triangles_;
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> around_;
};

// Decides one Delaunay edge by steps 2-4 of crust.h.
class Crust_edge_decider {
 public:
  Crust_edge_decider(const graphs::Delaunay_triangulation& dt, const Triangles& triangles)
      : dt_(dt), triangles_(triangles), stamp_(dt.size(), 0) {}

  bool keep(graphs::Delaunay_edge e) {
    if (e.left == no_vertex && e.right == no_vertex) return true;  // collinear points: the chain
    if (e.left == no_vertex) {  // a hull edge: orient it so that its triangle lies left
      std::swap(e.source, e.target);
      std::swap(e.left, e.right);
    }
    const Vertex p = e.source, q = e.target;
    const auto points = dt_.points();
    // Step 2: an apex angle >= 90 degrees (the apex in the closed diametral disk).
    for (const Vertex apex : {e.left, e.right})
      if (apex != no_vertex && graphs::blocks(points[p], points[q], points[apex], 1, graphs::Beta_region::lune))
        return false;

    const Edge_test test(points, p, q);
    Bound left{{p, q, e.left}, CGAL::POSITIVE};
    std::optional<Bound> right;
    if (e.right != no_vertex) right = Bound{{q, p, e.right}, CGAL::NEGATIVE};
    // Step 3: Gold and Snoeyink's test.
    if (right && !before(test, *right, left)) return false;

    // Step 4.
    while (true) {
      const std::optional<double> circle = witness_circle(test, left, right);
      if (!circle) return decide_by_scanning_all(test, left, right);
      bool tightened = false;
      for (const std::uint32_t f : triangles_in_search_disk(test, p, q, *circle)) {
        const Triangle& t = triangles_.all()[f];
        if (!test.in_closed_disk(t, *circle)) continue;
        const CGAL::Sign side = test.side(t);
        if (side == CGAL::ZERO) return false;  // on the line inside the disk: inside segment pq
        tighten(test, {t, side}, left, right);
        tightened = true;
      }
      if (!tightened) return true;
      if (right && !before(test, *right, left)) return false;
    }
  }

 private:
  struct Bound {
    Triangle triangle;
    CGAL::Sign side;
  };

  // t_a < t_b, exactly.
  static bool before(const Edge_test& test, const Bound& a, const Bound& b) {
    return test.compare(a.triangle, a.side, b.triangle, b.side) == CGAL::NEGATIVE;
  }

  static void tighten(const Edge_test& test, const Bound& found, Bound& left, std::optional<Bound>& right) {
    if (found.side == CGAL::POSITIVE) {
      if (before(test, found, left)) left = found;
    } else if (!right || before(test, *right, found)) {
      right = found;
    }
  }

  // A circle strictly between the bounds, verified exactly; nothing if none of the
  // rounded candidates verifies.
  static std::optional<double> witness_circle(const Edge_test& test, const Bound& left,
                                              const std::optional<Bound>& right) {
    const double high = test.approximate(left.triangle);
    const double low = right ? test.approximate(right->triangle) : -std::numeric_limits<double>::infinity();
    std::array<double, 3> candidates{0, 0, 0};
    std::size_t count = 0;
    if (low < 0 && high > 0) candidates[count++] = 0;
    if (std::isfinite(low) && std::isfinite(high) && low < high) candidates[count++] = low / 2 + high / 2;
    if (!right && std::isfinite(high)) candidates[count++] = high - (1 + std::abs(high)) / 4;
    for (std::size_t i = 0; i < count; ++i) {
      const double circle = candidates[i];
      if (!std::isfinite(circle)) continue;
      if (!test.in_closed_disk(left.triangle, circle) && (!right || !test.in_closed_disk(right->triangle, circle)))
        return circle;
    }
    return std::nullopt;
  }

  // Every triangle with all three corners in the search disk of `circle` (crust.h, step
  // 4), by breadth-first search from p and q.
  const std::vector<std::uint32_t>& triangles_in_search_disk(const Edge_test& test, Vertex p, Vertex q,
                                                             double circle) {
    ++round_;
    queue_.assign({p, q});
    stamp_[p] = stamp_[q] = round_;
    // Cheap rejection first: the search disk (centre x, radius r) lies within distance
    // |x - p| + r = |pq| (sqrt(1/4 + t^2) + sqrt(2 + 10 t^2)) of p; `reach` bounds that
    // factor squared from above (rounding is far below the 1e-3 slack), and the filter
    // decides |w - p|^2 > reach |pq|^2 exactly or not at all.
    const double reach_factor = std::sqrt(0.25 + circle * circle) + std::sqrt(2 + 10 * circle * circle);
    using geometry::squared_distance_approximation;
    const double reach =
        reach_factor * reach_factor * 1.001 * squared_distance_approximation(dt_.point(p), dt_.point(q));
    const auto beyond_reach = [&](Vertex w) {
      const auto s =
          geometry::certain_sign_of_difference(reach, squared_distance_approximation(dt_.point(p), dt_.point(w)));
      return s && *s == CGAL::POSITIVE;
    };
    for (std::size_t i = 0; i < queue_.size(); ++i)
      for (const Vertex w : dt_.neighbors(queue_[i]))
        if (stamp_[w] != round_ && !beyond_reach(w) && test.in_search_disk(dt_.point(w), circle)) {
          stamp_[w] = round_;
          queue_.push_back(w);
        }
    found_.clear();
    if (queue_.size() < 3) return found_;  // a triangle needs a third corner
    for (const Vertex v : queue_)
      for (const std::uint32_t f : triangles_.around(v)) {
        const Triangle& t = triangles_.all()[f];
        if (*std::min_element(t.begin(), t.end()) == v &&
            std::all_of(t.begin(), t.end(), [&](Vertex w) { return stamp_[w] == round_; }))
          found_.push_back(f);
      }
    return found_;
  }

  // The exact answer from every Voronoi vertex: for bounds too close for a double circle.
  bool decide_by_scanning_all(const Edge_test& test, Bound left, std::optional<Bound> right) const {
    for (const Triangle& t : triangles_.all()) {
      const CGAL::Sign side = test.side(t);
      if (side == CGAL::ZERO) {
        if (test.in_closed_disk(t, 0)) return false;  // on segment pq
        continue;
      }
      tighten(test, {t, side}, left, right);
    }
    return !right || before(test, *right, left);
  }

  const graphs::Delaunay_triangulation& dt_;
  const Triangles& triangles_;
  std::vector<std::uint64_t> stamp_;
  std::uint64_t round_ = 0;
  std::vector<Vertex> queue_;
  std::vector<std::uint32_t> found_;
};

}  // namespace

std::vector<Edge> crust_reconstruction(std::span<const Point> points) {
  const graphs::Delaunay_triangulation dt(points);
  const Triangles triangles(dt);
  Crust_edge_decider decider(dt, triangles);
  std::vector<Edge> edges;
  for (const graphs::Delaunay_edge& e : dt.edges())
    if (decider.keep(e)) edges.emplace_back(e.source, e.target);
  std::ranges::sort(edges);
  return edges;
}

Algorithm crust_algorithm() {
  return {
      .name = "crust",
      .title = "Crust",
      .reference = "Amenta, Bern, Eppstein 1998",
      .category = "Feature Size Criteria",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::yes, .multiple = Support::yes,
                       .guarantee = true, .time_complexity = "O(n log n)"},
      .condition = {.statement = "epsilon < 0.252", .epsilon_below = 0.252, .rho_below = {},
                    .corner_angle_above = {}},
      .reconstruct = edges_on_input(crust_reconstruction),
  };
}

}  // namespace curvebench::algorithms
