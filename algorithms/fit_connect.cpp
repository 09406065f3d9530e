// FitConnect (Ohrhallinger, Wimmer 2018; survey, "Noisy Points Fitting"): see
// fit_connect.h for the algorithm, its deviations from the authors' code and the ties.
#include "algorithms/fit_connect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/k_nearest_neighbor_graph.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {
namespace {

using geometry::cross;
using geometry::difference;
using geometry::dot;
using geometry::Error_bounded_double;
using geometry::squared_length;
using geometry::Vector2;
using Index = std::uint32_t;
constexpr Index none = std::numeric_limits<Index>::max();

void check_input(std::span<const Point> points, const Fit_connect_options& options) {
  if (points.size() >= none) throw std::invalid_argument("fit-connect: too many points");
  for (const Point& p : points)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw std::invalid_argument("fit-connect: a coordinate is not finite");
  std::vector<Point> sorted(points.begin(), points.end());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    throw std::invalid_argument("fit-connect: two points are equal");
  if (!(options.max_neighbors >= 2 && options.max_neighbors <= 1024))
    throw std::invalid_argument("fit-connect: max_neighbors must lie in [2, 1024]");
  if (!(options.corner_angle >= 0 && options.corner_angle <= 180))
    throw std::invalid_argument("fit-connect: corner_angle must lie in [0, 180] degrees");
}

// ---- The Kasa fit as polynomials --------------------------------------------------------
// Least squares of |u|^2 + D ux + E uy + F over the neighbourhood, u = x - p. By Cramer's
// rule its centre, relative to p, is (cx, cy) / w with w = 2 det(M) >= 0 (M is a Gram
// matrix; w = 0 exactly when the points are collinear). The direction from the centre to
// a point x is then that of w u - (cx, cy): a polynomial in the input coordinates.
template <class NT>
struct Fit {
  NT w, cx, cy;
};

template <class NT>
Fit<NT> kasa_fit(std::span<const Point> points, const Point& p, std::span<const Index> members) {
  NT sxx(0), sxy(0), syy(0), sx(0), sy(0), sxz(0), syz(0), sz(0);
  const NT s1(static_cast<double>(members.size() + 1));
  for (const Index m : members) {
    const Vector2<NT> u = difference<NT>(points[m], p);
    const NT z = u.x * u.x + u.y * u.y;
    sxx = sxx + u.x * u.x, sxy = sxy + u.x * u.y, syy = syy + u.y * u.y;
    sx = sx + u.x, sy = sy + u.y;
    sxz = sxz + u.x * z, syz = syz + u.y * z, sz = sz + z;
  }
  const NT det = sxx * (syy * s1 - sy * sy) - sxy * (sxy * s1 - sy * sx) + sx * (sxy * sy - syy * sx);
  const NT det1 = sxz * (syy * s1 - sy * sy) - sxy * (syz * s1 - sy * sz) + sx * (syz * sy - syy * sz);
  const NT det2 = sxx * (syz * s1 - sz * sy) - sxz * (sxy * s1 - sy * sx) + sx * (sxy * sz - syz * sx);
  return {det + det, det1, det2};
}

template <class NT>
Vector2<NT> radial(const Fit<NT>& fit, const Vector2<NT>& u) {
  return {fit.w * u.x - fit.cx, fit.w * u.y - fit.cy};
}

// The sign of Y sqrt(Q) - X sqrt(P) for P, Q > 0, from the signs of X and Y and, when
// they agree, the sign of Y^2 Q - X^2 P.
template <class Squared>
CGAL::Sign root_difference_sign(CGAL::Sign y, CGAL::Sign x, const Squared& squared_difference) {
  if (y != x) return y > x ? CGAL::POSITIVE : CGAL::NEGATIVE;
  if (y == CGAL::ZERO) return CGAL::ZERO;
  const CGAL::Sign s = squared_difference();
  return y == CGAL::POSITIVE ? s : CGAL::opposite(s);
}

// One point's neighbourhood (p and its k nearest) ordered along its fit. Member 0 is p.
class Fitted_neighborhood {
 public:
  Fitted_neighborhood(std::span<const Point> points, Index p, std::span<const Index> neighbors)
      : points_(points), p_(p), neighbors_(neighbors),
        approx_(kasa_fit<Error_bounded_double>(points, points[p], neighbors)) {
    const CGAL::Sign w = geometry::exact_sign(approx_.w, [&]<class NT>(std::type_identity<NT>) {
      return kasa_fit<NT>(points_, points_[p_], neighbors_).w;
    });
    collinear_ = w == CGAL::ZERO;
  }

