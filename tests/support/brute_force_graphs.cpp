#include "tests/support/brute_force_graphs.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <CGAL/CORE_Expr.h>
#include <CGAL/Exact_rational.h>

namespace curvebench::testing {
namespace {

using Q = CGAL::Exact_rational;
using R = CORE::Expr;

template <class NT>
struct P {
  NT x, y;
  P(NT x_, NT y_) : x(std::move(x_)), y(std::move(y_)) {}
  explicit P(const Point& p) : x(p.x()), y(p.y()) {}
  P operator-(const P& o) const { return {x - o.x, y - o.y}; }
  P operator+(const P& o) const { return {x + o.x, y + o.y}; }
  P operator*(const NT& s) const { return {x * s, y * s}; }
  NT dot(const P& o) const { return x * o.x + y * o.y; }
  NT cross(const P& o) const { return x * o.y - y * o.x; }
  NT norm2() const { return dot(*this); }
  P perp() const { return {-y, x}; }
};
using QP = P<Q>;
using RP = P<R>;

std::vector<QP> rational(const std::vector<Point>& points) { return {points.begin(), points.end()}; }
std::vector<RP> real(const std::vector<Point>& points) { return {points.begin(), points.end()}; }

template <class Keep>
std::vector<Edge> pairs_where(std::size_t n, Keep keep) {
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (keep(i, j)) edges.emplace_back(i, j);
  return edges;
}

template <class Blocks>
std::vector<Edge> pairs_unblocked(std::size_t n, Blocks blocks) {
  return pairs_where(n, [&](std::size_t i, std::size_t j) {
    for (std::size_t k = 0; k < n; ++k)
      if (k != i && k != j && blocks(i, j, k)) return false;
    return true;
  });
}

// Circles through p and q have centres m + t n (n perpendicular to pq). Point r is
// strictly inside iff A - B t < 0, so "r not strictly inside" bounds t on one side.
bool circle_through_exists(const std::vector<QP>& pts, std::size_t i, std::size_t j, bool strict) {
  const QP& p = pts[i];
  const QP& q = pts[j];
  const QP m = (p + q) * Q(1, 2);
  const QP n = (q - p).perp();
  std::optional<Q> lower, upper;
  bool lower_closed = true, upper_closed = true;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (k == i || k == j) continue;
    const QP& r = pts[k];
    const Q a = r.norm2() - p.norm2() - Q(2) * m.dot(r - p);
    const Q b = Q(2) * n.dot(r - p);
    if (b == 0) {
      if (a < 0 || (strict && a == 0)) return false;
      continue;
    }
    const Q bound = a / b;  // need a - b t >= 0 (or > 0)
    if (b > 0) {
      if (!upper || bound < *upper || (bound == *upper && strict)) upper = bound, upper_closed = !strict;
    } else {
      if (!lower || bound > *lower || (bound == *lower && strict)) lower = bound, lower_closed = !strict;
    }
  }
  if (!lower || !upper) return true;
  return *lower < *upper || (*lower == *upper && lower_closed && upper_closed);
}

}  // namespace

std::vector<Edge> weak_delaunay_edges(const std::vector<Point>& points) {
  const auto pts = rational(points);
  return pairs_where(pts.size(), [&](std::size_t i, std::size_t j) { return circle_through_exists(pts, i, j, false); });
}

std::vector<Edge> strong_delaunay_edges(const std::vector<Point>& points) {
  const auto pts = rational(points);
  return pairs_where(pts.size(), [&](std::size_t i, std::size_t j) { return circle_through_exists(pts, i, j, true); });
}

std::vector<std::array<std::size_t, 3>> brute_force_delaunay_triangles(const std::vector<Point>& points,
                                                                      const std::vector<Edge>& delaunay) {
  const auto pts = rational(points);
  const std::size_t n = pts.size();
  const auto is_edge = [&](std::size_t i, std::size_t j) {
    return std::binary_search(delaunay.begin(), delaunay.end(), Edge(std::min(i, j), std::max(i, j)));
  };
  // d strictly inside the circle through a, b, c: the in-circle determinant, signed by a b c's orientation.
  const auto inside = [&](const QP& a, const QP& b, const QP& c, const QP& d) {
    const QP u = a - d, v = b - d, w = c - d;
    const Q det = u.norm2() * v.cross(w) - v.norm2() * u.cross(w) + w.norm2() * u.cross(v);
    return (b - a).cross(c - a) > 0 ? det > 0 : det < 0;
  };
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        if (!is_edge(i, j) || !is_edge(j, k) || !is_edge(i, k) || (pts[j] - pts[i]).cross(pts[k] - pts[i]) == 0) continue;
        bool empty = true;
        for (std::size_t m = 0; m < n && empty; ++m)
          if (m != i && m != j && m != k && inside(pts[i], pts[j], pts[k], pts[m])) empty = false;
        if (empty) triangles.push_back({i, j, k});
      }
  return triangles;
}

