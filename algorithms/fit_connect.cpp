// FitConnect (Ohrhallinger, Wimmer 2018; survey, "Noisy Points Fitting"): see
// fit_connect.h for the algorithm, its deviations from the authors' code and the ties.
#include "algorithms/fit_connect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/nearest_neighbor_stream.h"
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
  if (!(options.max_neighbors >= 2 && options.max_neighbors <= 65536))
    throw std::invalid_argument("fit-connect: max_neighbors must lie in [2, 65536]");
  if (!(options.sharp_angle >= 0 && options.sharp_angle <= 180))
    throw std::invalid_argument("fit-connect: sharp_angle must lie in [0, 180] degrees");
  if (!(options.smoothing >= 0 && options.smoothing <= 64))
    throw std::invalid_argument("fit-connect: smoothing must lie in [0, 64]");
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

// The sums of the normal equations, relative to p.
template <class NT>
struct Kasa_sums {
  NT sxx{0}, sxy{0}, syy{0}, sx{0}, sy{0}, sxz{0}, syz{0}, sz{0};
  std::size_t count = 1;  // p itself, at the origin

  void add(const Vector2<NT>& u) {
    const NT z = u.x * u.x + u.y * u.y;
    sxx = sxx + u.x * u.x, sxy = sxy + u.x * u.y, syy = syy + u.y * u.y;
    sx = sx + u.x, sy = sy + u.y;
    sxz = sxz + u.x * z, syz = syz + u.y * z, sz = sz + z;
    ++count;
  }

  Fit<NT> fit() const {
    const NT s1(static_cast<double>(count));
    const NT det = sxx * (syy * s1 - sy * sy) - sxy * (sxy * s1 - sy * sx) + sx * (sxy * sy - syy * sx);
    const NT det1 = sxz * (syy * s1 - sy * sy) - sxy * (syz * s1 - sy * sz) + sx * (syz * sy - syy * sz);
    const NT det2 = sxx * (syz * s1 - sz * sy) - sxz * (sxy * s1 - sy * sx) + sx * (sxy * sz - syz * sx);
    return {det + det, det1, det2};
  }
};

template <class NT>
Vector2<NT> radial(const Fit<NT>& fit, const Vector2<NT>& u) {
  return {fit.w * u.x - fit.cx, fit.w * u.y - fit.cy};
}

