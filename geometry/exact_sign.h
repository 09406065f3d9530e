// The exact sign of a polynomial in input coordinates: the tool for predicates CGAL
// does not provide (beta-skeleton lunes, sums of distances, ...).
//
// A predicate is written once, generic in its number type:
//
//     exact_sign([&]<class NT>(std::type_identity<NT>) {
//       return dot(difference<NT>(r, p), difference<NT>(r, q));
//     });
//
// and evaluated first in double with a running forward-error bound, which settles the
// sign almost always at the cost of a few flops; only when the bound cannot exclude
// zero (near-degenerate input, overflow, underflow) is it evaluated again, in interval
// arithmetic and, if that cannot decide either, exactly in multiprecision (CGAL::Mpzf).
// Inputs are doubles, so the last evaluation is exact: the sign returned is the sign of
// the true value, never of a rounded one.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include <CGAL/FPU.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>

#include "geometry/kernel.h"

namespace curvebench::geometry {

// A double together with a bound on its distance to the exact value of the expression
// it was computed from. Rounding to nearest adds at most half an ulp per operation,
// bounded here by u|v| (u = 2^-53), plus an absolute term for underflow. That term is
// the smallest *normal* double, not the smallest subnormal: arithmetic on subnormal
// operands takes a microcode assist on x86 and made every predicate 20x slower.
class Error_bounded_double {
 public:
  // An exact value, such as an input coordinate: error 0. Implicit, so that a predicate's
  // inputs enter its expressions as they are.
  Error_bounded_double(double exact) : value_(exact), error_(0) {}  // NOLINT: inputs are exact

  // A value known to lie within `error` of the exact one.
  static Error_bounded_double with_error(double value, double error) { return {value, error}; }

  // The double computed.
  double value() const { return value_; }
  // The bound on |value() - exact value|; may be infinite (after overflow).
  double error() const { return error_; }

  // The rounded sum; the error bound adds those of a and b and the rounding of the sum.
  friend Error_bounded_double operator+(Error_bounded_double a, Error_bounded_double b) {
    const double v = a.value_ + b.value_;
    return {v, a.error_ + b.error_ + rounding(v)};
  }
  // The rounded difference, bounded as the sum.
  friend Error_bounded_double operator-(Error_bounded_double a, Error_bounded_double b) {
    const double v = a.value_ - b.value_;
    return {v, a.error_ + b.error_ + rounding(v)};
  }
  // The rounded product; the bound is |a| err(b) + |b| err(a) + err(a) err(b) plus the
  // rounding of the product.
  friend Error_bounded_double operator*(Error_bounded_double a, Error_bounded_double b) {
    const double v = a.value_ * b.value_;
    return {v, std::abs(a.value_) * b.error_ + std::abs(b.value_) * a.error_ +
                   a.error_ * b.error_ + rounding(v)};
  }

  // The sign if the error bound proves it, else nothing.
  bool sign_is_certain() const {
    // The bound itself was computed with rounding; the factor covers that slack.
    return std::isfinite(value_) && std::isfinite(error_) &&
           std::abs(value_) > error_ * (1 + 0x1p-40);
  }
  // The sign of value(): that of the exact value if sign_is_certain().
  CGAL::Sign sign() const { return value_ > 0 ? CGAL::POSITIVE : value_ < 0 ? CGAL::NEGATIVE : CGAL::ZERO; }

 private:
  Error_bounded_double(double value, double error) : value_(value), error_(error) {}
  static double rounding(double v) {
    return std::abs(v) * 0x1p-53 + std::numeric_limits<double>::min();
  }