std::size_t hull_boundary_size(const std::vector<Point>& points) {
  const auto pts = rational(points);
  const std::size_t n = pts.size();
  // p is on the hull boundary iff some line through p has every point on one closed side;
  // such a line can be taken through p and another point, or p is the only point.
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bool on_boundary = n <= 2;
    for (std::size_t j = 0; j < n && !on_boundary; ++j) {
      if (j == i) continue;
      bool left = false, right = false;
      for (std::size_t k = 0; k < n; ++k) {
        const Q c = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
        left = left || c > 0;
        right = right || c < 0;
      }
      on_boundary = !(left && right);
    }
    count += on_boundary;
  }
  return count;
}

bool has_crossing_or_overlap(const std::vector<Point>& points, const std::vector<Edge>& edges) {
  const auto pts = rational(points);
  const auto orient = [&](std::size_t a, std::size_t b, std::size_t c) {
    return CGAL::sign((pts[b] - pts[a]).cross(pts[c] - pts[a]));
  };
  for (const auto& [a, b] : edges) {
    for (std::size_t k = 0; k < pts.size(); ++k)  // a point inside an edge
      if (k != a && k != b && orient(a, b, k) == CGAL::ZERO && (pts[a] - pts[k]).dot(pts[b] - pts[k]) < 0)
        return true;
    for (const auto& [c, d] : edges) {
      if (a == c || a == d || b == c || b == d) continue;
      if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0) return true;
    }
  }
  return false;
}

std::vector<Edge> brute_force_gabriel_graph(const std::vector<Point>& points) {
  const auto pts = rational(points);
  return pairs_unblocked(pts.size(), [&](std::size_t i, std::size_t j, std::size_t k) {
    return (pts[k] - pts[i]).dot(pts[k] - pts[j]) <= 0;  // angle ikj >= 90 degrees
  });
}

std::vector<Edge> brute_force_relative_neighborhood_graph(const std::vector<Point>& points) {
  const auto pts = rational(points);
  return pairs_unblocked(pts.size(), [&](std::size_t i, std::size_t j, std::size_t k) {
    const Q pq = (pts[j] - pts[i]).norm2();
    return (pts[k] - pts[i]).norm2() < pq && (pts[k] - pts[j]).norm2() < pq;
  });
}

std::vector<Edge> brute_force_beta_skeleton(const std::vector<Point>& points, double beta, graphs::Beta_region region) {
  if (beta == 1) return brute_force_gabriel_graph(points);
  const auto pts = real(points);
  const R b(beta);
  return pairs_unblocked(pts.size(), [&](std::size_t i, std::size_t j, std::size_t k) {
    const RP& p = pts[i];
    const RP& q = pts[j];
    const RP& r = pts[k];
    const R length2 = (q - p).norm2();
    if (beta == 0) return (p - r).cross(q - r) == 0 && (p - r).dot(q - r) < 0;  // the open segment
    if (beta > 1 && region == graphs::Beta_region::lune) {
      // Disks of radius beta|pq|/2 centred at (1 - beta/2) p + (beta/2) q and symmetric.
      const RP c1 = p * (R(1) - b / 2) + q * (b / 2), c2 = q * (R(1) - b / 2) + p * (b / 2);
      const R radius2 = b * b * length2 / 4;
      return (r - c1).norm2() < radius2 && (r - c2).norm2() < radius2;
    }
    // Two circles through p and q: radius beta|pq|/2 (beta > 1) or |pq|/(2 beta) (beta < 1).
    const R radius2 = beta > 1 ? b * b * length2 / 4 : length2 / (4 * b * b);
    const R offset = sqrt(radius2 / length2 - R(1) / 4);  // centre distance from midpoint, in units of |pq|
    const RP m = (p + q) * R(0.5), n = (q - p).perp();
    const RP c1 = m + n * offset, c2 = m - n * offset;
    if (beta > 1) return (r - c1).norm2() < radius2 || (r - c2).norm2() < radius2;
    return (r - c1).norm2() <= radius2 && (r - c2).norm2() <= radius2;
  });
}

