#include "geometry/curves/corner_curve.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

using testing::norm;

constexpr double degree = std::numbers::pi / 180;

TEST(SharpCornerCurve, HasOneCornerWithTheRequestedOpeningAngle) {
  for (int angle = 10; angle <= 170; angle += 5) {
    const Curve curve = sharp_corner_curve(angle);
    EXPECT_EQ(curve.name, "corner:angle=" + std::to_string(angle));
    ASSERT_EQ(curve.components.size(), 1u);
    const auto& c = curve.components[0];
    EXPECT_TRUE(c.closed());
    ASSERT_EQ(c.corners(), std::vector<double>{0}) << angle;
    // The angle at the apex between the two lines leaving it.
    const Vector back = -c.piece(2).derivative(1), forth = c.piece(0).derivative(0);
    EXPECT_NEAR(std::acos(back * forth / (norm(back) * norm(forth))), angle * degree, 1e-12) << angle;
    EXPECT_TRUE(testing::valid_curve(curve));
  }
}

TEST(SharpCornerCurve, IsTheUnitCircleWithTwoTangents) {
  EXPECT_TRUE(rc::check("lengths, curvature, tangency", [] {
    const double angle = *rc::gen::inRange(1, 1800) / 10.0, half = angle * degree / 2;
    const Curve c_curve = sharp_corner_curve(angle);
    const auto& c = c_curve.components[0];
    // Each tangent from the apex at distance 1 / sin(half) has length cot(half); the arc
    // spans 360° minus the 180° - angle the tangent points cut off.
    RC_ASSERT(std::abs(c.length() - (2 / std::tan(half) + std::numbers::pi + 2 * half)) <= 1e-10 * c.length());
    RC_ASSERT(std::abs(c.curvature(1.5) - 1) <= 1e-12);
    RC_ASSERT(std::abs(c.curvature(0.5)) <= 1e-12);
    RC_ASSERT(std::abs(norm(c.point(1) - CGAL::ORIGIN) - 1) <= 1e-12);
    RC_ASSERT(std::abs(norm(c.point(1.3) - CGAL::ORIGIN) - 1) <= 1e-12);
    RC_ASSERT(std::abs(c.point(0).x() - 1 / std::sin(half)) <= 1e-12 / std::sin(half) && c.point(0).y() == 0);
    RC_ASSERT(c.corners().size() == 1u);
  }));
}

TEST(SharpCornerCurve, RejectsAnglesOutsideZeroTo180) {
  for (const double bad : {0.0, -10.0, 180.0, 200.0, double(NAN)}) EXPECT_THROW(sharp_corner_curve(bad), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench::geometry