// ---- The hyper fit, a construction ------------------------------------------------------
// The authors order each neighbourhood around Al-Sharadqah and Chernov's "hyper" circle fit
// (an algebraic fit without essential bias; Electronic Journal of Statistics 3, 2009). Its
// centre solves a quartic, so it is computed here in double, by Newton's method from 0 on
// the quartic's smallest root as in that paper, and then taken as exact: every decision on
// the neighbourhood is an exact sign with this centre as a given point, as CGAL's
// Exact_predicates_inexact_constructions_kernel treats any construction. Kasa's fit, whose
// centre is rational, serves where this one degenerates (nearly collinear members).
// Returns the centre minus p, or nothing.
std::optional<Vector2<double>> hyper_fit_centre(std::span<const Point> points, Index p, std::span<const Index> neighbors) {
  double extent = 0;
  for (const Index m : neighbors)
    extent = std::max({extent, std::abs(points[m].x() - points[p].x()), std::abs(points[m].y() - points[p].y())});
  if (!(extent > 0) || !std::isfinite(extent)) return std::nullopt;
  int e = 0;  // members in units of 2^e about p, so that no moment overflows or underflows
  std::frexp(extent, &e);
  std::vector<Vector2<double>> u;
  u.reserve(neighbors.size() + 1);
  u.push_back({0, 0});
  double mean_x = 0, mean_y = 0;
  for (const Index m : neighbors) {
    u.push_back({std::ldexp(points[m].x() - points[p].x(), -e), std::ldexp(points[m].y() - points[p].y(), -e)});
    mean_x += u.back().x, mean_y += u.back().y;
  }
  const double count = static_cast<double>(u.size());
  mean_x /= count, mean_y /= count;
  double mxx = 0, myy = 0, mxy = 0, mxz = 0, myz = 0, mzz = 0;  // central moments, z = x^2 + y^2
  for (const auto& [ux, uy] : u) {
    const double x = ux - mean_x, y = uy - mean_y, z = x * x + y * y;
    mxx += x * x, myy += y * y, mxy += x * y, mxz += x * z, myz += y * z, mzz += z * z;
  }
  mxx /= count, myy /= count, mxy /= count, mxz /= count, myz /= count, mzz /= count;
  const double mz = mxx + myy, covariance = mxx * myy - mxy * mxy, z_variance = mzz - mz * mz;
  // The characteristic polynomial 4 t^4 + a2 t^2 + a1 t + a0 of the constrained least squares.
  const double a2 = 4 * covariance - 3 * mz * mz - mzz;
  const double a1 = z_variance * mz + 4 * covariance * mz - mxz * mxz - myz * myz;
  const double a0 = mxz * (mxz * myy - myz * mxy) + myz * (myz * mxx - mxz * mxy) - z_variance * covariance;
  double t = 0, value = a0;
  for (int iteration = 0; iteration < 99; ++iteration) {
    const double next = t - value / (a1 + t * (2 * a2 + 16 * t * t));
    if (next == t || !std::isfinite(next)) break;
    const double next_value = a0 + next * (a1 + next * (a2 + 4 * next * next));
    if (!(std::abs(next_value) < std::abs(value))) break;
    t = next, value = next_value;
  }
  const double det = t * t - t * mz + covariance;
  if (!(det > 1e-14 * mz * mz)) return std::nullopt;
  const double cx = (mxz * (myy - t) - myz * mxy) / det / 2, cy = (myz * (mxx - t) - mxz * mxy) / det / 2;
  const Vector2<double> centre{std::ldexp(cx + mean_x, e), std::ldexp(cy + mean_y, e)};
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y)) return std::nullopt;
  return centre;
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
      : points_(points), p_(p), neighbors_(neighbors), scale_(filter_exponent(points, p, neighbors)),
        centre_(hyper_centre()), approx_(fit<Error_bounded_double>()) {
    approx_radial_.reserve(neighbors.size() + 1);
    approx_radial_.push_back(radial(approx_, Vector2<Error_bounded_double>{0.0, 0.0}));
    for (const Index m : neighbors) approx_radial_.push_back(radial(approx_, local<Error_bounded_double>(points[m])));
    if (centre_) return;
    const CGAL::Sign w = geometry::exact_sign(approx_.w, [&]<class NT>(std::type_identity<NT>) {
      return fitted<NT>().fit.w;
    });
    collinear_ = w == CGAL::ZERO;
  }

  // Sorts the members into the two sides of p, each nearest to p along the fit first, and
  // tells whether p is conforming. `guess` is a guess of the members' order along the fit
  // (member numbers, 1-based; the last fit's order, when a neighbourhood grows by a point):
  // it makes the sort nearly linear, and is replaced by this fit's order.
  void order(std::vector<std::uint32_t>& guess, std::array<std::vector<Index>, 2>& sides, bool& conforming) const {
    // Members the guess lacks (new ones) go to its end, then all are sorted by the angle in
    // double (insertion sort: a grown neighbourhood's order barely changes), each side is
    // checked pair by adjacent pair with the exact order, and only a side with a pair out of
    // order is sorted again by the exact order alone. The result is the exact order either way.
    std::vector<bool> listed(neighbors_.size() + 1, false);
    for (const std::uint32_t j : guess) listed[j] = true;
    for (std::uint32_t j = 1; j <= neighbors_.size(); ++j)
      if (!listed[j]) guess.push_back(j);
    std::vector<std::pair<double, std::uint32_t>> keyed;
    keyed.reserve(guess.size());
    for (const std::uint32_t j : guess) keyed.emplace_back(approximate_angle(j), j);
    std::size_t moves = 0;  // a guess far off (the fit turned over) falls back to a full sort
    for (std::size_t i = 1; i < keyed.size() && moves <= 8 * keyed.size(); ++i)
      for (std::size_t k = i; k > 0 && keyed[k].first < keyed[k - 1].first; --k, ++moves) std::swap(keyed[k], keyed[k - 1]);
    if (moves > 8 * keyed.size())
      std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::array<std::vector<std::size_t>, 2> members;
    for (const auto& [key, j] : keyed) {
      const int s = side(j);
      if (s >= 0) members[s].push_back(j);
    }
    std::reverse(members[0].begin(), members[0].end());
    for (int s = 0; s < 2; ++s) {
      const auto exact_before = [&](std::size_t a, std::size_t b) { return before(s, a, b); };
      if (std::adjacent_find(members[s].begin(), members[s].end(),
                             [&](std::size_t a, std::size_t b) { return !exact_before(a, b); }) != members[s].end())
        std::sort(members[s].begin(), members[s].end(), exact_before);
    }
    guess.assign(members[0].rbegin(), members[0].rend());
    guess.insert(guess.end(), members[1].begin(), members[1].end());
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

  // The power of two the filters scale the differences from p by: 0 for ordinary
  // coordinates, else the exponent of the largest difference. The predicates below are
  // homogeneous in the differences, of degree up to 30, so at coordinates near 1e300 (or
  // far apart in magnitude) they overflow double and intervals and every sign went to
  // GMP: 24 of the fuzzer's points, at 1e301 to 1e303, took 0.15 s, 0.0075 s scaled.
  static int filter_exponent(std::span<const Point> points, Index p, std::span<const Index> neighbors) {
    double largest = 0, farthest = std::max(std::abs(points[p].x()), std::abs(points[p].y()));
    for (const Index m : neighbors) {
      largest = std::max({largest, std::abs(points[m].x() - points[p].x()), std::abs(points[m].y() - points[p].y())});
      farthest = std::max({farthest, std::abs(points[m].x()), std::abs(points[m].y())});
    }
    if (!(largest > 0)) return 0;
    const int e = std::isinf(largest) ? 1024 : std::ilogb(largest);  // every difference is below 2^1025
    // Not where scaling would overflow a coordinate: tiny differences of huge coordinates.
    if (std::abs(e) <= 16 || std::ilogb(farthest) - e > 1000) return 0;
    return e;
  }

  // Member x's difference from p in the filters' frame (exact numbers need none).
  template <class NT>
  Vector2<NT> local(const Point& x) const {
    if constexpr (!std::is_same_v<NT, geometry::Exact_number>)
      if (scale_ != 0) return geometry::scaled_difference<NT>(x, points_[p_], scale_);
    return difference<NT>(x, points_[p_]);
  }

  // The hyper fit's centre in the filters' frame (minus p, scaled by 2^-scale_), such that
  // scaling it back is exact too; or nothing (Kasa's fit then).
  std::optional<Vector2<double>> hyper_centre() const {
    const auto centre = hyper_fit_centre(points_, p_, neighbors_);
    if (!centre) return std::nullopt;
    const Vector2<double> framed{std::ldexp(centre->x, -scale_), std::ldexp(centre->y, -scale_)};
    if (std::ldexp(std::ldexp(framed.x, scale_), -scale_) != framed.x ||
        std::ldexp(std::ldexp(framed.y, scale_), -scale_) != framed.y || !std::isfinite(std::ldexp(framed.x, scale_)) ||
        !std::isfinite(std::ldexp(framed.y, scale_)))
      return std::nullopt;
    return framed;
  }

  // The fit as the polynomials radial() takes: the hyper fit's centre (w = 1), else Kasa's.
  template <class NT>
  Fit<NT> fit() const {
    if (!centre_) return kasa_fit<NT>();
    if constexpr (std::is_same_v<NT, geometry::Exact_number>)
      return {NT(1), NT(std::ldexp(centre_->x, scale_)), NT(std::ldexp(centre_->y, scale_))};
    else
      return {NT(1), NT(centre_->x), NT(centre_->y)};
  }

  template <class NT>
  Fit<NT> kasa_fit() const {
    Kasa_sums<NT> sums;
    for (const Index m : neighbors_) sums.add(local<NT>(points_[m]));
    return sums.fit();
  }

  // Member j's angle around the fit's centre from p's direction, in double: only a sort key
  // (collinear neighbourhoods: the position along the line).
  double approximate_angle(std::size_t j) const {
    if (collinear_) {
      const double dx = point(j).x() - points_[p_].x(), dy = point(j).y() - points_[p_].y();
      const double ux = point(1).x() - points_[p_].x(), uy = point(1).y() - points_[p_].y();
      return dx * ux + dy * uy;
    }
    const Vector2<Error_bounded_double>& a = approx_radial_[0];
    const Vector2<Error_bounded_double>& b = approx_radial_[j];
    const double ax = a.x.value(), ay = a.y.value(), bx = b.x.value(), by = b.y.value();
    // A pseudo-angle, increasing with the angle on (-pi, pi] but cheaper than atan2.
    const double sine = ax * by - ay * bx, cosine = ax * bx + ay * by, size = std::abs(sine) + std::abs(cosine);
    if (!(size > 0)) return 0;
    const double t = sine / size;  // in [-1, 1]
    return cosine >= 0 ? t : (sine >= 0 ? 2 - t : -2 - t);
  }

  // Sign of a polynomial of the fit: first from the cached approximations of the radial
  // vectors, recomputed exactly when that does not settle it. `value` is a template lambda
  // (std::type_identity<NT>, r) -> NT where r(j) is the direction from the fit's centre to
  // member j (scaled by the fit's denominator).
  template <class Value>
  CGAL::Sign sign(const Value& value) const {
    const auto approx_r = [&](std::size_t j) -> const Vector2<Error_bounded_double>& { return approx_radial_[j]; };
    return geometry::exact_sign(value(std::type_identity<Error_bounded_double>{}, approx_r), [&]<class NT>(std::type_identity<NT> type) {
      const std::vector<Vector2<NT>>& radials = fitted<NT>().radials;
      return value(type, [&](std::size_t j) -> const Vector2<NT>& { return radials[j]; });
    });
  }

  // The fit and every member's radial vector in NT (intervals or exact), computed once
  // when a sign first needs them: degenerate neighbourhoods (cocircular, collinear runs)
  // need them for nearly every comparison, and a fit costs O(k).
  template <class NT>
  struct Fitted {
    Fit<NT> fit;
    std::vector<Vector2<NT>> radials;  // member j's, j = 0 is p
  };

  template <class NT>
  const Fitted<NT>& fitted() const {
    std::optional<Fitted<NT>>& cache = std::get<std::optional<Fitted<NT>>>(exact_caches_);
    if (!cache) {
      cache.emplace(Fitted<NT>{fit<NT>(), {}});
      cache->radials.reserve(neighbors_.size() + 1);
      cache->radials.push_back(radial(cache->fit, Vector2<NT>{NT(0), NT(0)}));
      for (const Index m : neighbors_) cache->radials.push_back(radial(cache->fit, local<NT>(points_[m])));
    }
    return *cache;
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
      return sign([m]<class NT>(std::type_identity<NT>, const auto& r) { return squared_length(r(m)); }) ==
             CGAL::ZERO;
    };
    if (zero(0) || zero(j)) return -1;
    const CGAL::Sign c = sign([j]<class NT>(std::type_identity<NT>, const auto& r) {
      return cross(r(0), r(j));
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
    const CGAL::Sign c = sign([a, b]<class NT>(std::type_identity<NT>, const auto& r) {
      return cross(r(a), r(b));
    });
    if (c != CGAL::ZERO) return (c == CGAL::POSITIVE) == (s == 1);
    const CGAL::Sign same = sign([a, b]<class NT>(std::type_identity<NT>, const auto& r) {
      return dot(r(a), r(b));
    });
    if (same == CGAL::POSITIVE) return neighbors_[a - 1] < neighbors_[b - 1];  // same angle
    // Opposite directions (only on side 1: angle 0 against angle pi): angle 0 first.
    return sign([a]<class NT>(std::type_identity<NT>, const auto& r) { return dot(r(0), r(a)); }) ==
           CGAL::POSITIVE;
  }

  // Whether, projected on the fit, the chord from a to b is longer than the chord from a
  // to p: cos(a, b) < cos(a, p) for the directions from the centre, i.e.
  // (Va.Vp) |Vb| - (Va.Vb) |Vp| > 0.
  bool longest_chord(std::size_t a, std::size_t b) const {
    const CGAL::Sign y = sign([a]<class NT>(std::type_identity<NT>, const auto& r) {
      return dot(r(a), r(0));
    });
    const CGAL::Sign x = sign([a, b]<class NT>(std::type_identity<NT>, const auto& r) {
      return dot(r(a), r(b));
    });
    return root_difference_sign(y, x, [&] {
             return sign([a, b]<class NT>(std::type_identity<NT>, const auto& r) {
               const Vector2<NT> va = r(a), vb = r(b), vp = r(0);
               const NT yy = dot(va, vp), xx = dot(va, vb);
               return yy * yy * squared_length(vb) - xx * xx * squared_length(vp);
             });
           }) == CGAL::POSITIVE;
  }

  std::span<const Point> points_;
  Index p_;
  std::span<const Index> neighbors_;
  int scale_;
  std::optional<Vector2<double>> centre_;  // the hyper fit's, in the filters' frame
  Fit<Error_bounded_double> approx_;
  std::vector<Vector2<Error_bounded_double>> approx_radial_;  // member j's, j = 0 is p
  mutable std::tuple<std::optional<Fitted<CGAL::Interval_nt_advanced>>, std::optional<Fitted<geometry::Exact_number>>>
      exact_caches_;
  bool collinear_ = false;
};

// ---- Output constructions (double) ------------------------------------------------------
// Circle (or line) fits over a neighbourhood, for the blended positions only. Each fit works in local
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
  fit.line = true, fit.s2 = line_s2, fit.usable = std::isfinite(line_s2);
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
    fit.line = false, fit.s2 = circle_s2;
    fit.cx = cx, fit.cy = cy, fit.r = r;
  }
  return fit;
}