std::vector<Edge> brute_force_minimum_spanning_tree(const std::vector<Point>& points) {
  const auto pts = rational(points);
  const std::size_t n = pts.size();
  // Edge order: exact squared length, then (min index, max index).
  const auto lighter = [&](const Edge& a, const Edge& b) {
    const Q la = (pts[a.first] - pts[a.second]).norm2(), lb = (pts[b.first] - pts[b.second]).norm2();
    const auto key = [](const Edge& e) { return std::minmax(e.first, e.second); };
    return la < lb || (la == lb && key(a) < key(b));
  };
  std::vector<bool> in_tree(n, false);
  std::vector<Edge> tree;
  if (n == 0) return tree;
  in_tree[0] = true;
  for (std::size_t step = 1; step < n; ++step) {
    std::optional<Edge> best;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (in_tree[i] && !in_tree[j] && (!best || lighter({i, j}, *best))) best = Edge{i, j};
    in_tree[best->second] = true;
    tree.emplace_back(std::min(best->first, best->second), std::max(best->first, best->second));
  }
  std::sort(tree.begin(), tree.end());
  return tree;
}

std::vector<Edge> brute_force_sphere_of_influence_graph(const std::vector<Point>& points) {
  const auto pts = real(points);
  const std::size_t n = pts.size();
  std::vector<R> radius(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::optional<R> nearest2;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i && (!nearest2 || (pts[j] - pts[i]).norm2() < *nearest2)) nearest2 = (pts[j] - pts[i]).norm2();
    if (nearest2) radius[i] = sqrt(*nearest2);
  }
  return pairs_where(n, [&](std::size_t i, std::size_t j) {
    return sqrt((pts[j] - pts[i]).norm2()) <= radius[i] + radius[j];
  });
}

std::vector<std::vector<std::size_t>> brute_force_k_nearest_neighbors(const std::vector<Point>& points, std::size_t k) {
  const auto pts = rational(points);
  const std::size_t n = pts.size();
  std::vector<std::vector<std::size_t>> ranked(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::size_t>& others = ranked[i];
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) others.push_back(j);
    std::sort(others.begin(), others.end(), [&](std::size_t a, std::size_t b) {
      const Q da = (pts[a] - pts[i]).norm2(), db = (pts[b] - pts[i]).norm2();
      return da < db || (da == db && a < b);
    });
    others.resize(std::min(k, others.size()));
  }
  return ranked;
}

std::vector<Edge> brute_force_k_nearest_neighbor_graph(const std::vector<Point>& points, std::size_t k) {
  std::vector<Edge> edges;
  const auto ranked = brute_force_k_nearest_neighbors(points, k);
  for (std::size_t i = 0; i < ranked.size(); ++i)
    for (const std::size_t j : ranked[i]) edges.emplace_back(std::min(i, j), std::max(i, j));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// Edelsbrunner and Muecke's alpha-complex: a triangle is in it if its circumdisk has no
// point strictly inside and squared radius <= alpha; an edge if it is a side of such a
// triangle, or its diametral disk has no point strictly inside and |pq|^2 / 4 <= alpha.
// Its boundary: the edges of the complex without a triangle of the complex on both sides.
std::vector<Edge> brute_force_alpha_shape_boundary(const std::vector<Point>& points, double alpha) {
  const auto pts = rational(points);
  const std::size_t n = pts.size();
  const Q a(alpha);
  const auto triangle_in_complex = [&](std::size_t i, std::size_t j, std::size_t k) {
    const QP u = pts[j] - pts[i], v = pts[k] - pts[i];
    const Q d = Q(2) * u.cross(v);
    if (d == 0) return false;
    const QP c = pts[i] + QP(v.y * u.norm2() - u.y * v.norm2(), u.x * v.norm2() - v.x * u.norm2()) * (Q(1) / d);
    const Q radius2 = (pts[i] - c).norm2();
    if (radius2 > a) return false;
    for (std::size_t x = 0; x < n; ++x)
      if ((pts[x] - c).norm2() < radius2) return false;
    return true;
  };
  return pairs_where(n, [&](std::size_t i, std::size_t j) {
    bool covered_left = false, covered_right = false;
    for (std::size_t k = 0; k < n; ++k) {
      if (k == i || k == j || !triangle_in_complex(i, j, k)) continue;
      ((pts[j] - pts[i]).cross(pts[k] - pts[i]) > 0 ? covered_left : covered_right) = true;
    }
    bool in_complex = covered_left || covered_right;
    if (!in_complex && (pts[j] - pts[i]).norm2() <= Q(4) * a) {
      in_complex = true;
      for (std::size_t k = 0; k < n && in_complex; ++k)
        in_complex = k == i || k == j || (pts[k] - pts[i]).dot(pts[k] - pts[j]) >= 0;
    }
    return in_complex && !(covered_left && covered_right);
  });
}

double total_length(const std::vector<Point>& points, const std::vector<Edge>& edges) {
  double sum = 0;
  for (const auto& [i, j] : edges) sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(points[i], points[j])));
  return sum;
}

}  // namespace curvebench::testing
