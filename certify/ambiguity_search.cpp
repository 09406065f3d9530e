#include "certify/ambiguity_search.h"

#include <fstream>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "certify/sampling_measure.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/curve_name.h"
#include "geometry/io/edge_io.h"
#include "geometry/io/point_io.h"
#include "geometry/sampling/seeded_random.h"
#include "geometry/io/svg_picture.h"

namespace curvebench::certify {
namespace {

using geometry::Curve;
using geometry::Seeded_random;
using geometry::Vector;

constexpr double infinity = std::numeric_limits<double>::infinity();

double length(const Vector& v) { return std::sqrt(v.squared_length()); }

// The mirror R: x -> -x. Exact in doubles, and so is every spline built from mirrored
// points (rounding is symmetric under negation), which makes C2 = R(C1) bit for bit.
Point mirrored(const Point& p) { return Point(-p.x(), p.y()); }

// Solves the cyclic tridiagonal system  below[i] x[i-1] + diagonal[i] x[i] + above[i] x[i+1]
// = rhs[i] (indices mod n, n >= 3) by Sherman-Morrison: the corner entries are a rank-one
// correction of a plain tridiagonal matrix, which the Thomas algorithm solves.
std::vector<Vector> solve_cyclic_tridiagonal(const std::vector<double>& below, std::vector<double> diagonal,
                                             const std::vector<double>& above, const std::vector<Vector>& rhs) {
  const std::size_t n = diagonal.size();
  const double gamma = -diagonal[0];
  diagonal[0] -= gamma;
  diagonal[n - 1] -= below[0] * above[n - 1] / gamma;
  // Thomas on the modified matrix, for a vector right-hand side and for u.
  const auto thomas = [&](const auto& d) {
    using T = std::decay_t<decltype(d[0])>;
    std::vector<double> c(n);
    std::vector<T> x(d.begin(), d.end());
    c[0] = above[0] / diagonal[0];
    x[0] = x[0] / diagonal[0];
    for (std::size_t i = 1; i < n; ++i) {
      const double m = diagonal[i] - below[i] * c[i - 1];
      c[i] = i + 1 < n ? above[i] / m : 0;
      x[i] = (x[i] - x[i - 1] * below[i]) / m;
    }
    for (std::size_t i = n - 1; i-- > 0;) x[i] = x[i] - x[i + 1] * c[i];
    return x;
  };
  std::vector<double> u(n, 0.0);
  u[0] = gamma, u[n - 1] = above[n - 1];
  const std::vector<Vector> y = thomas(rhs);
  const std::vector<double> z = thomas(u);
  // v = (1, 0, ..., 0, below[0] / gamma)
  const double vz = z[0] + below[0] / gamma * z[n - 1];
  const Vector vy = y[0] + y[n - 1] * (below[0] / gamma);
  std::vector<Vector> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = y[i] - vy * (z[i] / (1 + vz));
  return x;
}

// ---- polygons ---------------------------------------------------------------------------

// Whether the closed polygon through points[order[0]], points[order[1]], ... is simple:
// exact segment tests, O(n²) (n is small here). Adjacent edges must not be collinear.
bool simple_polygon(std::span<const Point> points, std::span<const std::size_t> order) {
  const std::size_t n = order.size();
  const auto at = [&](std::size_t i) { return points[order[i % n]]; };
  for (std::size_t i = 0; i < n; ++i) {
    if (CGAL::collinear(at(i), at(i + 1), at(i + 2))) return false;
    const geometry::Kernel::Segment_2 a(at(i), at(i + 1));
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the wrap
      if (CGAL::do_intersect(a, geometry::Kernel::Segment_2(at(j), at(j + 1)))) return false;
    }
  }
  return true;
}

double perimeter(std::span<const Point> points, std::span<const std::size_t> order) {
  double total = 0;
  for (std::size_t i = 0; i < order.size(); ++i)
    total += std::sqrt(CGAL::squared_distance(points[order[i]], points[order[(i + 1) % order.size()]]));
  return total;
}

// Every second cyclic order one move away from 0, 1, ..., n-1 whose polygon is simple
// and differs from the first: or-opt (point k taken out and put into another edge) and
// 2-opt (a sub-chain reversed), shortest polygon first (ties by generation order).
std::vector<std::vector<std::size_t>> alternative_orders(std::span<const Point> points) {
  const std::size_t n = points.size();
  std::vector<std::size_t> identity(n);
  for (std::size_t i = 0; i < n; ++i) identity[i] = i;
  const std::vector<Edge> base = order_edges(identity);
  std::vector<std::pair<double, std::vector<std::size_t>>> found;
  const auto consider = [&](std::vector<std::size_t> order) {
    if (order_edges(order) != base && simple_polygon(points, order))
      found.emplace_back(perimeter(points, order), std::move(order));
  };
  for (std::size_t k = 0; k < n; ++k)  // or-opt: k between j and the point after j
    for (std::size_t j = 0; j < n; ++j) {
      if (j == k || (j + 1) % n == k) continue;
      std::vector<std::size_t> order;
      for (std::size_t i = 0; i < n; ++i) {
        if (i == k) continue;
        order.push_back(i);
        if (i == j) order.push_back(k);
      }
      consider(order);
    }
  for (std::size_t i = 1; i < n; ++i)  // 2-opt: reverse i .. j
    for (std::size_t j = i + 1; j < n; ++j) {
      if (i == 1 && j == n - 1) continue;  // the whole cycle but point 0: the same polygon
      std::vector<std::size_t> order = identity;
      std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i), order.begin() + static_cast<std::ptrdiff_t>(j) + 1);
      consider(order);
    }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::vector<std::size_t>> orders;
  for (auto& [cost, order] : found) orders.push_back(std::move(order));
  return orders;
}