// The displacement from x to its nearest point on the fit, in absolute units, or nothing
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


// The nearest point of a fit to x, if it lies on the fitted arc: between the fit's
// extreme members as seen along the fit (the authors keep a projection only inside the
// fitted arc too). Absolute coordinates; output construction only.
class Arc_projection {
 public:
  Arc_projection(std::span<const Point> points, Index anchor, std::span<const Index> members)
      : fit_(arc_fit(points, points[anchor], members)) {
    if (!fit_.usable) return;
    lo_ = std::numeric_limits<double>::infinity(), hi_ = -lo_;
    const Vector2<double> reference = local(points[anchor]);
    for (const Index m : members) {
      const double t = position(local(points[m]), reference);
      lo_ = std::min(lo_, t), hi_ = std::max(hi_, t);
    }
    reference_ = reference;
  }

  bool usable() const { return fit_.usable; }
  // The fit's mean squared residual per degree of freedom, in absolute units.
  double residual() const { return std::ldexp(fit_.s2, 2 * fit_.e); }

  std::optional<Point> project(const Point& x) const {
    if (!fit_.usable) return std::nullopt;
    const Vector2<double> u = local(x);
    Vector2<double> q;
    if (fit_.line) {
      const double t = u.x * fit_.dx + u.y * fit_.dy;
      q = {t * fit_.dx, t * fit_.dy};
    } else {
      const double gx = u.x - fit_.cx, gy = u.y - fit_.cy, g = std::sqrt(gx * gx + gy * gy);
      if (!(g > 0)) return std::nullopt;
      q = {fit_.cx + gx * (fit_.r / g), fit_.cy + gy * (fit_.r / g)};
    }
    const double t = position(q, reference_);
    if (!(t >= lo_ && t <= hi_)) return std::nullopt;
    const Point result(std::ldexp(q.x + fit_.mx, fit_.e) + fit_.anchor.x(), std::ldexp(q.y + fit_.my, fit_.e) + fit_.anchor.y());
    if (!std::isfinite(result.x()) || !std::isfinite(result.y())) return std::nullopt;
    return result;
  }