  // Sorts the members into the two sides of p, each nearest to p along the fit first, and
  // tells whether p is conforming.
  void order(std::array<std::vector<Index>, 2>& sides, bool& conforming) const {
    std::array<std::vector<std::size_t>, 2> members;  // member numbers, 1-based
    for (std::size_t j = 1; j <= neighbors_.size(); ++j) {
      const int s = side(j);
      if (s >= 0) members[s].push_back(j);
    }
    for (int s = 0; s < 2; ++s)
      std::sort(members[s].begin(), members[s].end(), [&](std::size_t a, std::size_t b) { return before(s, a, b); });
    for (int s = 0; s < 2; ++s) {
      sides[s].clear();
      for (const std::size_t j : members[s]) sides[s].push_back(neighbors_[j - 1]);
    }
    conforming = !members[0].empty() && !members[1].empty() &&
                 (collinear_ || (longest_chord(members[0].back(), members[1].back()) &&
                                 longest_chord(members[1].back(), members[0].back())));
  }

 private:
  const Point& point(std::size_t j) const { return j == 0 ? points_[p_] : points_[neighbors_[j - 1]]; }

  // Sign of a polynomial of the fit: the cached approximation first, recomputed exactly
  // when that does not settle it. `value` is a template lambda (fit, u) -> NT where u(j)
  // is member j relative to p.
  template <class Value>
  CGAL::Sign sign(const Value& value) const {
    const auto approx_u = [&](std::size_t j) {
      return j == 0 ? Vector2<Error_bounded_double>{0.0, 0.0} : difference<Error_bounded_double>(point(j), points_[p_]);
    };
    return geometry::exact_sign(value(approx_, approx_u), [&]<class NT>(std::type_identity<NT>) {
      const Fit<NT> fit = kasa_fit<NT>(points_, points_[p_], neighbors_);
      const auto u = [&](std::size_t j) {
        return j == 0 ? Vector2<NT>{NT(0), NT(0)} : difference<NT>(point(j), points_[p_]);
      };
      return value(fit, u);
    });
  }

  // 1 (after p), 0 (before p), or -1 (cannot be ordered: on the fit centre, or the centre
  // is p itself).
  int side(std::size_t j) const {
    if (collinear_) {
      const CGAL::Sign t = geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
        return dot(difference<NT>(point(j), points_[p_]), difference<NT>(point(1), points_[p_]));
      });
      return t == CGAL::POSITIVE ? 1 : 0;  // never zero: distinct collinear points
    }
    const auto zero = [&](std::size_t m) {
      return sign([m]<class NT>(const Fit<NT>& f, const auto& u) { return squared_length(radial(f, u(m))); }) ==
             CGAL::ZERO;
    };
    if (zero(0) || zero(j)) return -1;
    const CGAL::Sign c = sign([j]<class NT>(const Fit<NT>& f, const auto& u) {
      return cross(radial(f, u(0)), radial(f, u(j)));
    });
    if (c != CGAL::ZERO) return c == CGAL::POSITIVE ? 1 : 0;
    return 1;  // on the line through the centre and p: angle 0 or pi, both "after"
  }

  // Whether member a comes before member b (nearer to p along the fit) on side s.
  bool before(int s, std::size_t a, std::size_t b) const {
    if (collinear_) {
      const CGAL::Sign t = geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
        return dot(difference<NT>(point(b), point(a)), difference<NT>(point(1), points_[p_]));
      });
      if (t != CGAL::ZERO) return (t == CGAL::POSITIVE) == (s == 1);
      return neighbors_[a - 1] < neighbors_[b - 1];
    }
    const CGAL::Sign c = sign([a, b]<class NT>(const Fit<NT>& f, const auto& u) {
      return cross(radial(f, u(a)), radial(f, u(b)));
    });
    if (c != CGAL::ZERO) return (c == CGAL::POSITIVE) == (s == 1);
    const CGAL::Sign same = sign([a, b]<class NT>(const Fit<NT>& f, const auto& u) {
      return dot(radial(f, u(a)), radial(f, u(b)));
    });
    if (same == CGAL::POSITIVE) return neighbors_[a - 1] < neighbors_[b - 1];  // same angle
    // Opposite directions (only on side 1: angle 0 against angle pi): angle 0 first.
    return sign([a]<class NT>(const Fit<NT>& f, const auto& u) { return dot(radial(f, u(0)), radial(f, u(a))); }) ==
           CGAL::POSITIVE;
  }

  // Whether, projected on the fit, the chord from a to b is longer than the chord from a
  // to p: cos(a, b) < cos(a, p) for the directions from the centre, i.e.
  // (Va.Vp) |Vb| - (Va.Vb) |Vp| > 0.
  bool longest_chord(std::size_t a, std::size_t b) const {
    const CGAL::Sign y = sign([a]<class NT>(const Fit<NT>& f, const auto& u) {
      return dot(radial(f, u(a)), radial(f, u(0)));
    });
    const CGAL::Sign x = sign([a, b]<class NT>(const Fit<NT>& f, const auto& u) {
      return dot(radial(f, u(a)), radial(f, u(b)));
    });
    return root_difference_sign(y, x, [&] {
             return sign([a, b]<class NT>(const Fit<NT>& f, const auto& u) {
               const Vector2<NT> va = radial(f, u(a)), vb = radial(f, u(b)), vp = radial(f, u(0));
               const NT yy = dot(va, vp), xx = dot(va, vb);
               return yy * yy * squared_length(vb) - xx * xx * squared_length(vp);
             });
           }) == CGAL::POSITIVE;
  }

  std::span<const Point> points_;
  Index p_;
  std::span<const Index> neighbors_;
  Fit<Error_bounded_double> approx_;
  bool collinear_ = false;
};