// ---- measuring ---------------------------------------------------------------------------

// measure_ambiguity, giving up (invalid) as soon as one epsilon is at least `give_up_at`.
// A `mirror` case (C2 = R(C1) exactly) measures C1 only while searching: eps2 = eps1.
Ambiguity_measure measure(const Ambiguity_case& c, double density, double give_up_at, bool mirror = false) {
  Ambiguity_measure m;
  if (order_edges(c.orders[0]) == order_edges(c.orders[1])) return m;
  for (int k = 0; k < (mirror ? 1 : 2); ++k) {
    Curve curve;
    try {
      curve = ambiguity_curve(c, k);
    } catch (const std::invalid_argument&) {
      return m;  // coincident points or a degenerate spline
    }
    const geometry::Local_feature_size lfs(curve, density);
    if (!lfs.sharp_points().empty()) return m;  // a cusp or a self-crossing
    const Epsilon_measure e = measure_epsilon(lfs, c.points, 0);
    if (!(e.epsilon < give_up_at)) return m;
    m.epsilon[k] = e.epsilon;
    m.where[k] = e.where;
    m.worst_point[k] = lfs.curve().components[e.where.component].point(e.where.parameter);
  }
  if (mirror) m.epsilon[1] = m.epsilon[0], m.where[1] = m.where[0], m.worst_point[1] = mirrored(m.worst_point[0]);
  m.valid = true;
  return m;
}

// ---- the search --------------------------------------------------------------------------

// A uniformly random vector in the disc of radius r (rejection: no libm, same bits everywhere).
Vector in_disc(Seeded_random& random, double r) {
  for (;;) {
    const double x = random.uniform(-1, 1), y = random.uniform(-1, 1);
    if (x * x + y * y <= 1) return Vector(x * r, y * r);
  }
}

std::size_t below(Seeded_random& random, std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(random.uniform() * static_cast<double>(n)));
}

std::size_t nearest_point(std::span<const Point> points, const Point& p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (CGAL::compare_distance_to_point(p, points[i], points[best]) == CGAL::SMALLER) best = i;
  return best;
}

