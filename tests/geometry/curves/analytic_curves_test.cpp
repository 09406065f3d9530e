#include "geometry/curves/analytic_curves.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

using testing::closed_polyline_self_intersects;
using testing::derivatives_match_finite_differences;
using testing::valid_curve;

constexpr double pi = std::numbers::pi;

// The ellipse's perimeter by the Gauss-Kummer series π (a + b) Σ binom(1/2, n)² h^n,
// h = ((a - b) / (a + b))²: independent of the curve model's quadrature.
double ellipse_perimeter(double a, double b) {
  const double h = std::pow((a - b) / (a + b), 2);
  double sum = 0, coefficient = 1, power = 1;
  for (int n = 0; n < 400; ++n) {
    sum += coefficient * coefficient * power;
    coefficient *= (0.5 - n) / (n + 1);
    power *= h;
  }
  return pi * (a + b) * sum;
}

TEST(AnalyticCurves, CircleHasLengthTwoPiRAndCurvatureOneOverR) {
  for (const double r : {1e-3, 0.5, 1.0, 7.0, 1e4}) {
    const Curve curve = circle(r);
    EXPECT_EQ(curve.name, r == 1.0 ? "circle:r=1" : curve.name);
    ASSERT_EQ(curve.components.size(), 1u);
    const auto& c = curve.components[0];
    EXPECT_TRUE(c.closed());
    EXPECT_NEAR(c.length(), 2 * pi * r, 1e-12 * r);
    for (const double s : {0.0, 0.1, 0.37, 0.9}) {
      EXPECT_NEAR(c.curvature(s), 1 / r, 1e-12 / r);
      EXPECT_NEAR(std::hypot(c.point(s).x(), c.point(s).y()), r, 1e-12 * r);
    }
    EXPECT_TRUE(c.corners().empty());
  }
  EXPECT_EQ(circle(2.5).name, "circle:r=2.5");
}

TEST(AnalyticCurves, EllipseLengthMatchesTheGaussKummerSeries) {
  EXPECT_NEAR(ellipse_perimeter(1, 1), 2 * pi, 1e-14);
  EXPECT_TRUE(rc::check("ellipse perimeter", [] {
    const double a = *rc::gen::inRange(1, 1000) / 100.0, b = a / (*rc::gen::inRange(100, 600) / 100.0);
    const Curve curve = ellipse(a, b);
    RC_ASSERT(std::abs(curve.length() - ellipse_perimeter(a, b)) <= 1e-9 * curve.length());
  }));
}

TEST(AnalyticCurves, EllipseCurvatureMatchesTheClosedForm) {
  EXPECT_TRUE(rc::check("ellipse curvature ab / (a² sin² θ + b² cos² θ)^(3/2)", [] {
    const double a = *rc::gen::inRange(10, 1000) / 100.0, b = *rc::gen::inRange(10, 1000) / 100.0;
    const double s = *rc::gen::inRange(0, 1000) / 1000.0, theta = 2 * pi * s;
    const Curve c_curve = ellipse(a, b);
    const auto& c = c_curve.components[0];
    const double expected = a * b / std::pow(std::pow(a * std::sin(theta), 2) + std::pow(b * std::cos(theta), 2), 1.5);
    RC_ASSERT(std::abs(c.curvature(s) - expected) <= 1e-10 * expected);
    RC_ASSERT(std::abs(c.point(s).x() - a * std::cos(theta)) <= 1e-12 * a);
  }));
  EXPECT_EQ(ellipse(2, 1).name, "ellipse:a=2,b=1");
}

TEST(AnalyticCurves, RejectsNonPositiveOrNonFiniteSizes) {
  for (const double bad : {0.0, -1.0, HUGE_VAL, double(NAN)}) {
    EXPECT_THROW(circle(bad), std::invalid_argument);
    EXPECT_THROW(ellipse(1, bad), std::invalid_argument);
    EXPECT_THROW(superellipse(1, 1, bad), std::invalid_argument);
  }
}

TEST(AnalyticCurves, SuperellipsePointsSatisfyItsEquation) {
  EXPECT_TRUE(rc::check("|x/a|^n + |y/b|^n = 1 on the curve", [] {
    const double a = *rc::gen::inRange(10, 500) / 100.0, b = *rc::gen::inRange(10, 500) / 100.0;
    const double n = *rc::gen::inRange(20, 1000) / 100.0;
    const Curve c_curve = superellipse(a, b, n);
    const auto& c = c_curve.components[0];
    const double s = *rc::gen::inRange(0, 1000) / 1000.0 * double(c.piece_count());
    const Point p = c.point(s);
    RC_ASSERT(std::abs(std::pow(std::abs(p.x() / a), n) + std::pow(std::abs(p.y() / b), n) - 1) <= 1e-12);
  }));
}