// ---- Output constructions (double) ------------------------------------------------------
// Circle fits over chain windows, for the denoised positions only. Each fit works in local
// coordinates: translated to its anchor and scaled by a power of two to unit size, so the
// arithmetic neither overflows nor underflows and commutes exactly with scaling the input
// by a power of two.

struct Arc_fit {
  bool usable = false, line = false;
  Point anchor{0, 0};
  int e = 0;                        // local = (x - anchor) * 2^-e
  double mx = 0, my = 0;            // centroid (local)
  double cx = 0, cy = 0, r = 0;     // circle, relative to the centroid (local)
  double dx = 0, dy = 0;            // line: through the centroid, unit direction
  double s2 = 0;                    // residual variance per degree of freedom (local units)
  std::size_t m = 0;                // points fitted
  int parameters = 0;               // 3 circle, 2 line
  double variance() const { return std::ldexp(s2, 2 * e); }      // absolute units
  double sigma() const { return std::ldexp(std::sqrt(s2), e); }  // absolute units
};

// Solves the symmetric 3x3 system a x = b by Gaussian elimination with partial pivoting.
bool solve3(std::array<std::array<double, 4>, 3> a, std::array<double, 3>& x) {
  for (int c = 0; c < 3; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 3; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (!(std::abs(a[pivot][c]) > 0)) return false;
    std::swap(a[c], a[pivot]);
    for (int r = c + 1; r < 3; ++r) {
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < 4; ++k) a[r][k] -= f * a[c][k];
    }
  }
  for (int r = 2; r >= 0; --r) {
    double s = a[r][3];
    for (int k = r + 1; k < 3; ++k) s -= a[r][k] * x[k];
    x[r] = s / a[r][r];
  }
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// The least-squares circle (geometric distances: Kasa's algebraic fit refined by
// Gauss-Newton) or line, whichever has the smaller residual per degree of freedom, of
// the points `members` (at least 4), anchored at `anchor`.
Arc_fit arc_fit(std::span<const Point> points, const Point& anchor, std::span<const Index> members) {
  Arc_fit fit;
  fit.anchor = anchor;
  fit.m = members.size();
  if (fit.m < 4) return fit;
  double extent = 0;
  for (const Index j : members)
    extent = std::max({extent, std::abs(points[j].x() - anchor.x()), std::abs(points[j].y() - anchor.y())});
  if (!(extent > 0) || !std::isfinite(extent)) return fit;
  std::frexp(extent, &fit.e);
  std::vector<double> xs(fit.m), ys(fit.m);
  for (std::size_t j = 0; j < fit.m; ++j) {
    xs[j] = std::ldexp(points[members[j]].x() - anchor.x(), -fit.e);
    ys[j] = std::ldexp(points[members[j]].y() - anchor.y(), -fit.e);
    fit.mx += xs[j], fit.my += ys[j];
  }
  const double count = static_cast<double>(fit.m);
  fit.mx /= count, fit.my /= count;
  double sxx = 0, sxy = 0, syy = 0, sxz = 0, syz = 0, sz = 0;
  for (std::size_t j = 0; j < fit.m; ++j) {
    xs[j] -= fit.mx, ys[j] -= fit.my;
    const double z = xs[j] * xs[j] + ys[j] * ys[j];
    sxx += xs[j] * xs[j], sxy += xs[j] * ys[j], syy += ys[j] * ys[j];
    sxz += xs[j] * z, syz += ys[j] * z, sz += z;
  }
  // The line: principal direction of the centred points.
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  fit.dx = std::cos(angle), fit.dy = std::sin(angle);
  double line_sse = 0;
  for (std::size_t j = 0; j < fit.m; ++j) {
    const double d = xs[j] * fit.dy - ys[j] * fit.dx;
    line_sse += d * d;
  }
  const double line_s2 = line_sse / (count - 2);
  fit.line = true, fit.parameters = 2, fit.s2 = line_s2, fit.usable = std::isfinite(line_s2);
  // The circle: Kasa (x^2 + y^2 + D x + E y + F = 0 in least squares), then Gauss-Newton on
  // the geometric distances, kept only while it lowers their sum of squares.
  std::array<double, 3> kasa{};
  if (!solve3({{{sxx, sxy, 0, -sxz}, {sxy, syy, 0, -syz}, {0, 0, count, -sz}}}, kasa)) return fit;
  double cx = -kasa[0] / 2, cy = -kasa[1] / 2;
  double r2 = cx * cx + cy * cy - kasa[2];
  if (!(r2 > 0) || !(r2 < 1e8)) return fit;  // a line, or too flat to tell
  double r = std::sqrt(r2);
  const auto sse = [&](double a, double b, double rr) {
    double s = 0;
    for (std::size_t j = 0; j < fit.m; ++j) {
      const double d = std::sqrt((xs[j] - a) * (xs[j] - a) + (ys[j] - b) * (ys[j] - b)) - rr;
      s += d * d;
    }
    return s;
  };
  double best = sse(cx, cy, r);
  for (int iteration = 0; iteration < 8; ++iteration) {
    std::array<std::array<double, 4>, 3> a{};
    for (std::size_t j = 0; j < fit.m; ++j) {
      const double gx = xs[j] - cx, gy = ys[j] - cy, g = std::sqrt(gx * gx + gy * gy);
      if (!(g > 0)) return fit;
      const std::array<double, 3> jac{-gx / g, -gy / g, -1.0};
      const double res = g - r;
      for (int u = 0; u < 3; ++u) {
        for (int v = 0; v < 3; ++v) a[u][v] += jac[u] * jac[v];
        a[u][3] -= jac[u] * res;
      }
    }
    std::array<double, 3> step{};
    if (!solve3(a, step)) break;
    const double value = sse(cx + step[0], cy + step[1], r + step[2]);
    if (!(value < best) || !(r + step[2] > 0)) break;
    const bool small = std::abs(step[2]) <= 1e-12 * r;
    cx += step[0], cy += step[1], r += step[2], best = value;
    if (small) break;
  }
  if (!(r < 1e4)) return fit;
  const double circle_s2 = best / (count - 3);
  if (fit.m >= 5 && circle_s2 < line_s2) {
    fit.line = false, fit.parameters = 3, fit.s2 = circle_s2;
    fit.cx = cx, fit.cy = cy, fit.r = r;
  }
  return fit;
}