// Whether every two points are at least `distance` apart (O(n²); n is small).
bool separated(std::span<const Point> points, double distance) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (CGAL::squared_distance(points[i], points[j]) < distance * distance) return false;
  return true;
}

// A start: n points at (jittered) equal arc-length steps of a random Fourier curve whose
// polygon is simple, with a second order from alternative_orders() whose two splines
// are smooth and simple. Draws again until one is found (at most 10000 times).
std::pair<Ambiguity_case, Ambiguity_measure> make_start(Seeded_random& random, std::size_t n, double density) {
  for (int attempt = 0;; ++attempt) {
    if (attempt == 10000) throw std::runtime_error("ambiguity search: no start with two smooth simple curves found");
    const auto curve_seed = static_cast<std::uint64_t>(random.uniform() * 0x1.0p53);
    const geometry::Fourier_curve_parameters shape{.harmonics = 2 + static_cast<int>(below(random, 3)),
                                                   .amplitude = random.uniform(0.4, 1.0), .decay = 1.5};
    const Curve base = geometry::random_fourier_curve(curve_seed, shape);
    const geometry::Curve_component& component = base.components[0];
    Ambiguity_case c;
    const double offset = random.uniform();
    for (std::size_t j = 0; j < n; ++j) {
      const double step = (static_cast<double>(j) + offset + random.uniform(-0.2, 0.2)) / static_cast<double>(n);
      c.points.push_back(component.point(component.parameter_at_arc_length(component.length() * std::fmod(step, 1.0))));
    }
    c.orders[0].resize(n);
    for (std::size_t i = 0; i < n; ++i) c.orders[0][i] = i;
    if (!simple_polygon(c.points, c.orders[0])) continue;
    std::vector<std::vector<std::size_t>> alternatives = alternative_orders(c.points);
    // Among the shortest few, a random one first; then the rest in order.
    if (alternatives.empty()) continue;
    std::swap(alternatives[0], alternatives[below(random, std::min<std::size_t>(4, alternatives.size()))]);
    for (std::size_t a = 0; a < std::min<std::size_t>(6, alternatives.size()); ++a) {
      c.orders[1] = alternatives[a];
      const Ambiguity_measure m = measure(c, density, infinity);
      if (m.valid) return {c, m};
    }
  }
}

// ---- mirror-symmetric cases ------------------------------------------------------------
//
// A case with S = R(S) and C2 = R(C1) has eps2 = eps1, and its two orders differ as a
// whole curve differs from its mirror image, not by a local swap of two points (the
// general search's trap, where two swapped points merge and both curves fold).

// mirror[i]: the index of R(points[i]) in S (i itself on the axis x = 0).
struct Mirror_start {
  Ambiguity_case c;
  Ambiguity_measure m;
  std::vector<std::size_t> mirror;
};

// The crossing of segments a0a1 and b0b1 at a0 + t (a1 - a0) = b0 + u (b1 - b0), if they
// cross properly (0 < t, u < 1). Doubles: a start is an experiment's guess, checked later.
std::optional<std::pair<double, double>> crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
  const Vector r = a1 - a0, q = b1 - b0, w = b0 - a0;
  const double denominator = r.x() * q.y() - r.y() * q.x();
  if (denominator == 0) return std::nullopt;
  const double t = (w.x() * q.y() - w.y() * q.x()) / denominator, u = (w.x() * r.y() - w.y() * r.x()) / denominator;
  if (!(t > 0 && t < 1 && u > 0 && u < 1)) return std::nullopt;
  return std::pair{t, u};
}

// The closed polygon through `points` in their order.
double perimeter(std::span<const Point> points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  return perimeter(points, order);
}

