// The exact-sign evaluator: its error bound must contain the truth, and its signs must
// agree with CGAL's exact predicates, above all where the doubles alone would lie.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "geometry/exact_sign.h"
#include "tests/support/finite_double.h"

namespace curvebench::geometry {
namespace {

using testing::finite_double;

template <class NT>
NT orientation_determinant(const Point& p, const Point& q, const Point& r) {
  return cross(difference<NT>(q, p), difference<NT>(r, p));
}

CGAL::Sign exact_orientation(const Point& p, const Point& q, const Point& r) {
  return exact_sign([&]<class NT>(std::type_identity<NT>) { return orientation_determinant<NT>(p, q, r); });
}

RC_GTEST_PROP(ErrorBoundedDouble, BoundContainsTheExactValue, ()) {
  const Point p(*finite_double(), *finite_double()), q(*finite_double(), *finite_double()),
      r(*finite_double(), *finite_double());
  const Error_bounded_double approximate = orientation_determinant<Error_bounded_double>(p, q, r);
  RC_PRE(std::isfinite(approximate.value()) && std::isfinite(approximate.error()));
  const Exact_number exact = orientation_determinant<Exact_number>(p, q, r);
  const Exact_number gap = exact - Exact_number(approximate.value());
  RC_ASSERT(CGAL::abs(gap) <= Exact_number(approximate.error()));
}

RC_GTEST_PROP(ExactSign, AgreesWithCgalOrientationOnArbitraryDoubles, ()) {
  const Point p(*finite_double(), *finite_double()), q(*finite_double(), *finite_double()),
      r(*finite_double(), *finite_double());
  RC_ASSERT(exact_orientation(p, q, r) == CGAL::orientation(p, q, r));
}

// Points a few ulps off a line: the double determinant is noise, the sign is not.
RC_GTEST_PROP(ExactSign, AgreesWithCgalOrientationNearALine, ()) {
  const double scale = std::ldexp(1.0, *rc::gen::inRange(-1000, 1000));
  const double slope = *rc::gen::inRange(1, 1000) / 7.0;
  const auto point_on_line = [&](int t, int ulps) {
    double y = slope * t;
    for (int i = 0; i < std::abs(ulps); ++i) y = std::nextafter(y, ulps > 0 ? INFINITY : -INFINITY);
    return Point(t * scale, y * scale);
  };
  const Point p = point_on_line(*rc::gen::inRange(-50, 50), *rc::gen::inRange(-2, 3));
  const Point q = point_on_line(*rc::gen::inRange(-50, 50), *rc::gen::inRange(-2, 3));
  const Point r = point_on_line(*rc::gen::inRange(-50, 50), *rc::gen::inRange(-2, 3));
  RC_ASSERT(exact_orientation(p, q, r) == CGAL::orientation(p, q, r));
}

TEST(ExactSign, DecidesWhereDoublesOverflowOrUnderflow) {
  // Squares of 1e200 overflow and of 1e-200 underflow; the signs are still exact.
  const auto squared_norm_difference = [](double a, double b) {
    return exact_sign([&]<class NT>(std::type_identity<NT>) { return NT(a) * NT(a) - NT(b) * NT(b); });
  };
  EXPECT_EQ(squared_norm_difference(1e200, std::nextafter(1e200, 0.0)), CGAL::POSITIVE);
  EXPECT_EQ(squared_norm_difference(1e-200, std::nextafter(1e-200, 1.0)), CGAL::NEGATIVE);
  EXPECT_EQ(squared_norm_difference(1e-200, -1e-200), CGAL::ZERO);
  EXPECT_EQ(squared_norm_difference(std::numeric_limits<double>::denorm_min(), 0.0), CGAL::POSITIVE);
}

}  // namespace
}  // namespace curvebench::geometry