// The displacement from x to its nearest point on the fit, in absolute units, or nothing
// if that point is farther than the window's extent (a fit that does not reach x).
std::optional<Vector2<double>> displacement(const Arc_fit& fit, const Point& x) {
  const double ux = std::ldexp(x.x() - fit.anchor.x(), -fit.e) - fit.mx;
  const double uy = std::ldexp(x.y() - fit.anchor.y(), -fit.e) - fit.my;
  double qx, qy;
  if (fit.line) {
    const double t = ux * fit.dx + uy * fit.dy;
    qx = t * fit.dx, qy = t * fit.dy;
  } else {
    const double gx = ux - fit.cx, gy = uy - fit.cy, g = std::sqrt(gx * gx + gy * gy);
    if (!(g > 0)) return std::nullopt;
    qx = fit.cx + gx * (fit.r / g), qy = fit.cy + gy * (fit.r / g);
  }
  const double ddx = qx - ux, ddy = qy - uy;
  if (!(ddx * ddx + ddy * ddy <= 1)) return std::nullopt;
  const Vector2<double> d{std::ldexp(ddx, fit.e), std::ldexp(ddy, fit.e)};
  if (!std::isfinite(d.x) || !std::isfinite(d.y)) return std::nullopt;
  return d;
}
// ---- The angle test for sharp corners (exact) --------------------------------------------
// The sign of cos(angle a p b) - c, for the opening angle at p.
CGAL::Sign cosine_minus(const Point& a, const Point& p, const Point& b, double c) {
  const auto d = [&]<class NT>(std::type_identity<NT>) { return dot(difference<NT>(a, p), difference<NT>(b, p)); };
  const CGAL::Sign s = geometry::exact_sign(d);
  const CGAL::Sign target = c > 0 ? CGAL::POSITIVE : c < 0 ? CGAL::NEGATIVE : CGAL::ZERO;
  // cos - c = (d - c |u||v|) / (|u||v|): compare d sqrt(1) against c sqrt(|u|^2 |v|^2).
  return root_difference_sign(s, target, [&] {
    return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
      const Vector2<NT> u = difference<NT>(a, p), v = difference<NT>(b, p);
      const NT dd = dot(u, v);
      return dd * dd - NT(c * c) * squared_length(u) * squared_length(v);
    });
  });
}