// Forces `c` onto the symmetric cases: each mirror pair to the mean of the one and the
// other's mirror image, each axis point onto the axis, and both curves' knot factors to
// their mean (edge k of order 2 is R of edge k of order 1).
void symmetrize(Ambiguity_case& c, std::span<const std::size_t> mirror) {
  for (std::size_t i = 0; i < mirror.size(); ++i) {
    const std::size_t j = mirror[i];
    if (j == i) {
      c.points[i] = Point(0, c.points[i].y());
    } else if (i < j) {
      const Point a = c.points[i], b = mirrored(c.points[j]);
      c.points[i] = Point((a.x() + b.x()) / 2, (a.y() + b.y()) / 2);
      c.points[j] = mirrored(c.points[i]);
    }
  }
  auto& [f1, f2] = c.log_knot_factors;
  for (std::size_t k = 0; k < f1.size() && k < f2.size(); ++k) f1[k] = f2[k] = (f1[k] + f2[k]) / 2;
  auto& [v1, v2] = c.via;
  for (std::size_t e = 0; e < v1.size() && e < v2.size(); ++e) {
    const Point b = mirrored(v2[e]);
    v1[e] = Point((v1[e].x() + b.x()) / 2, (v1[e].y() + b.y()) / 2);
    v2[e] = mirrored(v1[e]);
  }
}

// Gives both curves of `c` a via point in the middle of each of its spline segments: nearly
// the same curves, with twice the points to move.
void add_via_points(Ambiguity_case& c) {
  for (int k = 0; k < 2; ++k) {
    std::vector<Point> via;
    for (const auto& b : curve_controls(c, k))
      via.push_back(Point((b[0].x() + 3 * b[1].x() + 3 * b[2].x() + b[3].x()) / 8,
                          (b[0].y() + 3 * b[1].y() + 3 * b[2].y() + b[3].y()) / 8));
    c.via[k] = std::move(via);
    c.log_knot_factors[k].clear();
  }
}

// A mirror start: S is where a random Fourier curve K crosses its mirror image R(K) (a
// crossing x of K and R(K) has R(x) on both too), order 1 is S along K, order 2 is S
// along R(K), i.e. R of order 1. Kept when it has `points` points (0: 6 to 20), the two
// polygons differ, and the spline C1 through S is smooth and simple (then so is C2 =
// R(C1)). K is drawn wild (large amplitude, shifted off the axis), so that it is far from
// star-shaped: the crossings of a near-circle with its mirror image come in the same
// order on both. Draws again until one is found (at most 10000 times).
Mirror_start make_mirror_start(Seeded_random& random, std::size_t points, double density) {
  for (int attempt = 0;; ++attempt) {
    if (attempt == 10000) throw std::runtime_error("ambiguity search: no mirror start with two smooth simple curves found");
    const auto curve_seed = static_cast<std::uint64_t>(random.uniform() * 0x1.0p53);
    const geometry::Fourier_curve_parameters shape{.harmonics = 2 + static_cast<int>(below(random, 5)),
                                                   .amplitude = random.uniform(0.5, 1.0), .decay = 1.2};
    const Vector shift(random.uniform(-0.4, 0.4), 0);
    Curve base;
    try {
      base = geometry::random_fourier_curve(curve_seed, shape);
    } catch (const std::invalid_argument&) {
      continue;  // too wild to be simple
    }
    std::vector<Point> k = base.components[0].polyline(2e-3 * base.components[0].length());
    for (Point& p : k) p = p + shift;
    const std::size_t m = k.size();
    // Crossings as (position along K, point): segment i of K against segment j of R(K).
    std::vector<std::pair<double, Point>> crossings;
    for (std::size_t i = 0; i < m; ++i) {
      const Point& a0 = k[i];
      const Point& a1 = k[(i + 1) % m];
      if ((a0.x() < 0) != (a1.x() < 0)) {  // K meets the axis: a point of S on it
        const double t = a0.x() / (a0.x() - a1.x());
        crossings.emplace_back(static_cast<double>(i) + t, Point(0, a0.y() + t * (a1.y() - a0.y())));
      }
      for (std::size_t j = 0; j < m; ++j) {
        if (j == i) continue;
        const auto hit = crossing(a0, a1, mirrored(k[j]), mirrored(k[(j + 1) % m]));
        if (!hit) continue;
        const Point x = a0 + hit->first * (a1 - a0);
        if (!(x.x() > 0)) continue;  // its mirror image, found as the pair's other member
        // x on K at i + t; R(x) on K at j + u (segment j of R(K) is R of segment j of K).
        crossings.emplace_back(static_cast<double>(i) + hit->first, x);
        crossings.emplace_back(static_cast<double>(j) + hit->second, mirrored(x));
      }
    }
    const std::size_t n = crossings.size();
    if (n < 6 || n > 20 || (points != 0 && n != points)) continue;
    std::ranges::sort(crossings, {}, &std::pair<double, Point>::first);
    Mirror_start start;
    for (const auto& [position, x] : crossings) start.c.points.push_back(x);
    // Near the axis, rounding can give a crossing twice: keep the points apart.
    if (!separated(start.c.points, 1e-2 * perimeter(k) / static_cast<double>(n))) continue;
    for (const Point& p : start.c.points)
      start.mirror.push_back(static_cast<std::size_t>(std::ranges::find(start.c.points, mirrored(p)) - start.c.points.begin()));
    if (std::ranges::find(start.mirror, n) != start.mirror.end()) continue;  // exact by construction; never
    start.c.orders[0].resize(n);
    for (std::size_t i = 0; i < n; ++i) start.c.orders[0][i] = i, start.c.orders[1].push_back(start.mirror[i]);
    if (!simple_polygon(start.c.points, start.c.orders[0])) continue;
    start.m = measure(start.c, density, infinity, true);
    if (start.m.valid) return start;
  }
}