 private:
  Vector2<double> local(const Point& x) const {
    return {std::ldexp(x.x() - fit_.anchor.x(), -fit_.e) - fit_.mx, std::ldexp(x.y() - fit_.anchor.y(), -fit_.e) - fit_.my};
  }
  // Where u lies along the fit: arc length along a line, angle from the reference around
  // a circle's centre.
  double position(const Vector2<double>& u, const Vector2<double>& reference) const {
    if (fit_.line) return u.x * fit_.dx + u.y * fit_.dy;
    const double ax = reference.x - fit_.cx, ay = reference.y - fit_.cy, bx = u.x - fit_.cx, by = u.y - fit_.cy;
    return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }

  Arc_fit fit_;
  Vector2<double> reference_{0, 0};
  double lo_ = 0, hi_ = 0;
};

// ---- The state machine of the authors' reconstructNoisy -----------------------------------
// Every point starts unhandled and is fitted with its two nearest neighbours. Rounds visit
// the unhandled points in index order; each visit grows the point's neighbourhood by the
// next nearest point, refits it, and updates the "overlaps": p and q overlap when each
// lies in the other's fitted neighbourhood, on facing sides, and they become each other's
// curve neighbours ("links"). The points strictly between two overlapping points, in both
// neighbourhoods, are redundant and eliminated: this is what thins a noisy band to one
// chain of representative points. A point with links on both sides is manifold (handled);
// a point whose neighbourhood cannot grow any more becomes a leaf (a curve end) or is
// eliminated. The rules below are the authors', renamed; see fit_connect.h for the few
// places where ours differ.
enum class State : std::uint8_t { initial, conform, nonconform, manifold, sharp, leaf, eliminated };

bool is_handled(State s) { return s == State::manifold || s == State::sharp || s == State::leaf || s == State::eliminated; }
bool on_curve(State s) { return s == State::manifold || s == State::sharp || s == State::leaf; }

class Fit_connect {
 public:
  Fit_connect(std::span<const Point> points, const Fit_connect_options& options)
      : points_(points), options_(options), n_(points.size()), dt_(points), state_(n_, State::initial),
        nearest_(n_), sides_(n_), fit_order_(n_), links_(n_, {none, none}), referrers_(n_), mark_(n_, 0) {
    streams_.reserve(n_);
    for (Index p = 0; p < n_; ++p) streams_.emplace_back(dt_, p);
  }

  Fitted_connectivity run() {
    Fitted_connectivity result;
    if (n_ < 3) return result;  // a fit needs a point and two neighbours
    for (Index p = 0; p < n_; ++p) unhandled_.insert(p);
    // Each visit grows a neighbourhood, and neighbourhoods are bounded, so the rounds end;
    // the bound on visits only guards against a cycle of state changes we have not seen.
    const std::size_t most_visits = 8 * n_ * static_cast<std::size_t>(options_.max_neighbors) + 64;
    std::size_t visits = 0;
    while (!unhandled_.empty() && visits < most_visits) {
      cursor_ = *unhandled_.begin();
      while (cursor_ != none && visits++ < most_visits) {
        const Index p = cursor_;
        cursor_ = successor(p);
        visit(p);
      }
    }
    for (Index p = 0; p < n_; ++p)
      if (on_curve(state_[p])) result.representatives.push_back(p);
    for (const Index p : result.representatives)
      for (const Index q : links_[p])  // both ways, so that no point gets a third edge
        if (q != none && on_curve(state_[q]) && (links_[q][0] == p || links_[q][1] == p))
          result.edges.emplace_back(std::min(p, q), std::max(p, q));
    result.edges = geometry::canonical_edges(std::move(result.edges));
    return result;
  }

  // A window of smoothing_window(p, hops) and its fit, if it has the 5 points a circle's
  // residual needs and the fit is usable.
  struct Window_fit {
    std::vector<Index> members;
    std::optional<Arc_projection> fit;
  };

  Window_fit window_fit(Index p, int hops) const {
    Window_fit window{smoothing_window(p, hops), std::nullopt};
    if (window.members.size() >= 5)
      if (Arc_projection fit(points_, p, window.members); fit.usable()) window.fit.emplace(std::move(fit));
    return window;
  }

  // The authors' blending (projectPoints): each representative moves to the mean of its
  // projections onto its own fit and onto the fits of the manifold points whose
  // neighbourhoods hold it; sharp points and their curve neighbours keep their position.
  std::vector<Point> blended(std::span<const Index> representatives) const {
    std::vector<double> sum_x(n_, 0), sum_y(n_, 0);
    std::vector<int> weight(n_, 0);
    const auto fixed = [&](Index p) {
      if (state_[p] == State::sharp) return true;
      for (const Index q : links_[p])
        if (q != none && state_[q] == State::sharp) return true;
      return false;
    };
    // Each manifold representative's one-hop window and its fit: the noise level needs them
    // all, and the blending again wherever it widens.
    std::vector<Window_fit> one_hop(representatives.size());
    for (std::size_t i = 0; i < representatives.size(); ++i)
      if (state_[representatives[i]] == State::manifold) one_hop[i] = window_fit(representatives[i], 1);
    // How far a blending window may widen, from the input's noise level (fit_connect.h).
    const double noise = noise_level(representatives, one_hop);
    const int widest = noise > 0.03 ? options_.smoothing : noise > 0.005 ? std::min(options_.smoothing, 1) : 0;
    for (std::size_t i = 0; i < representatives.size(); ++i) {
      const Index p = representatives[i];
      if (state_[p] != State::manifold) continue;
      std::vector<Index> members;
      const std::optional<Arc_projection> arc = smoothing_fit(p, members, widest, one_hop[i]);
      if (!arc) continue;
      for (const Index k : members) {
        if (fixed(k)) continue;
        if (const std::optional<Point> q = arc->project(points_[k])) sum_x[k] += q->x(), sum_y[k] += q->y(), ++weight[k];
      }
    }
    std::vector<Point> result;
    for (const Index p : representatives) {
      const bool moved = options_.blend && weight[p] > 0;
      result.push_back(moved ? Point(sum_x[p] / weight[p], sum_y[p] / weight[p]) : points_[p]);
    }
    return result;
  }