// The sign of cos(angle a p b) - cos(angle e q f): POSITIVE if the angle at p is smaller.
CGAL::Sign compare_cosines(const Point& a, const Point& p, const Point& b, const Point& e, const Point& q,
                           const Point& f) {
  const CGAL::Sign s = geometry::exact_sign(
      [&]<class NT>(std::type_identity<NT>) { return dot(difference<NT>(a, p), difference<NT>(b, p)); });
  const CGAL::Sign t = geometry::exact_sign(
      [&]<class NT>(std::type_identity<NT>) { return dot(difference<NT>(e, q), difference<NT>(f, q)); });
  return root_difference_sign(s, t, [&] {
    return geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
      const Vector2<NT> u = difference<NT>(a, p), v = difference<NT>(b, p);
      const Vector2<NT> g = difference<NT>(e, q), h = difference<NT>(f, q);
      const NT x = dot(u, v), y = dot(g, h);
      return x * x * squared_length(g) * squared_length(h) - y * y * squared_length(u) * squared_length(v);
    });
  });
}

// ---- The connection rounds -------------------------------------------------------------
class Fit_connect {
 public:
  Fit_connect(std::span<const Point> points, const Fit_connect_options& options)
      : points_(points), options_(options), n_(points.size()) {}

  Reconstruction run() {
    Reconstruction result;
    result.points.assign(points_.begin(), points_.end());
    if (n_ < 2) return result;
    const graphs::Delaunay_triangulation dt(points_);
    knn_ = graphs::k_nearest_neighbors(dt, static_cast<std::size_t>(options_.max_neighbors));
    k_.assign(n_, 0);
    sides_.resize(n_);
    conforming_.assign(n_, false);
    alive_.assign(n_, true);
    choice_.assign(n_, {none, none});
    containing_.assign(n_, {});
    for (Index p = 0; p < n_; ++p) {
      k_[p] = std::min<std::size_t>(2, knn_[p].size());
      for (std::size_t i = 0; i < k_[p]; ++i) containing_[knn_[p][i]].push_back(p);
      refit(p);
    }
    for (Index p = 0; p < n_; ++p) choose(p);
    connect();
    const std::vector<std::array<Index, 2>> adjacent = adjacency();
    for (Index p = 0; p < n_; ++p)
      for (const Index q : adjacent[p])
        if (q != none && p < q) result.edges.emplace_back(p, q);
    std::sort(result.edges.begin(), result.edges.end());
    denoise(adjacent, result.points);
    return result;
  }

 private:
  std::span<const Index> members(Index p) const { return {knn_[p].data(), k_[p]}; }

  void refit(Index p) {
    const Fitted_neighborhood fit(points_, p, members(p));
    bool conforming = false;
    fit.order(sides_[p], conforming);
    conforming_[p] = conforming;
  }

  // p's choice on each side: the nearest live point along its fit.
  void choose(Index p) {
    for (int s = 0; s < 2; ++s) {
      choice_[p][s] = none;
      for (const Index q : sides_[p][s])
        if (alive_[q]) {
          choice_[p][s] = q;
          break;
        }
    }
  }

  bool chose(Index p, Index q) const { return choice_[p][0] == q || choice_[p][1] == q; }
  int degree(Index p) const {
    int d = 0;
    for (const Index q : choice_[p]) d += q != none && alive_[q] && chose(q, p);
    return d;
  }
  bool turned_down_a_chooser(Index p) const {
    for (const Index q : containing_[p])  // only a point whose neighbourhood holds p can choose it
      if (alive_[q] && chose(q, p) && !chose(p, q)) return true;
    return false;
  }