// Hill climbing from `c` for `evaluations` steps: one point moved (often the one nearest
// the worst curve point), or every point and knot factor a little, or one knot factor; a
// step is kept if it lowers max(eps1, eps2). The step size grows on success and shrinks
// on failure; once it is tiny it is reset (larger trial steps around the local minimum).
// Steps that bring two points closer than `separation` times the start's mean edge are
// refused without a measurement (see Ambiguity_search_options::minimum_separation). With
// a `mirror`, every step is symmetrized, so the case stays mirror-symmetric.
std::pair<Ambiguity_case, Ambiguity_measure> climb(Ambiguity_case c, Ambiguity_measure m, Seeded_random& random,
                                                    std::size_t evaluations, double density, double separation,
                                                    std::span<const std::size_t> mirror = {}) {
  const std::size_t n = c.points.size();
  const bool via = !c.via[0].empty();
  for (auto& factors : c.log_knot_factors) factors.resize(via ? 2 * n : n, 0.0);
  const double scale = perimeter(c.points, c.orders[0]) / static_cast<double>(n);
  double step = 0.15 * scale;
  for (std::size_t e = 0; e < evaluations; ++e) {
    Ambiguity_case next = c;
    const int worse = m.epsilon[1] > m.epsilon[0] ? 1 : 0;
    const double kind = random.uniform();
    if (kind < 0.35) {
      // A sample, or (half the time, with via points) a via point of the worse curve.
      std::vector<Point>& moved = via && random.uniform() < 0.5 ? next.via[worse] : next.points;
      const std::size_t i = random.uniform() < 0.5 ? nearest_point(moved, m.worst_point[worse]) : below(random, moved.size());
      moved[i] = moved[i] + in_disc(random, step);
    } else if (kind < 0.7) {
      for (Point& p : next.points) p = p + in_disc(random, step / 2);
      for (auto& points : next.via)
        for (Point& p : points) p = p + in_disc(random, step / 2);
      for (auto& factors : next.log_knot_factors)
        for (double& factor : factors) factor = std::clamp(factor + random.uniform(-1, 1) * step / scale, -2.0, 2.0);
    } else {
      const int k = random.uniform() < 0.5 ? worse : static_cast<int>(below(random, 2));
      double& factor = next.log_knot_factors[k][below(random, next.log_knot_factors[k].size())];
      factor = std::clamp(factor + random.uniform(-1, 1) * 2 * step / scale, -2.0, 2.0);
    }
    if (!mirror.empty()) symmetrize(next, mirror);
    if (!separated(next.points, separation * scale)) {
      step *= 0.97;
      continue;
    }
    const Ambiguity_measure tried = measure(next, density, m.max_epsilon(), !mirror.empty());
    if (tried.valid && tried.max_epsilon() < m.max_epsilon()) {
      c = std::move(next), m = tried;
      step = std::min(step * 1.3, 0.5 * scale);
    } else {
      step *= 0.97;
      if (step < 1e-3 * scale) step = 0.1 * scale;  // converged: kick it out of the local minimum
    }
  }
  return {c, m};
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::filesystem::filesystem_error("cannot write", path, std::make_error_code(std::errc::io_error));
}