  // The input's noise level: the median over manifold representatives p of the residual
  // of the fit to p, its curve neighbours and their neighbourhoods, against the mean
  // squared length of p's two edges. Scale-free; on the suites' samplings at epsilon 0.3 it
  // is 0.003-0.004 without noise (the fit's model error), 0.004-0.008 at uniform noise 0.01,
  // 0.01-0.016 at 0.03, 0.006-0.015 at lfs noise 0.1 and 0.04-0.1 at 0.33 to 0.5.
  double noise_level(std::span<const Index> representatives, std::span<const Window_fit> one_hop) const {
    std::vector<double> levels;
    for (std::size_t i = 0; i < representatives.size(); ++i) {
      const Index p = representatives[i];
      if (!one_hop[i].fit || links_[p][0] == none || links_[p][1] == none) continue;
      double spacing = 0;
      for (const Index q : links_[p]) spacing += CGAL::squared_distance(points_[p], points_[q]) / 2;
      const double level = one_hop[i].fit->residual() / spacing;
      if (spacing > 0 && std::isfinite(level)) levels.push_back(level);  // not at the ends of double
    }
    if (levels.empty()) return 0;
    std::nth_element(levels.begin(), levels.begin() + levels.size() / 2, levels.end());
    return levels[levels.size() / 2];
  }

  // The fit p's blending projects onto, and its members. On a sparse sampling a
  // neighbourhood holds a few points, too few to average noise out, so the window may take
  // in the neighbourhoods of up to `widest` representatives on each side along the
  // curve. It widens while its residual stays that of noise: widening multiplies the
  // residual of noise by about 1 but that of a fit the curve bends away from by more,
  // as its deviation grows with the window's length cubed. Ratio 2 was chosen on the
  // `lfsnoise-full` and `noisy-full` suites (the trade-off is in docs/algorithms.md: heavier
  // noise favours wider windows, a noise-free sampling none).
  // `one_hop` is window_fit(p, 1), computed once by the caller.
  std::optional<Arc_projection> smoothing_fit(Index p, std::vector<Index>& members, int widest,
                                              const Window_fit& one_hop) const {
    constexpr double noise_ratio = 2;
    std::optional<Arc_projection> chosen;
    for (int hops = 0; hops <= widest; ++hops) {
      Window_fit window = hops == 1 ? one_hop : window_fit(p, hops);
      if (!window.fit) continue;
      if (chosen && !(window.fit->residual() <= noise_ratio * chosen->residual())) break;
      chosen = std::move(window.fit);
      members = std::move(window.members);
    }
    return chosen;
  }

  // p and the representatives up to `hops` links away along the curve, with their
  // neighbourhoods; p first.
  std::vector<Index> smoothing_window(Index p, int hops) const {
    std::vector<Index> members{p};
    const auto add = [&](Index c) {
      members.push_back(c);
      for (int s = 0; s < 2; ++s) members.insert(members.end(), sides_[c][s].begin(), sides_[c][s].end());
    };
    add(p);
    for (const Index first : links_[p]) {
      Index from = p, q = first;
      for (int h = 0; h < hops && q != none && q != p; ++h) {
        add(q);
        const Index next = onward(q, from);
        from = q, q = next;
      }
    }
    std::sort(members.begin() + 1, members.end());
    members.erase(std::unique(members.begin() + 1, members.end()), members.end());
    members.erase(std::remove(members.begin() + 1, members.end(), p), members.end());
    return members;
  }

 private:
  using Sides = std::array<std::vector<Index>, 2>;

  // ---- Bookkeeping of the unhandled set, as the authors' loop walks it ------------------
  Index successor(Index p) const {
    const auto next = unhandled_.upper_bound(p);
    return next == unhandled_.end() ? none : *next;
  }

  void set_state(Index p, State s) {
    if (is_handled(s)) {
      if (unhandled_.erase(p) && cursor_ == p) cursor_ = successor(p);
    } else {
      unhandled_.insert(p);
    }
    state_[p] = s;
  }

  static bool holds(const std::vector<Index>& side, Index q) { return std::find(side.begin(), side.end(), q) != side.end(); }
  int link_count(Index p) const { return (links_[p][0] != none) + (links_[p][1] != none); }
  bool has_state(Index p, std::initializer_list<State> states) const {
    return p != none && std::find(states.begin(), states.end(), state_[p]) != states.end();
  }
  // The link of q other than `from` (the next point along the curve).
  Index onward(Index q, Index from) const { return links_[q][links_[q][0] == from ? 1 : 0]; }
  int slot_of(Index q, Index p) const { return links_[q][0] == p ? 0 : 1; }

  // ---- Neighbourhoods (increaseNHood, fitCircleAndOrderNeighbors) ------------------------
  // Adds the next nearest point (the two nearest on the first visit) and refits; false if
  // the neighbourhood cannot grow.
  bool grow(Index p) {
    const std::size_t wanted = state_[p] == State::initial ? 2 : 1;
    if (nearest_[p].size() + wanted > static_cast<std::size_t>(options_.max_neighbors)) return false;
    for (std::size_t i = 0; i < wanted; ++i) {
      const Index q = streams_[p].next();
      if (q == none) return false;
      nearest_[p].push_back(q);
      referrers_[q].push_back(p);
    }
    bool conforming = false;
    Fitted_neighborhood(points_, p, nearest_[p]).order(fit_order_[p], sides_[p], conforming);
    state_[p] = conforming ? State::conform : State::nonconform;  // both unhandled: no set change
    return true;
  }

  // ---- Overlaps --------------------------------------------------------------------------
  // determinePointOverlapSide: the farthest point q on side s of p that can take p as its
  // curve neighbour: q holds p in its own neighbourhood and has a free slot (or is already
  // linked to p).
  Index overlap(Index p, int s) const {
    for (auto q = sides_[p][s].rbegin(); q != sides_[p][s].rend(); ++q) {
      if (!has_state(*q, {State::conform, State::leaf, State::manifold})) continue;
      for (int j = 0; j < 2; ++j) {
        if (!holds(sides_[*q][j], p)) continue;
        const bool linked = links_[*q][0] == p || links_[*q][1] == p;
        if (state_[*q] == State::manifold ? linked : (links_[*q][j] == none || links_[*q][j] == p)) return *q;
      }
    }
    return none;
  }

  // doRemoveOverlap: unlinks p's side s; a partner that loses a link is unhandled again, and a
  // sharp partner loses both its links.
  void unlink(Index p, int s) {
    const Index q = links_[p][s];
    if (q == none) return;
    links_[p][s] = none;
    if (links_[q][slot_of(q, p)] == p) links_[q][slot_of(q, p)] = none;
    if (has_state(q, {State::manifold, State::leaf})) {
      set_state(q, State::conform);
    } else if (state_[q] == State::sharp) {
      set_state(q, State::nonconform);
      for (int t = 0; t < 2; ++t) {
        const Index r = links_[q][t];
        if (r == none) continue;
        links_[q][t] = none;
        if (links_[r][slot_of(r, q)] == q) links_[r][slot_of(r, q)] = none;
        if (state_[r] == State::manifold) set_state(r, State::conform);
      }
    }
  }