  void connect() {
    std::vector<Index> check(n_), grow, kill, changed;
    for (Index p = 0; p < n_; ++p) check[p] = p;
    while (!check.empty()) {
      std::sort(check.begin(), check.end());
      check.erase(std::unique(check.begin(), check.end()), check.end());
      grow.clear(), kill.clear(), changed.clear();
      for (const Index p : check) {
        if (!alive_[p] || degree(p) == 2) continue;
        if (k_[p] < knn_[p].size())
          grow.push_back(p);
        else if (conforming_[p] && turned_down_a_chooser(p))
          kill.push_back(p);
      }
      if (grow.empty() && kill.empty()) break;
      for (const Index p : grow) {
        containing_[knn_[p][k_[p]]].push_back(p);
        ++k_[p];
        refit(p);
        changed.push_back(p);
      }
      for (const Index p : kill) alive_[p] = false;
      for (const Index p : kill)
        for (const Index q : containing_[p]) changed.push_back(q);
      std::sort(changed.begin(), changed.end());
      changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
      check.clear();
      for (const Index p : changed) {
        if (!alive_[p]) continue;
        choose(p);
        check.push_back(p);
        check.insert(check.end(), containing_[p].begin(), containing_[p].end());
        for (const Index q : choice_[p])
          if (q != none) check.push_back(q);
      }
    }
  }

  std::vector<std::array<Index, 2>> adjacency() const {
    std::vector<std::array<Index, 2>> adjacent(n_, {none, none});
    for (Index p = 0; p < n_; ++p) {
      if (!alive_[p]) continue;
      int d = 0;
      for (const Index q : choice_[p])
        if (q != none && alive_[q] && chose(q, p)) adjacent[p][d++] = q;
    }
    return adjacent;
  }

