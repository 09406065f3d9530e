#include "geometry/curves/cubic_bezier.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>

#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

using testing::derivatives_match_finite_differences;
using testing::norm;

// The textbook Bernstein form, for comparison.
Point bezier(const std::array<Point, 4>& p, double t) {
  const double s = 1 - t;
  return {s * s * s * p[0].x() + 3 * s * s * t * p[1].x() + 3 * s * t * t * p[2].x() + t * t * t * p[3].x(),
          s * s * s * p[0].y() + 3 * s * s * t * p[1].y() + 3 * s * t * t * p[2].y() + t * t * t * p[3].y()};
}

rc::Gen<Point> small_point() {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(-100, 101), rc::gen::inRange(-100, 101)),
                      [](std::pair<int, int> xy) { return Point(xy.first / 10.0, xy.second / 10.0); });
}

// Control points not all on a line; with a degenerate start (p1 = p0), end (p2 = p3), or neither.
rc::Gen<std::array<Point, 4>> cubic_control_points() {
  return rc::gen::suchThat(
      rc::gen::apply(
          [](Point a, Point b, Point c, Point d, int degenerate) {
            if (degenerate == 1) b = a;
            if (degenerate == 2) c = d;
            return std::array<Point, 4>{a, b, c, d};
          },
          small_point(), small_point(), small_point(), small_point(), rc::gen::inRange(0, 3)),
      [](const std::array<Point, 4>& p) {
        return !(CGAL::collinear(p[0], p[1], p[2]) && CGAL::collinear(p[0], p[1], p[3]) &&
                 CGAL::collinear(p[0], p[2], p[3]) && CGAL::collinear(p[1], p[2], p[3]));
      });
}

TEST(CubicBezier, DerivativesMatchFiniteDifferences) {
  EXPECT_TRUE(rc::check("any cubic, degenerate ends included", [] {
    const Cubic_bezier piece(*cubic_control_points());
    RC_ASSERT(derivatives_match_finite_differences(piece, *rc::gen::inRange(2, 99) / 100.0, 1e-5));
  }));
}

TEST(CubicBezier, TracesTheBezierCurveFromEndToEnd) {
  EXPECT_TRUE(rc::check("same points as B(t), ends exact, regular", [] {
    const auto p = *cubic_control_points();
    const Cubic_bezier piece(p);
    RC_ASSERT(piece.point(0) == p[0]);
    RC_ASSERT(piece.point(1) == p[3]);
    RC_ASSERT(norm(piece.derivative(0)) > 0);
    RC_ASSERT(norm(piece.derivative(1)) > 0);
    const double u = *rc::gen::inRange(0, 1001) / 1000.0;
    // The reparametrised end runs B(√u) (start) or B(1 - √(1 - u)) (end).
    const double t = p[1] == p[0] ? std::sqrt(u) : p[2] == p[3] ? 1 - std::sqrt(1 - u) : u;
    RC_ASSERT(norm(piece.point(u) - bezier(p, t)) <= 1e-12 * 20);
  }));
}

TEST(CubicBezier, DegenerateEndsHaveTheTangentOfTheNextControlPoint) {
  const Cubic_bezier start({Point(0, 0), Point(0, 0), Point(1, 1), Point(2, 0)});
  EXPECT_EQ(start.derivative(0), Vector(3, 3));
  const Cubic_bezier end({Point(0, 0), Point(1, 1), Point(2, 0), Point(2, 0)});
  EXPECT_EQ(end.derivative(1), Vector(3, -3));
  EXPECT_TRUE(std::isfinite(end.second_derivative(1).x()));
}

TEST(CubicBezier, CollinearControlPointsBecomeSegmentsBetweenTurningPoints) {
  std::vector<std::shared_ptr<const Curve_piece>> pieces;
  append_cubic_bezier(pieces, {Point(1, 1), Point(1, 1), Point(1, 1), Point(1, 1)});
  EXPECT_TRUE(pieces.empty());
  append_cubic_bezier(pieces, {Point(0, 0), Point(1, 0), Point(1, 0), Point(3, 0)});
  ASSERT_EQ(pieces.size(), 1u);  // monotone: one segment
  EXPECT_EQ(pieces[0]->point(1), Point(3, 0));
  pieces.clear();
  // x(t) = 6t - 15t² + 10t³ turns where 1 - 5t + 5t² = 0, at t = (5 ∓ √5) / 10: forth, back, forth.
  const std::array<Point, 4> p{Point(0, 0), Point(2, 0), Point(-1, 0), Point(1, 0)};
  append_cubic_bezier(pieces, p);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[0]->point(0), Point(0, 0));
  EXPECT_NEAR(pieces[0]->point(1).x(), bezier(p, (5 - std::sqrt(5.0)) / 10).x(), 1e-15);
  EXPECT_NEAR(pieces[1]->point(1).x(), bezier(p, (5 + std::sqrt(5.0)) / 10).x(), 1e-15);
  EXPECT_EQ(pieces[2]->point(1), Point(1, 0));
  // The segments cover exactly the total variation of x(t).
  double variation = 0, covered = 0;
  for (int i = 0; i < 100000; ++i) variation += std::abs(bezier(p, (i + 1) / 1e5).x() - bezier(p, i / 1e5).x());
  for (const auto& piece : pieces) covered += norm(piece->derivative(0));
  EXPECT_NEAR(covered, variation, 1e-9);
}

TEST(CubicBezier, ElevatedQuadraticIsTheSameCurve) {
  EXPECT_TRUE(rc::check("quadratic (1-t)² p0 + 2(1-t)t c + t² p1", [] {
    const Point p0 = *small_point(), c = *small_point(), p1 = *small_point();
    const auto cubic = elevate_quadratic_bezier(p0, c, p1);
    const double t = *rc::gen::inRange(0, 101) / 100.0, s = 1 - t;
    const Point expected(s * s * p0.x() + 2 * s * t * c.x() + t * t * p1.x(), s * s * p0.y() + 2 * s * t * c.y() + t * t * p1.y());
    RC_ASSERT(cubic[0] == p0);
    RC_ASSERT(cubic[3] == p1);
    RC_ASSERT(norm(bezier(cubic, t) - expected) <= 1e-13);
  }));
}

}  // namespace
}  // namespace curvebench::geometry