  void unlink_side(Index p, int s) {  // removeOverlap
    unlink(p, s);
    affected_.insert(p);
    if (state_[p] == State::manifold) set_state(p, State::conform);
  }

  void unlink_all(Index p) {  // removeOverlaps
    unlink(p, 0), unlink(p, 1);
    affected_.insert(p);
    if (has_state(p, {State::manifold, State::leaf})) set_state(p, State::conform);
    else if (state_[p] == State::sharp) set_state(p, State::nonconform);
  }

  // determineConsistentPointSetInNhood: the points reached by following the curve from p
  // through side s while it stays inside that side.
  std::vector<Index> followed(Index p, int s) const {
    std::vector<Index> result;
    Index previous = p, current = links_[p][s];
    while (current != none && holds(sides_[p][s], current) && !holds(result, current)) {
      result.push_back(current);
      const Index next = onward(current, previous);
      previous = current, current = next;
    }
    return result;
  }

  // Whether a curve point on side s of p is not on the curve followed from p: the side
  // holds pieces of another curve.
  bool inconsistent(Index q, const std::vector<Index>& followed_points) const {
    return !holds(followed_points, q) && has_state(q, {State::manifold, State::leaf, State::sharp});
  }

  void unlink_inconsistent(Index p, int s) {  // removeInconsistentPointSetInNhood
    const std::vector<Index> consistent = followed(p, s);
    for (const Index q : sides_[p][s])
      if (inconsistent(q, consistent)) unlink_all(q);
  }

  // addRedundantPointsInOverlap: unhandled points strictly between p and its partner on
  // side s, in both neighbourhoods.
  std::vector<Index> redundant(Index p, int s) const {
    const Index q = links_[p][s];
    const auto before = [&](const std::vector<Index>& side, Index end) {
      std::vector<Index> result;
      for (const Index m : side) {
        if (m == end) break;
        if (unhandled_.contains(m)) result.push_back(m);
      }
      std::sort(result.begin(), result.end());
      return result;
    };
    const std::vector<Index> mine = before(sides_[p][s], q), theirs = before(sides_[q][slot_of(q, p)], p);
    std::vector<Index> both;
    std::set_intersection(mine.begin(), mine.end(), theirs.begin(), theirs.end(), std::back_inserter(both));
    return both;
  }

  // isInsideEdge: p lies between two linked curve points that are the nearest non-eliminated
  // points on either side of p.
  bool inside_edge(Index p) const {
    for (const Index q : links_[p])
      if (q != none && state_[q] == State::manifold) return false;
    const auto curve_points = [&](int s) {
      std::vector<Index> result;
      for (const Index q : sides_[p][s])
        if (has_state(q, {State::manifold, State::sharp})) result.push_back(q);
      return result;
    };
    const std::vector<Index> left = curve_points(0), right = curve_points(1);
    const auto nothing_before = [&](int s, Index end) {
      for (const Index m : sides_[p][s]) {
        if (m == end) return true;
        if (state_[m] != State::eliminated && state_[m] != State::initial) return false;
      }
      return true;
    };
    for (const Index a : left) {
      Index b = holds(right, links_[a][0]) ? links_[a][0] : holds(right, links_[a][1]) ? links_[a][1] : none;
      if (b != none && nothing_before(0, a) && nothing_before(1, b)) return true;
    }
    return false;
  }

  // ---- Sharp corners (collectIntersectingSegmentsInNHood, isSharpPoint) ------------------
  struct Segments {
    std::vector<std::vector<Index>> open;  // each from its end inside the neighbourhood outwards
    bool closed = false;                   // a curve passes through the neighbourhood
  };

  Segments segments(Index p) {
    Segments result;
    const auto manifold = [&](Index q) { return state_[q] == State::manifold; };
    if (std::none_of(sides_[p][0].begin(), sides_[p][0].end(), manifold) &&
        std::none_of(sides_[p][1].begin(), sides_[p][1].end(), manifold))
      return result;
    if (++stamp_ == 0) std::fill(mark_.begin(), mark_.end(), 0), stamp_ = 1;  // after 2^32 calls
    const std::uint32_t stamp = stamp_;  // mark_[q] == stamp: q is in p's neighbourhood
    std::size_t inside = 0;
    std::vector<Index> starts;
    for (int s = 0; s < 2; ++s)
      for (const Index q : sides_[p][s]) {
        mark_[q] = stamp, ++inside;
        if (state_[q] == State::manifold) starts.push_back(q);
      }
    const auto in = [&](Index q) { return q != none && mark_[q] == stamp; };
    std::sort(starts.begin(), starts.end());
    std::vector<bool> done(starts.size(), false);
    for (std::size_t i = 0; i < starts.size(); ++i) {
      if (done[i]) continue;
      const Index start = starts[i];
      std::deque<Index> segment{start};
      std::array<bool, 2> leaves{false, false};
      for (int direction = 0; direction < 2; ++direction) {
        Index previous = start, current = links_[start][direction];
        std::size_t steps = 0;
        while (current != none && current != start && in(current) && steps++ <= inside) {
          direction == 0 ? segment.push_back(current) : segment.push_front(current);
          const auto known = std::lower_bound(starts.begin(), starts.end(), current);
          if (known != starts.end() && *known == current) done[known - starts.begin()] = true;
          const Index next = onward(current, previous);
          previous = current, current = next;
        }
        leaves[direction] = current != none && current != p && current != start && !in(current);
      }
      if (leaves[0] && leaves[1]) {
        result.closed = true;
      } else if (leaves[0] || leaves[1]) {
        if (leaves[1]) std::reverse(segment.begin(), segment.end());
        result.open.emplace_back(segment.begin(), segment.end());
      }
    }
    return result;
  }

  // Two curve ends meet at p at a sharp corner: their curves leave p's neighbourhood within
  // `sharp_angle` of each other as seen from p, and joining p to both ends crosses no curve
  // edge in the neighbourhood.
  bool sharp(Index p, const Segments& found) const {
    std::vector<Index> inside{p};
    for (int s = 0; s < 2; ++s) inside.insert(inside.end(), sides_[p][s].begin(), sides_[p][s].end());
    std::array<Index, 2> outside{};
    for (int i = 0; i < 2; ++i) {
      const Index end = found.open[i].back();
      outside[i] = holds(inside, links_[end][0]) ? links_[end][1] : links_[end][0];
      if (outside[i] == none) return false;
    }
    const double cosine = std::cos(options_.sharp_angle * std::numbers::pi / 180);
    if (cosine_minus(points_[outside[0]], points_[p], points_[outside[1]], cosine) == CGAL::NEGATIVE) return false;
    for (const auto& segment : found.open) {
      const Index end = segment.front();
      const geometry::Kernel::Segment_2 joint(points_[p], points_[end]);
      for (const Index a : inside) {
        if (!has_state(a, {State::manifold, State::conform, State::leaf})) continue;
        for (const Index b : links_[a])
          if (has_state(b, {State::manifold, State::conform, State::leaf}) && a != end && b != end &&
              CGAL::do_intersect(joint, geometry::Kernel::Segment_2(points_[a], points_[b])))
            return false;
      }
    }
    return true;
  }