std::string curve_svg(const std::vector<std::array<Point, 4>>& controls) {
  using geometry::format_number;
  const auto xy = [](const Point& p) { return format_number(p.x()) + " " + format_number(p.y()); };
  std::string d = "M " + xy(controls[0][0]);
  for (const auto& b : controls) d += " C " + xy(b[1]) + " " + xy(b[2]) + " " + xy(b[3]);
  return "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path fill=\"none\" stroke=\"black\" d=\"" + d + " Z\"/>\n</svg>\n";
}

std::string json_list(std::span<const std::size_t> values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + std::to_string(values[i]);
  return text + "]";
}

}  // namespace

// ---- the spline ---------------------------------------------------------------------------

std::vector<double> centripetal_knot_intervals(std::span<const Point> points) {
  std::vector<double> h;
  for (std::size_t i = 0; i < points.size(); ++i)
    h.push_back(std::sqrt(length(points[(i + 1) % points.size()] - points[i])));
  return h;
}

std::vector<std::array<Point, 4>> closed_spline_controls(std::span<const Point> q, std::span<const double> h) {
  const std::size_t n = q.size();
  if (n < 3 || h.size() != n) throw std::invalid_argument("closed spline: needs n >= 3 points and n knot intervals");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(h[i] > 0 && h[i] < infinity)) throw std::invalid_argument("closed spline: knot intervals must be positive");
    if (!std::isfinite(q[i].x()) || !std::isfinite(q[i].y())) throw std::invalid_argument("closed spline: non-finite point");
    if (q[i] == q[(i + 1) % n]) throw std::invalid_argument("closed spline: consecutive points coincide");
  }
  // The knot derivatives D_i (per unit of the spline parameter): C2 at knot i between
  // intervals h_{i-1} (before) and h_i (after) is
  //   h_i D_{i-1} + 2 (h_{i-1} + h_i) D_i + h_{i-1} D_{i+1} = 3 (h_i d_{i-1} + h_{i-1} d_i),
  // with d_i = (q_{i+1} - q_i) / h_i the slope of interval i.
  std::vector<double> sub(n), diagonal(n), super(n);
  std::vector<Vector> rhs(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
    sub[i] = h[i], diagonal[i] = 2 * (h[prev] + h[i]), super[i] = h[prev];
    rhs[i] = 3 * (h[i] * ((q[i] - q[prev]) / h[prev]) + h[prev] * ((q[next] - q[i]) / h[i]));
  }
  const std::vector<Vector> d = solve_cyclic_tridiagonal(sub, diagonal, super, rhs);
  // Hermite to Bézier: the inner control points are a third of an interval along D.
  std::vector<std::array<Point, 4>> controls;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = (i + 1) % n;
    controls.push_back({q[i], q[i] + d[i] * (h[i] / 3), q[next] - d[next] * (h[i] / 3), q[next]});
  }
  return controls;
}

Curve closed_spline_curve(std::span<const Point> points, std::span<const double> knot_intervals, std::string name) {
  std::vector<std::shared_ptr<const geometry::Curve_piece>> pieces;
  for (const auto& control : closed_spline_controls(points, knot_intervals)) geometry::append_cubic_bezier(pieces, control);
  Curve curve{std::move(name), {}};
  curve.components.emplace_back(std::move(pieces), true);
  return curve;
}