namespace curvebench::geometry {
namespace {

// When the cheap filter decides a comparison of squared distances, it decides it right.
RC_GTEST_PROP(CertainSignOfDifference, AgreesWithCgalDistanceComparison, ()) {
  const auto coordinate = rc::gen::oneOf(testing::finite_double(), rc::gen::map(rc::gen::inRange(-8, 9), [](int i) {
                                           return static_cast<double>(i);
                                         }));
  const Point a(*coordinate, *coordinate), b(*coordinate, *coordinate), c(*coordinate, *coordinate),
      d(*coordinate, *coordinate);
  const auto sign = certain_sign_of_difference(squared_distance_approximation(a, b), squared_distance_approximation(c, d));
  RC_TAG(sign.has_value());
  if (sign) {  // sign of |cd|^2 - |ab|^2
    const auto expected = Kernel().compare_distance_2_object()(c, d, a, b);
    RC_ASSERT(*sign == (expected == CGAL::LARGER ? CGAL::POSITIVE : expected == CGAL::SMALLER ? CGAL::NEGATIVE : CGAL::ZERO));
  }
}

// The refined filter decides what the cheap one cannot, and decides it right: segments
// whose lengths agree to about 16 digits (cd is ab turned a quarter and moved, then its
// coordinates nudged by a few ulps), at any scale whose coordinates are finite: up to
// 2^1021, where d's coordinates (up to 3 scale) still are. (Above 2^1023 they were
// infinite: no point at all, and CGAL's exact oracle traps converting them to GMP.)
RC_GTEST_PROP(CertainSignOfRefinedDifference, AgreesWithCgalDistanceComparison, ()) {
  const double scale = std::ldexp(1.0, *rc::gen::inRange(-1100, 1022));
  const auto coordinate = rc::gen::map(rc::gen::inRange(-1000000, 1000001),
                                       [scale](int i) { return static_cast<double>(i) * 1e-6 * scale; });
  const auto nudge = [](double x, int ulps) {
    for (; ulps > 0; --ulps) x = std::nextafter(x, HUGE_VAL);
    for (; ulps < 0; ++ulps) x = std::nextafter(x, -HUGE_VAL);
    return x;
  };
  const auto ulps = rc::gen::inRange(-3, 4);
  const Point a(*coordinate, *coordinate), b(*coordinate, *coordinate), c(*coordinate, *coordinate);
  const Point d(nudge(c.x() - (b.y() - a.y()), *ulps), nudge(c.y() + (b.x() - a.x()), *ulps));
  const auto cheap = certain_sign_of_difference(squared_distance_approximation(a, b), squared_distance_approximation(c, d));
  const auto refined = certain_sign_of_difference(refined_squared_distance(a, b), refined_squared_distance(c, d));
  RC_TAG(cheap.has_value(), refined.has_value());
  const auto expected = Kernel().compare_distance_2_object()(c, d, a, b);
  const CGAL::Sign truth = expected == CGAL::LARGER ? CGAL::POSITIVE : expected == CGAL::SMALLER ? CGAL::NEGATIVE : CGAL::ZERO;
  if (refined) {
    RC_ASSERT(*refined == truth);
  }
  // Both filters decide only strict comparisons.
  if (truth == CGAL::ZERO) {
    RC_ASSERT(!refined.has_value());
  }
}

TEST(CertainSignOfRefinedDifference, SettlesLengthsOneUlpApartThatTheCheapFilterCannot) {
  const Point a(0, 0), b(0.1, 0.7), c(0, 0), d(0.7, std::nextafter(0.1, 1.0));  // |cd|^2 > |ab|^2 by 2^-57 of it
  EXPECT_FALSE(certain_sign_of_difference(squared_distance_approximation(a, b), squared_distance_approximation(c, d)));
  EXPECT_EQ(certain_sign_of_difference(refined_squared_distance(a, b), refined_squared_distance(c, d)), CGAL::POSITIVE);
  EXPECT_EQ(certain_sign_of_difference(refined_squared_distance(c, d), refined_squared_distance(a, b)), CGAL::NEGATIVE);
}

}  // namespace
}  // namespace curvebench::geometry