  double value_;
  double error_;
};

// A vector of the plane in a predicate's number type NT (Error_bounded_double, an interval
// or Exact_number), for writing a polynomial once for every stage of exact_sign.
template <class NT>
struct Vector2 {
  // The x coordinate.
  NT x, y;  // the y coordinate
  // The componentwise sum.
  friend Vector2 operator+(const Vector2& a, const Vector2& b) { return {a.x + b.x, a.y + b.y}; }
};

// a - b in NT, from the exact input coordinates of a and b.
template <class NT>
Vector2<NT> difference(const Point& a, const Point& b) {
  return {NT(a.x()) - NT(b.x()), NT(a.y()) - NT(b.y())};
}
// An input coordinate times 2^-e as a filter's number: exact, unless the product is
// subnormal and lost bits, which then count as its error. A homogeneous predicate has the
// sign at scaled inputs that it has at the inputs, and its filters, evaluated where the
// coordinates are near 1, neither overflow nor underflow where the inputs are huge.
template <class NT>
NT scaled(double v, int e);
// As a filter's number: v 2^-e with error 0, or the smallest subnormal if bits were lost.
template <>
inline Error_bounded_double scaled(double v, int e) {
  const double s = std::ldexp(v, -e);
  return Error_bounded_double::with_error(s, std::ldexp(s, e) == v ? 0.0 : 0x1p-1074);
}
// As an interval: the point v 2^-e, or an interval around it one smallest subnormal wide
// on each side if bits were lost. Call with the FPU rounding upwards.
template <>
inline CGAL::Interval_nt_advanced scaled(double v, int e) {  // under upward rounding
  const double s = std::ldexp(v, -e);
  if (std::ldexp(s, e) == v) return s;
  return {-(0x1p-1074 - s), s + 0x1p-1074};
}
// a - b in NT, with every coordinate scaled by 2^-e first (see scaled).
template <class NT>
Vector2<NT> scaled_difference(const Point& a, const Point& b, int e) {
  return {scaled<NT>(a.x(), e) - scaled<NT>(b.x(), e), scaled<NT>(a.y(), e) - scaled<NT>(b.y(), e)};
}

// The dot product a.x b.x + a.y b.y.
template <class NT>
NT dot(const Vector2<NT>& a, const Vector2<NT>& b) { return a.x * b.x + a.y * b.y; }
// The cross product a.x b.y - a.y b.x: positive if b is counterclockwise from a.
template <class NT>
NT cross(const Vector2<NT>& a, const Vector2<NT>& b) { return a.x * b.y - a.y * b.x; }
// dot(a, a).
template <class NT>
NT squared_length(const Vector2<NT>& a) { return dot(a, a); }

// CGAL::Mpzf: a multiprecision binary float, exact for + - x on doubles, which is all a
// polynomial needs; several times faster than rationals, which normalise by a gcd after
// every operation (measured: the EMST of 10^6 points on a smooth curve, whose sorted edge
// lengths agree to 1e-16 and so reach this stage a million times, 4.5 s with CGAL::Gmpq).
// Not CGAL::Exact_rational: that may be gmpxx's mpq_class, whose expression templates
// would dangle when a polynomial returns `a * b - c`.
using Exact_number = CGAL::Mpzf;

// The sign of `polynomial`, given its value in Error_bounded_double when the caller
// already has it (e.g. a difference of cached squared lengths).
// Three stages: the error bound; then interval arithmetic, which keeps a value that was
// computed without rounding (an exact tie on grid input) as a point and so certifies a
// zero at a twentieth of the cost of GMP; then GMP (CGAL::Mpzf).
template <class Polynomial>
CGAL::Sign exact_sign(const Error_bounded_double& approximation, const Polynomial& polynomial) {
  if (approximation.sign_is_certain()) return approximation.sign();
  {
    using Interval = CGAL::Interval_nt_advanced;
    CGAL::Protect_FPU_rounding<true> upward;
    const Interval value = polynomial(std::type_identity<Interval>{});
    if (value.inf() > 0) return CGAL::POSITIVE;
    if (value.sup() < 0) return CGAL::NEGATIVE;
    if (value.inf() == 0 && value.sup() == 0) return CGAL::ZERO;
  }
  using Result = decltype(polynomial(std::type_identity<Exact_number>{}));
  static_assert(std::is_same_v<Result, Exact_number>, "a polynomial must return its number type");
  return CGAL::sign(polynomial(std::type_identity<Exact_number>{}));
}

// The exact sign of `polynomial`, a callable that takes std::type_identity<NT> and
// returns its value in NT (see the top of this file), evaluated first in
// Error_bounded_double.
template <class Polynomial>
CGAL::Sign exact_sign(const Polynomial& polynomial) {
  return exact_sign(polynomial(std::type_identity<Error_bounded_double>{}), polynomial);
}

// The cheapest filter, for comparing two sums of squares of coordinate differences (and
// their multiples by an exact double): such sums have no cancellation, so each double is
// within a relative 5 ulps of its exact value (inside the normal range), and a gap wider
// than 2^-48 (a + b) decides the sign of b - a. Returns nothing when it cannot decide:
// callers then ask exact_sign. Several times cheaper than Error_bounded_double, and
// distance comparisons are most of what the proximity graphs evaluate.
inline std::optional<CGAL::Sign> certain_sign_of_difference(double a, double b) {
  const double sum = a + b, gap = b - a;
  // Below 2^-900 the subnormal rounding of a term is no longer negligible.
  if (!(sum >= 0x1p-900 && std::isfinite(sum)) || std::abs(gap) <= sum * 0x1p-48) return std::nullopt;
  return gap > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
}

// (a.x - b.x)² + (a.y - b.y)² in double, rounded: the kind of value that
// certain_sign_of_difference compares.
inline double squared_distance_approximation(const Point& a, const Point& b) {
  const double dx = a.x() - b.x(), dy = a.y() - b.y();
  return dx * dx + dy * dy;
}

// |ab|² as an unevaluated sum hi + lo, 2^48 times finer than
// squared_distance_approximation, for the comparisons that one cannot decide (an evenly
// sampled curve's lengths agree to 15 digits). Within 2^-96 |ab|² of the exact value when
// hi lies in [2^-800, 2^1000], where no term underflows or overflows: the differences are
// exact as TwoSum pairs, the squares of their high parts exact as fma splits, and the
// rest is below the square by 2^-52 or more and rounded once or twice.
struct Refined_squared_distance {
  // The rounded sum.
  double hi, lo;  // what rounding left off, at most half an ulp of hi
  // The order of hi + lo (lexicographic, since lo is below half an ulp of hi).
  friend bool operator<(const Refined_squared_distance& a, const Refined_squared_distance& b) {
    return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
  }
};

namespace detail {
// a + b as the rounded sum and its rounding error, exactly (Knuth's TwoSum).
inline std::pair<double, double> two_sum(double a, double b) {
  const double sum = a + b, b_part = sum - a;
  return {sum, (a - (sum - b_part)) + (b - b_part)};
}
}  // namespace detail

// See Refined_squared_distance.
inline Refined_squared_distance refined_squared_distance(const Point& a, const Point& b) {
  const auto [hx, lx] = detail::two_sum(a.x(), -b.x());
  const auto [hy, ly] = detail::two_sum(a.y(), -b.y());
  const double px = hx * hx, py = hy * hy;
  const auto [hi, carry] = detail::two_sum(px, py);
  const double lo = carry + std::fma(hx, hx, -px) + std::fma(hy, hy, -py) + (2 * hx * lx + lx * lx) +
                    (2 * hy * ly + ly * ly);
  const double sum = hi + lo;
  return {sum, lo - (sum - hi)};
}

// The sign of b - a where the refined sums decide it, as certain_sign_of_difference does
// for rounded ones: nothing when they lie within 2^-90 (a + b) of each other or outside
// [2^-800, 2^1000]. Within a factor 2 the difference of the high parts is exact
// (Sterbenz), so the gap is off by far less than the margin.
inline std::optional<CGAL::Sign> certain_sign_of_difference(const Refined_squared_distance& a,
                                                            const Refined_squared_distance& b) {
  const auto in_range = [](double hi) { return hi >= 0x1p-800 && hi <= 0x1p1000; };
  if (!in_range(a.hi) || !in_range(b.hi)) return std::nullopt;
  if (b.hi > 2 * a.hi) return CGAL::POSITIVE;
  if (a.hi > 2 * b.hi) return CGAL::NEGATIVE;
  const double gap = (b.hi - a.hi) + (b.lo - a.lo);
  if (std::abs(gap) <= (a.hi + b.hi) * 0x1p-90) return std::nullopt;
  return gap > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
}

}  // namespace curvebench::geometry