  // ---- One visit ---------------------------------------------------------------------------
  void visit(Index p) {
    const State before = state_[p];
    const Sides old_sides = sides_[p];
    const int leaf_side = leaf_candidate_side(p);

    if (!grow(p)) {
      cannot_grow(p);
    } else if (leaf_side >= 0 && sides_[p][1 - leaf_side].empty()) {
      // A curve end whose grown neighbourhood reaches another curve: it stays an end.
      const std::vector<Index> consistent = followed(p, leaf_side);
      bool other_curve = false;
      for (const Index q : sides_[p][leaf_side]) other_curve = other_curve || inconsistent(q, consistent);
      if (other_curve) {
        sides_[p] = old_sides;
        set_state(p, State::leaf);
        affected_.insert(p);
        align_links(p);
      }
    }

    if (state_[p] == State::conform) connect(p);

    if (has_state(p, {State::conform, State::nonconform}) && inside_edge(p)) {
      if (state_[p] == State::nonconform && before == State::conform) state_[p] = State::conform;
      if (state_[p] == State::conform) unlink_all(p);
      set_state(p, State::eliminated);
      affected_.insert(p);
    }

    if (state_[p] == State::nonconform) join_at_sharp_corner(p, before);

    restore_consistency();

    if (state_[p] == State::nonconform && before == State::conform) {  // keep the old fit and its links
      sides_[p] = old_sides;
      state_[p] = State::conform;
    }
  }

  // A conforming point with one link whose curve runs on through two more manifold points
  // of that side: if its grown neighbourhood turns out to hold another curve, it is an end.
  int leaf_candidate_side(Index p) const {
    if (state_[p] != State::conform || link_count(p) != 1) return -1;
    const int s = links_[p][0] != none ? 0 : 1;
    Index previous = p, current = links_[p][s];
    for (int count = 0; count < 2; ++count) {
      const Index next = onward(current, previous);
      if (!(next != none && state_[next] == State::manifold && holds(sides_[p][s], next))) return -1;
      previous = current, current = next;
    }
    return s;
  }

  void cannot_grow(Index p) {
    if (state_[p] == State::conform && link_count(p) > 0) {
      // A curve end: it becomes a leaf, or hands the end on to the one non-conforming point
      // beyond it.
      const int s = links_[p][0] != none ? 0 : 1;
      std::vector<Index> beyond;
      for (const Index q : sides_[p][1 - s])
        if (state_[q] == State::nonconform) beyond.push_back(q);
      if (beyond.size() == 1 && links_[p][1 - s] == none) {
        const Index q = beyond[0];
        const int qs = holds(sides_[q][0], p) ? 0 : 1;
        if (links_[q][qs] == none) {
          links_[p][1 - s] = q, links_[q][qs] = p;
          set_state(q, State::leaf), affected_.insert(q);
          set_state(p, State::manifold), affected_.insert(p);
          return;
        }
      }
      set_state(p, State::leaf), affected_.insert(p);
      return;
    }
    // A non-conforming point with all its neighbourhood on one side, next to a curve end: it
    // extends that curve as its new end.
    if (state_[p] == State::nonconform && link_count(p) == 0 && sides_[p][0].empty() != sides_[p][1].empty()) {
      const int s = sides_[p][0].empty() ? 1 : 0;
      for (const Index q : sides_[p][s]) {
        if (state_[q] == State::eliminated) continue;
        if (state_[q] == State::conform && link_count(q) == 1) {
          links_[q][links_[q][0] == none ? 0 : 1] = p;
          links_[p][s] = q;
          set_state(q, State::manifold), affected_.insert(q);
          set_state(p, State::leaf), affected_.insert(p);
          return;
        }
        break;
      }
    }
    if (link_count(p) > 0) unlink_all(p);
    set_state(p, State::eliminated);
  }

  // Links each of p's sides to its overlap, drops links that are no overlap any more, and
  // eliminates the points the new overlaps make redundant.
  void connect(Index p) {
    const std::array<Index, 2> wanted{overlap(p, 0), overlap(p, 1)};
    for (int s = 0; s < 2; ++s) {
      const Index q = links_[p][s];
      if (q != none && q != wanted[0] && q != wanted[1]) unlink_side(p, s);
    }
    for (const Index q : wanted) {
      if (q == none || q == links_[p][0] || q == links_[p][1]) continue;
      const int s = links_[p][0] == none ? 0 : links_[p][1] == none ? 1 : -1;
      const int qs = holds(sides_[q][0], p) ? 0 : 1;
      if (s < 0 || links_[q][qs] != none) continue;
      links_[p][s] = q, links_[q][qs] = p;
      if (links_[p][1 - s] != none) set_state(p, State::manifold), affected_.insert(p);
      if (links_[q][1 - qs] != none) set_state(q, State::manifold), affected_.insert(q);
    }
    align_links(p);
    for (int s = 0; s < 2; ++s) {
      if (links_[p][s] == none) continue;
      for (const Index q : redundant(p, s)) {
        if (has_state(q, {State::manifold, State::conform, State::sharp})) unlink_all(q);
        set_state(q, State::eliminated);
      }
    }
    for (int s = 0; s < 2; ++s) {
      if (links_[p][s] == none) continue;
      unlink_inconsistent(p, s);
      const Index q = links_[p][s];
      if (q != none) unlink_inconsistent(q, slot_of(q, p));
    }
    // A point with one overlap whose way to a second one is blocked by a conforming point
    // that already links across p: p is the redundant one.
    if (link_count(p) == 1) {
      const int s = links_[p][0] != none ? 0 : 1;
      for (const Index q : sides_[p][s]) {
        if (q == links_[p][s]) break;
        if (state_[q] != State::conform) continue;
        if (link_count(q) == 1 && holds(sides_[p][1 - s], links_[q][links_[q][0] != none ? 0 : 1])) {
          unlink_side(p, s);
          set_state(p, State::eliminated);
        }
        break;
      }
    }
  }

  // Keeps link slot s on neighbourhood side s.
  void align_links(Index p) {
    const bool off = (links_[p][0] != none && !holds(sides_[p][0], links_[p][0])) ||
                     (links_[p][1] != none && !holds(sides_[p][1], links_[p][1]));
    if (off) std::swap(links_[p][0], links_[p][1]);
  }