// ---- a case -------------------------------------------------------------------------------

std::vector<Point> ordered_points(const Ambiguity_case& c, int k) {
  const auto& via = c.via[k];
  if (!via.empty() && via.size() != c.orders[k].size()) throw std::invalid_argument("ambiguity case: one via point per edge");
  std::vector<Point> points;
  for (std::size_t e = 0; e < c.orders[k].size(); ++e) {
    points.push_back(c.points.at(c.orders[k][e]));
    if (!via.empty()) points.push_back(via[e]);
  }
  return points;
}

std::vector<double> knot_intervals(const Ambiguity_case& c, int k) {
  std::vector<double> h = centripetal_knot_intervals(ordered_points(c, k));
  const auto& factors = c.log_knot_factors[k];
  if (!factors.empty() && factors.size() != h.size())
    throw std::invalid_argument("ambiguity case: one knot factor per interval");
  for (std::size_t i = 0; i < factors.size(); ++i) h[i] *= std::exp(factors[i]);
  return h;
}

std::vector<std::array<Point, 4>> curve_controls(const Ambiguity_case& c, int k) {
  return closed_spline_controls(ordered_points(c, k), knot_intervals(c, k));
}

Curve ambiguity_curve(const Ambiguity_case& c, int k) {
  return closed_spline_curve(ordered_points(c, k), knot_intervals(c, k), k == 0 ? "spline C1" : "spline C2");
}

std::vector<Edge> order_edges(std::span<const std::size_t> order) {
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < order.size(); ++i) edges.emplace_back(order[i], order[(i + 1) % order.size()]);
  return geometry::canonical_edges(std::move(edges));
}

Ambiguity_measure measure_ambiguity(const Ambiguity_case& c, double density) { return measure(c, density, infinity); }

Ambiguity_search_result search_ambiguity(const Ambiguity_search_options& options) {
  if (options.count == 0) throw std::invalid_argument("ambiguity search: count must be positive");
  if (options.points != 0 && options.points < 4) throw std::invalid_argument("ambiguity search: at least 4 points");
  Ambiguity_search_result result;
  result.measure = {};
  for (std::size_t s = 0; s < options.count; ++s) {
    // Each start has its own stream, so start s is the same whatever `count` is.
    Seeded_random random(options.seed * 0x9E3779B97F4A7C15ull + s + 1);
    Ambiguity_case c;
    Ambiguity_measure m;
    std::vector<std::size_t> mirror;
    if (options.mirror) {
      Mirror_start start = make_mirror_start(random, options.points, options.search_density);
      c = std::move(start.c), m = start.m, mirror = std::move(start.mirror);
    } else {
      const std::size_t n = options.points ? options.points : 6 + below(random, 11);
      std::tie(c, m) = make_start(random, n, options.search_density);
    }
    std::tie(c, m) = climb(std::move(c), m, random, options.evaluations, options.search_density,
                           options.minimum_separation, mirror);
    if (options.via_points) {
      add_via_points(c);
      if (options.mirror) symmetrize(c, mirror);
      m = measure(c, options.search_density, infinity, options.mirror);
      std::tie(c, m) = climb(std::move(c), m, random, options.evaluations, options.search_density,
                             options.minimum_separation, mirror);
      result.evaluations += options.evaluations + 1;
    }
    const Ambiguity_measure final_measure = measure_ambiguity(c);  // at the default density
    result.start_results.push_back(final_measure.max_epsilon());
    result.evaluations += options.evaluations + 1;
    if (s == 0 || final_measure.max_epsilon() < result.measure.max_epsilon()) {
      result.best = std::move(c), result.measure = final_measure, result.best_start = s;
    }
  }
  return result;
}

// ---- output -------------------------------------------------------------------------------