TEST(AnalyticCurves, SuperellipseSpecialCasesAndCorners) {
  // n = 2 is the ellipse, n = 1 the rhombus with sides √(a² + b²), n <= 1 has four corners.
  EXPECT_NEAR(superellipse(2, 1, 2).length(), ellipse_perimeter(2, 1), 1e-9);
  EXPECT_NEAR(superellipse(2, 1, 1).length(), 4 * std::sqrt(5.0), 1e-12);
  for (const double n : {0.3, 0.5, 1.0}) EXPECT_EQ(superellipse(2, 1, n).components[0].corners().size(), 4u) << n;
  for (const double n : {1.2, 1.9, 2.0, 4.0, 10.0}) EXPECT_TRUE(superellipse(2, 1, n).components[0].corners().empty()) << n;
  EXPECT_EQ(superellipse(1, 1, 4).components[0].piece_count(), 1u);
  EXPECT_EQ(superellipse(1, 1, 4).name, "superellipse:a=1,b=1,n=4");
  // A squircle's curvature vanishes at the axis points: r(φ) = 1 has r'' = 0 there for n > 2.
  EXPECT_NEAR(superellipse(1, 1, 4).components[0].curvature(0), 0, 1e-9);
}

TEST(AnalyticCurves, DerivativesMatchFiniteDifferences) {
  EXPECT_TRUE(rc::check("ellipse, superellipse and Fourier pieces", [] {
    const double a = *rc::gen::inRange(10, 500) / 100.0, b = *rc::gen::inRange(10, 500) / 100.0;
    const double n = *rc::gen::inRange(20, 800) / 100.0;
    // Away from the superellipse's axis points, where derivatives of some order blow up for n < 3.
    const double t = 0.011 + *rc::gen::inRange(0, 1000) / 1000.0 * 0.228 + 0.25 * *rc::gen::inRange(0, 4);
    for (const Curve& curve : {circle(a), ellipse(a, b), superellipse(a, b, n),
                               random_fourier_curve(*rc::gen::arbitrary<std::uint64_t>())}) {
      const auto& c = curve.components[0];
      for (std::size_t i = 0; i < c.piece_count(); ++i) RC_ASSERT(derivatives_match_finite_differences(c.piece(i), t));
    }
  }));
}

TEST(AnalyticCurves, ArcLengthInversionRoundTrips) {
  EXPECT_TRUE(rc::check("parameter_at_arc_length(arc_length(s)) = s", [] {
    const std::uint64_t seed = *rc::gen::arbitrary<std::uint64_t>();
    for (const Curve& curve : {ellipse(3, 0.5), superellipse(1, 2, 0.7), superellipse(1, 2, 1.5), random_fourier_curve(seed)}) {
      const auto& c = curve.components[0];
      const double s = *rc::gen::inRange(0, 10000) / 10000.0 * double(c.piece_count());
      RC_ASSERT(std::abs(c.parameter_at_arc_length(c.arc_length(s)) - s) <= 1e-9);
    }
  }));
}

std::vector<Point> parameter_polyline(const Curve_component& c, int n) {
  std::vector<Point> points;
  for (int i = 0; i < n; ++i) points.push_back(c.point(double(i) / n));
  return points;
}

TEST(AnalyticCurves, FourierCurvesAreReproducibleAndDifferBySeed) {
  const Curve first = random_fourier_curve(7), again = random_fourier_curve(7), other = random_fourier_curve(8);
  EXPECT_EQ(first.name, "fourier:seed=7,harmonics=5,amplitude=0.4,decay=2");
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const double s = i / 100.0;
    const Point p = first.components[0].point(s), q = again.components[0].point(s);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(p.x()), std::bit_cast<std::uint64_t>(q.x()));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(p.y()), std::bit_cast<std::uint64_t>(q.y()));
    differs = differs || p != other.components[0].point(s);
  }
  EXPECT_TRUE(differs);
}

TEST(AnalyticCurves, FourierCoefficientsArePlatformIndependent) {
  // At θ = 0 the point is (1, 0) + Σ A_k: sums of mt19937_64 draws mapped exactly and scaled
  // by amplitude / k² (exact powers), no libm sine involved. The bits were recorded once.
  const Point start = random_fourier_curve(7).components[0].point(0);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(start.x()), 0x3ff03bafeaeb5cb5ULL) << std::hexfloat << start.x();
  EXPECT_EQ(std::bit_cast<std::uint64_t>(start.y()), 0x3fb0e8bbbedd8316ULL) << std::hexfloat << start.y();
}

TEST(AnalyticCurves, FourierCurvesNeverSelfIntersect) {
  EXPECT_TRUE(rc::check("brute-force segment test on a polyline of 1500 parameter steps", [] {
    const std::uint64_t seed = *rc::gen::arbitrary<std::uint64_t>();
    const double amplitude = *rc::gen::inRange(0, 120) / 100.0;  // up to strongly folded curves
    const Curve curve = random_fourier_curve(seed, {6, amplitude, 1.5});
    RC_ASSERT(valid_curve(curve));
    RC_ASSERT(!closed_polyline_self_intersects(parameter_polyline(curve.components[0], 1500)));
  }));
}

TEST(AnalyticCurves, FourierRejectsBadParameters) {
  EXPECT_THROW(random_fourier_curve(1, {-1, 0.4, 2}), std::invalid_argument);
  EXPECT_THROW(random_fourier_curve(1, {65, 0.4, 2}), std::invalid_argument);
  EXPECT_THROW(random_fourier_curve(1, {5, -0.1, 2}), std::invalid_argument);
  EXPECT_THROW(random_fourier_curve(1, {5, double(NAN), 2}), std::invalid_argument);
  EXPECT_NEAR(random_fourier_curve(1, {0, 0.4, 2}).length(), 2 * pi, 1e-12);  // no harmonic: the unit circle
}

}  // namespace
}  // namespace curvebench::geometry