  void join_at_sharp_corner(Index p, State before) {
    const Segments found = segments(p);
    if (found.closed || found.open.size() != 2 || !sharp(p, found)) return;
    if (before == State::conform) {
      state_[p] = State::conform;
      unlink_all(p);
    }
    set_state(p, State::sharp);
    affected_.insert(p);
    for (int i = 0; i < 2; ++i) {
      const Index end = found.open[i].front();
      if (state_[end] != State::manifold) {
        set_state(end, State::manifold);
        affected_.insert(end);
        links_[end][links_[end][0] == none ? 0 : 1] = p;
      }
      links_[p][i] = end;
    }
  }

  // The authors' clean-up after each visit: every point whose neighbourhood holds an
  // affected point re-checks its links, and drops them all if a link is off its side or
  // its neighbourhood holds pieces of another curve.
  void restore_consistency() {
    while (!affected_.empty()) {
      for (auto next = affected_.begin(); next != affected_.end();) {
        const Index q = *next;
        next = affected_.erase(next);
        std::vector<Index> referrers = referrers_[q];
        std::sort(referrers.begin(), referrers.end());
        referrers.erase(std::unique(referrers.begin(), referrers.end()), referrers.end());
        for (const Index r : referrers)
          if (link_count(r) > 0 && !consistent(r)) unlink_all(r);
      }
    }
  }

  bool consistent(Index r) const {
    if (state_[r] == State::sharp)
      return has_state(links_[r][0], {State::manifold}) && has_state(links_[r][1], {State::manifold});
    for (int s = 0; s < 2; ++s) {
      const Index m = links_[r][s];
      if (m != none && state_[m] != State::sharp && !holds(sides_[r][s], m)) return false;
    }
    for (int s = 0; s < 2; ++s) {
      const Index m = links_[r][s];
      if (m == none || state_[m] == State::sharp) continue;
      const std::vector<Index> consistent_points = followed(r, s);
      for (const Index q : sides_[r][s])
        if (inconsistent(q, consistent_points)) return false;
    }
    return true;
  }

  std::span<const Point> points_;
  Fit_connect_options options_;
  std::size_t n_;
  graphs::Delaunay_triangulation dt_;
  std::vector<graphs::Nearest_neighbor_stream> streams_;
  std::vector<State> state_;
  std::vector<std::vector<Index>> nearest_;  // the neighbourhood, nearest first
  std::vector<Sides> sides_;                 // ... ordered along its fit, nearest first
  std::vector<std::vector<std::uint32_t>> fit_order_;  // ... all along the fit (member numbers)
  std::vector<std::array<Index, 2>> links_;  // curve neighbours, slot s on side s
  std::vector<std::vector<Index>> referrers_;  // the points whose neighbourhood holds this one
  std::set<Index> unhandled_;
  std::set<Index> affected_;
  Index cursor_ = none;
  std::vector<std::uint32_t> mark_;  // scratch marks for segments(), see stamp_
  std::uint32_t stamp_ = 0;
};

}  // namespace

Fitted_connectivity fit_connect_connectivity(std::span<const Point> points, const Fit_connect_options& options) {
  check_input(points, options);
  if (points.size() < 3) {  // no fit: what there is, joined
    Fitted_connectivity result;
    for (Index p = 0; p < points.size(); ++p) result.representatives.push_back(p);
    if (points.size() == 2) result.edges.emplace_back(0, 1);
    return result;
  }
  return Fit_connect(points, options).run();
}

Reconstruction fit_connect_reconstruction(std::span<const Point> points, const Fit_connect_options& options) {
  check_input(points, options);
  Reconstruction result;
  if (points.size() < 3) {
    result.points.assign(points.begin(), points.end());
    if (points.size() == 2) result.edges.emplace_back(0, 1);
    return result;
  }
  Fit_connect machine(points, options);
  const Fitted_connectivity connectivity = machine.run();
  result.points = machine.blended(connectivity.representatives);
  std::vector<Index> number(points.size(), none);
  for (std::size_t i = 0; i < connectivity.representatives.size(); ++i) number[connectivity.representatives[i]] = static_cast<Index>(i);
  for (const auto& [a, b] : connectivity.edges) result.edges.emplace_back(number[a], number[b]);
  result.edges = geometry::canonical_edges(std::move(result.edges));
  return result;
}

Algorithm fit_connect_algorithm() {
  static const Parameter max_neighbors{.name = "max_neighbors",
                                       .type = Parameter_type::integer,
                                       .default_value = 1024,
                                       .minimum = 2,
                                       .maximum = 65536,
                                       .meaning = "largest neighbourhood a point's fit grows to"};
  static const Parameter sharp_angle{.name = "sharp_angle",
                                     .type = Parameter_type::real,
                                     .default_value = 60,
                                     .minimum = 0,
                                     .maximum = 180,
                                     .meaning = "degrees; two curve ends meeting within it form a sharp corner"};
  static const Parameter smoothing{.name = "smoothing",
                                   .type = Parameter_type::integer,
                                   .default_value = 2,
                                   .minimum = 0,
                                   .maximum = 64,
                                   .meaning = "representatives on each side whose neighbourhoods a blending fit may take "
                                              "in under heavy noise (1 under light noise, none without); 0: the point's "
                                              "own (the authors')"};
  static const Parameter blend{.name = "blend",
                               .type = Parameter_type::integer,
                               .default_value = 1,
                               .minimum = 0,
                               .maximum = 1,
                               .meaning = "1: output points blended onto the fits; 0: at their input positions"};
  return {
      .name = "fit-connect",
      .title = "FitConnect",
      .reference = "Ohrhallinger, Wimmer 2018",
      .category = "Noisy Points Fitting",
      .parameters = {max_neighbors, sharp_angle, smoothing, blend},
      .capabilities = {.non_uniform = Support::yes, .noise = Support::yes, .outliers = Support::yes,
                       .manifold = Support::yes, .open = Support::yes, .multiple = Support::yes,
                       .sharp = Support::yes, .guarantee = true, .time_complexity = "O(n k^2)"},
      .condition = {.statement = "as HNN-Crust (survey's table; not certified for this implementation)"},
      .reconstruct = [](std::span<const Point> points, const Parameter_values& values) {
        return fit_connect_reconstruction(points, {.max_neighbors = static_cast<int>(values[max_neighbors]),
                                                   .sharp_angle = values[sharp_angle],
                                                   .smoothing = static_cast<int>(values[smoothing]),
                                                   .blend = values[blend] != 0});
      },
  };
}

}  // namespace curvebench::algorithms