  // Sharp corners, then every connected point blended over the fits that hold it.
  void denoise(const std::vector<std::array<Index, 2>>& adjacent, std::vector<Point>& out) const {
    constexpr std::size_t reach = 8;
    const auto walk = [&](Index p, Index first, std::vector<Index>& chain) {
      chain.clear();
      Index previous = p, current = first;
      while (current != none && current != p && chain.size() < reach) {
        chain.push_back(current);
        const Index next = adjacent[current][0] == previous ? adjacent[current][1] : adjacent[current][0];
        previous = current, current = next;
      }
    };
    // The chain points 2, 4 and 8 steps away on both sides (as far as the chain goes and
    // the two walks do not meet): a corner's legs are straight, so its angle is below the
    // threshold at every scale, where a smooth but coarsely sampled bend opens up at the
    // small ones. ends[p]: the pair at the largest scale reached.
    constexpr std::array<std::size_t, 3> scales{2, 4, 8};
    std::vector<std::array<Index, 2>> ends(n_, {none, none});
    std::vector<char> candidate(n_, false), sharp(n_, false), frozen(n_, false);
    std::vector<Index> left, right;
    const double c = std::cos(options_.corner_angle * std::numbers::pi / 180);
    for (Index p = 0; p < n_ && options_.corner_angle > 0; ++p) {
      if (adjacent[p][1] == none) continue;
      walk(p, adjacent[p][0], left);
      walk(p, adjacent[p][1], right);
      std::size_t steps = 0;
      while (steps < left.size() && steps < right.size() &&
             std::find(right.begin(), right.begin() + steps + 1, left[steps]) == right.begin() + steps + 1 &&
             std::find(left.begin(), left.begin() + steps, right[steps]) == left.begin() + steps)
        ++steps;
      if (steps < scales[0]) continue;
      bool below = true;
      for (const std::size_t s : scales)
        if (s <= steps) {
          below = below && cosine_minus(points_[left[s - 1]], points_[p], points_[right[s - 1]], c) == CGAL::POSITIVE;
          ends[p] = {left[s - 1], right[s - 1]};
        }
      candidate[p] = below;
    }
    {
      for (Index p = 0; p < n_; ++p) {
        if (!candidate[p]) continue;
        bool smallest = true;
        for (int s = 0; s < 2 && smallest; ++s) {
          walk(p, adjacent[p][s], left);
          for (const Index q : left) {
            if (!candidate[q]) continue;
            const CGAL::Sign cmp = compare_cosines(points_[ends[p][0]], points_[p], points_[ends[p][1]],
                                                   points_[ends[q][0]], points_[q], points_[ends[q][1]]);
            if (cmp == CGAL::NEGATIVE || (cmp == CGAL::ZERO && q < p)) smallest = false;
          }
        }
        sharp[p] = smallest;
      }
      for (Index p = 0; p < n_; ++p)
        if (sharp[p]) {
          frozen[p] = true;
          for (const Index q : adjacent[p])
            if (q != none) frozen[q] = true;
        }
    }
    // The chains (paths from an end, then cycles) of the connected points.
    std::vector<std::vector<Index>> chains;
    std::vector<char> closed;
    {
      std::vector<char> visited(n_, false);
      const auto walk_chain = [&](Index start, bool cycle) {
        std::vector<Index> chain{start};
        visited[start] = true;
        Index previous = start, current = adjacent[start][0];
        while (current != none && !visited[current]) {
          visited[current] = true;
          chain.push_back(current);
          const Index next = adjacent[current][0] == previous ? adjacent[current][1] : adjacent[current][0];
          previous = current, current = next;
        }
        chains.push_back(std::move(chain));
        closed.push_back(cycle);
      };
      for (Index p = 0; p < n_; ++p)
        if (!visited[p] && adjacent[p][0] != none && adjacent[p][1] == none) walk_chain(p, false);
      for (Index p = 0; p < n_; ++p)
        if (!visited[p] && adjacent[p][1] != none) walk_chain(p, true);
    }
    // Local spacing: the mean length of a point's edges (the unit of the blending weights).
    std::vector<double> spacing(n_, 0);
    for (Index p = 0; p < n_; ++p) {
      double sum = 0;
      int count = 0;
      for (const Index q : adjacent[p])
        if (q != none) sum += std::sqrt(squared_length(difference<double>(points_[q], points_[p]))), ++count;
      if (count > 0) spacing[p] = sum / count;
    }
    // Every non-sharp point's fit: the window of its chain neighbours up to w steps on each
    // side (never past a sharp point), w among 2, 3, 4, 6, 8, 12, 16, chosen by generalised
    // cross-validation, the residual variance per degree of freedom times m / (m - p),
    // averaged over the point and its two chain neighbours on each side (one window's
    // residual, with as few as 2 degrees of freedom, is too noisy a guide alone). Noise
    // keeps the score falling as w grows; a bend the circle cannot follow makes it rise.
    constexpr std::array<int, 7> widths{2, 3, 4, 6, 8, 12, 16};
    constexpr std::ptrdiff_t pool = 2;
    std::vector<Arc_fit> fits(n_);
    std::vector<std::vector<std::pair<Index, int>>> windows(n_);  // (point, steps from the anchor)
    std::vector<int> half(n_, 0);
    std::vector<Index> members;
    std::vector<std::pair<Index, int>> window;
    for (std::size_t c = 0; c < chains.size(); ++c) {
      const std::vector<Index>& chain = chains[c];
      const auto m = static_cast<std::ptrdiff_t>(chain.size());
      const auto build = [&](std::ptrdiff_t i, int w) {
        window.assign(1, {chain[i], 0});
        for (const int side : {-1, 1})
          for (int step = 1; step <= w; ++step) {
            std::ptrdiff_t at = i + side * step;
            if (closed[c]) {
              if (2 * step > m - 1 + (side > 0 && m % 2 == 0)) break;  // each point once
              at = ((at % m) + m) % m;
            } else if (at < 0 || at >= m) {
              break;
            }
            window.emplace_back(chain[at], step);
            if (sharp[chain[at]]) break;
          }
        members.clear();
        for (const auto& [q, step] : window) members.push_back(q);
      };
      std::vector<std::array<double, widths.size()>> score(chain.size());
      for (std::ptrdiff_t i = 0; i < m; ++i) {
        score[i].fill(std::numeric_limits<double>::infinity());
        if (sharp[chain[i]]) continue;
        std::size_t previous_size = 0;
        for (std::size_t k = 0; k < widths.size(); ++k) {
          build(i, widths[k]);
          if (window.size() == previous_size) break;  // the chain is exhausted
          previous_size = window.size();
          const Arc_fit fit = arc_fit(points_, points_[chain[i]], members);
          if (fit.usable)
            score[i][k] = fit.variance() * static_cast<double>(fit.m) / static_cast<double>(fit.m - fit.parameters);
        }
      }
      for (std::ptrdiff_t i = 0; i < m; ++i) {
        if (sharp[chain[i]]) continue;
        double best = std::numeric_limits<double>::infinity();
        std::size_t chosen = widths.size();
        for (std::size_t k = 0; k < widths.size(); ++k) {
          if (!std::isfinite(score[i][k])) continue;
          double sum = 0;
          int count = 0;
          for (std::ptrdiff_t d = -pool; d <= pool; ++d) {
            std::ptrdiff_t j = i + d;
            if (closed[c])
              j = ((j % m) + m) % m;
            else if (j < 0 || j >= m)
              continue;
            if (std::isfinite(score[j][k])) sum += score[j][k], ++count;
          }
          if (sum / count < best) best = sum / count, chosen = k;  // ties: the smaller window
        }
        if (chosen == widths.size()) continue;
        build(i, widths[chosen]);
        fits[chain[i]] = arc_fit(points_, points_[chain[i]], members);
        windows[chain[i]] = window, half[chain[i]] = widths[chosen];
      }
    }
    // Blending: each point moves by the weighted mean of its displacements onto the fits
    // whose window holds it, weighted by a biweight window kernel (a fit is most accurate
    // at its anchor) over the fit's residual variance, and by at most its own fit's RMS
    // residual (its estimated noise): noise-free input, whose fits have residuals near 0,
    // barely moves. Sharp points and their chain neighbours stay where they are.
    std::vector<double> sx(n_, 0), sy(n_, 0), sw(n_, 0);
    for (Index p = 0; p < n_; ++p) {
      if (!fits[p].usable) continue;
      for (const auto& [q, step] : windows[p]) {
        if (frozen[q] || !(spacing[q] > 0)) continue;
        const auto d = displacement(fits[p], points_[q]);
        if (!d) continue;
        const double t = static_cast<double>(step) / (half[p] + 1);
        const double relative = fits[p].sigma() / spacing[q];
        const double weight = (1 - t * t) * (1 - t * t) / (relative * relative + 1e-12);
        if (!std::isfinite(weight)) continue;
        sx[q] += weight * d->x, sy[q] += weight * d->y, sw[q] += weight;
      }
    }
    for (Index x = 0; x < n_; ++x) {
      if (!(sw[x] > 0) || frozen[x] || !fits[x].usable) continue;
      double mx = sx[x] / sw[x], my = sy[x] / sw[x];
      const double cap = fits[x].sigma(), length = std::sqrt(mx * mx + my * my);
      if (!(length <= cap)) {
        if (!(length > 0) || !(cap > 0) || !std::isfinite(length)) continue;
        mx *= cap / length, my *= cap / length;
      }
      const Point moved(points_[x].x() + mx, points_[x].y() + my);
      if (std::isfinite(moved.x()) && std::isfinite(moved.y())) out[x] = moved;
    }
  }