namespace {

// "C1: epsilon 0.93", built by appending (GCC 12 warns falsely on the operator+ chain).
std::string curve_legend(std::size_t k, double epsilon) {
  std::string legend = "C";
  legend += std::to_string(k + 1);
  legend += ": epsilon ";
  legend += geometry::format_number(epsilon);
  return legend;
}

}  // namespace

Ambiguity_files write_ambiguity_case(const std::filesystem::path& directory, const Ambiguity_case& c,
                                     const Ambiguity_measure& m, std::uint64_t seed,
                                     std::span<const std::pair<std::string, double>> extra) {
  using geometry::format_number;
  std::filesystem::create_directories(directory);
  Ambiguity_files files{directory / "points.xy",
                        {directory / "edges_1.edges", directory / "edges_2.edges"},
                        {directory / "curve_1.svg", directory / "curve_2.svg"},
                        directory / "picture.svg",
                        directory / "summary.json",
                        directory / "replay.sh"};
  geometry::write_points(files.points, c.points);
  const std::string colours[2] = {"#1f77b4", "#d62728"};
  geometry::SvgPicture picture(c.points);
  for (int k = 0; k < 2; ++k) {
    geometry::write_edges(files.edges[k], order_edges(c.orders[k]));
    write_text(files.curves[k], curve_svg(curve_controls(c, k)));
  }
  picture.set_title("ambiguous sampling: " + std::to_string(c.points.size()) + " points, epsilon " +
                    format_number(m.epsilon[0]) + " (C1, blue) and " + format_number(m.epsilon[1]) + " (C2, red)");
  for (int k = 0; k < 2; ++k) {
    const Curve curve = ambiguity_curve(c, k);
    const auto& component = curve.components[0];
    const std::vector<Point> line = component.polyline(1e-4 * component.length());
    std::vector<Edge> chain;
    for (std::size_t i = 0; i < line.size(); ++i) chain.emplace_back(i, (i + 1) % line.size());
    picture.add_edges(line, chain,
                      {.colour = colours[k], .width_px = 2, .opacity = 0.8,
                       .dash_px = k == 0 ? std::vector<double>{} : std::vector<double>{6, 3},
                       .legend = curve_legend(k, m.epsilon[k])});
  }
  picture.add_points({.colour = "#000000", .radius_px = 4, .legend = "S"});
  picture.write(files.picture);

  std::string json = "{\n  \"points\": " + std::to_string(c.points.size()) + ",\n  \"epsilon_1\": " +
                     format_number(m.epsilon[0]) + ",\n  \"epsilon_2\": " + format_number(m.epsilon[1]) +
                     ",\n  \"max_epsilon\": " + format_number(m.max_epsilon()) + ",\n  \"lfs_error_bound\": " +
                     format_number(lfs_relative_error_bound) + ",\n  \"max_epsilon_upper\": " +
                     format_number(m.max_epsilon() / (1 - lfs_relative_error_bound)) +
                     ",\n  \"via_points\": " + std::to_string(c.via[0].size() + c.via[1].size()) +
                     ",\n  \"seed\": " + std::to_string(seed) + ",\n  \"order_1\": " + json_list(c.orders[0]) +
                     ",\n  \"order_2\": " + json_list(c.orders[1]);
  for (const auto& [key, value] : extra) json += ",\n  \"" + key + "\": " + format_number(value);
  json += "\n}\n";
  write_text(files.summary, json);
  write_text(files.replay,
             "#!/bin/sh\n# Re-measures S against C1 and C2 with the project's unfloored epsilon.\n"
             "cd \"$(dirname \"$0\")\"\n"
             "${CURVEBENCH:-curvebench} measure --curve svg:curve_1.svg -i points.xy -e edges_1.edges --min-lfs 0\n"
             "${CURVEBENCH:-curvebench} measure --curve svg:curve_2.svg -i points.xy -e edges_2.edges --min-lfs 0\n");
  return files;
}

}  // namespace curvebench::certify