  std::span<const Point> points_;
  Fit_connect_options options_;
  std::size_t n_;
  std::vector<std::vector<Index>> knn_;
  std::vector<std::size_t> k_;
  std::vector<std::array<std::vector<Index>, 2>> sides_;
  std::vector<char> conforming_, alive_;
  std::vector<std::array<Index, 2>> choice_;
  std::vector<std::vector<Index>> containing_;  // containing_[q]: the points whose neighbourhood holds q
};

}  // namespace

Reconstruction fit_connect_reconstruction(std::span<const Point> points, Fit_connect_options options) {
  check_input(points, options);
  return Fit_connect(points, options).run();
}

Algorithm fit_connect_algorithm() {
  static const Parameter max_neighbors{.name = "max_neighbors",
                                       .type = Parameter_type::integer,
                                       .default_value = 16,
                                       .minimum = 2,
                                       .maximum = 64,
                                       .meaning = "largest neighbourhood a point's arc fit grows to"};
  static const Parameter corner_angle{.name = "corner_angle",
                                      .type = Parameter_type::real,
                                      .default_value = 100,
                                      .minimum = 0,
                                      .maximum = 180,
                                      .meaning = "degrees; chain angles below it may be sharp corners (0: none)"};
  return {
      .name = "fit-connect",
      .title = "FitConnect",
      .reference = "Ohrhallinger, Wimmer 2018",
      .category = "Noisy Points Fitting",
      .parameters = {max_neighbors, corner_angle},
      .capabilities = {.non_uniform = Support::yes, .noise = Support::yes, .outliers = Support::yes,
                       .manifold = Support::yes, .open = Support::yes, .multiple = Support::yes,
                       .sharp = Support::yes, .guarantee = true, .time_complexity = "O(n k^2)"},
      .condition = {.statement = "as HNN-Crust (survey's table; not certified for this implementation)"},
      .reconstruct = [](std::span<const Point> points, const Parameter_values& values) {
        return fit_connect_reconstruction(
            points, {.max_neighbors = static_cast<int>(values[max_neighbors]), .corner_angle = values[corner_angle]});
      },
  };
}

}  // namespace curvebench::algorithms
