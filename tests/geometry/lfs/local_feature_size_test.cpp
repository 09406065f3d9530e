#include <gtest/gtest.h>

#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/corner_curve.h"
#include "geometry/curves/curve_crossings.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/lfs/medial_axis.h"
#include "tests/support/closed_form_lfs.h"
#include "tests/support/even_in_range.h"

namespace curvebench::geometry {
namespace {

using testing::ellipse_lfs;
using testing::sharp_corner_lfs;

Curve open_segment(const Point& a, const Point& b) {
  Curve curve{"segment", {}};
  curve.components.emplace_back(std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Line_segment>(a, b)},
                                false);
  return curve;
}

Curve circle_at(const Point& center, double r) {
  return Curve{"circle", {Curve_component({std::make_shared<Circular_arc>(center, r, 0, 2 * std::numbers::pi)}, true)}};
}

TEST(MedialAxis, OfARegularPolygonIsItsCenter) {
  std::vector<Point> polygon;
  for (int k = 0; k < 12; ++k) polygon.emplace_back(3 + std::cos(k * std::numbers::pi / 6), -1 + std::sin(k * std::numbers::pi / 6));
  const std::vector<Sample_chain> chain{{polygon.size(), true}};
  const Medial_axis axis(polygon, chain, {});
  ASSERT_FALSE(axis.points().empty());
  for (const Point& p : axis.points()) EXPECT_LT(std::hypot(p.x() - 3, p.y() + 1), 1e-12);
  EXPECT_NEAR(axis.distance(Point(3, 1)), 2, 1e-12);
}

TEST(MedialAxis, OfCollinearPointsIsEmptyUnlessGivenExactPoints) {
  const std::vector<Point> line{{0, 0}, {1, 1}, {2, 2}};
  const std::vector<Sample_chain> chain{{line.size(), false}};
  EXPECT_EQ(Medial_axis(line, chain, {}).distance(Point(0, 0)), std::numeric_limits<double>::infinity());
  const std::vector<Point> exact{{5, 1}};
  EXPECT_EQ(Medial_axis(line, chain, exact).distance(Point(2, 1)), 3);
}

TEST(LocalFeatureSize, OfACircleIsItsRadius) {
  const Local_feature_size lfs(circle(2.5));
  for (int i = 0; i < 500; ++i) EXPECT_NEAR(lfs.at(0, i / 500.0), 2.5, 1e-9);
  EXPECT_NEAR(lfs.at(Point(0.5, 0)), 0.5, 1e-9);  // off the curve: its distance to the medial axis
  EXPECT_TRUE(lfs.sharp_points().empty());
  for (const Point& p : lfs.medial_axis().points()) EXPECT_LT(std::hypot(p.x(), p.y()), 1e-9);
}

// An arc of the unit circle with a gap of half-angle g around the direction (1, 0): its
// medial axis is the ray from the centre through the gap (a point on it has the two ends
// as its nearest points), so at angle t from the gap's direction lfs = sin t for t <= 90
// degrees, else 1 (the centre). At the ends it is half the gap's chord: no Voronoi vertex
// of a dense sample is near there, as all are the centre.
TEST(LocalFeatureSize, OfAnOpenArcIsItsDistanceToTheRayThroughTheGap) {
  for (const double g : {0.1 * std::numbers::pi, 0.3 * std::numbers::pi}) {
    const Curve arc{"arc", {Curve_component({std::make_shared<Circular_arc>(Point(0, 0), 1, g, 2 * std::numbers::pi - 2 * g)}, false)}};
    const Local_feature_size lfs(arc);
    const Curve_component& component = arc.components[0];
    double worst = 0;
    for (int i = 0; i <= 400; ++i) {
      const double s = i / 400.0 * static_cast<double>(component.piece_count());
      const Point p = component.point(s);
      const double t = std::abs(std::atan2(p.y(), p.x()));
      const double expected = t <= std::numbers::pi / 2 ? std::sin(t) : 1.0;
      worst = std::max(worst, std::abs(lfs.at(0, s) - expected) / expected);
    }
    EXPECT_LT(worst, 1e-3) << "gap half-angle " << g;
    EXPECT_GE(lfs.at(0, 0.0), std::sin(g) * (1 - 1e-9));  // from above: the estimate never undercuts
  }
}

// The accuracy the header promises: relative error below 1e-3 at the default density,
// against the closed form, over many points of ellipses of several aspect ratios.
TEST(LocalFeatureSize, MatchesTheEllipseClosedFormWithinOnePerMille) {
  for (const double ratio : {1.25, 2.0, 4.0, 8.0}) {
    const double a = 1.5, b = a / ratio;
    const Local_feature_size lfs(ellipse(a, b));
    const Curve_component& component = lfs.curve().components[0];
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
      const double s = (i + 0.37) / 2000;  // off the dense sample's grid
      const double truth = ellipse_lfs(a, b, component.point(s));
      worst = std::max(worst, std::abs(lfs.at(0, s) - truth) / truth);
    }
    EXPECT_LT(worst, 1e-3) << "a/b = " << ratio;
  }
}

TEST(LocalFeatureSize, GetsMoreAccurateWithDensity) {
  const auto worst_error = [](double density) {
    const Local_feature_size lfs(ellipse(1, 0.25), density);
    double worst = 0;
    for (int i = 0; i < 1000; ++i) {
      const Point p = lfs.curve().components[0].point(i / 1000.0);
      worst = std::max(worst, std::abs(lfs.at(p) - ellipse_lfs(1, 0.25, p)) / ellipse_lfs(1, 0.25, p));
    }
    return worst;
  };
  EXPECT_LT(worst_error(32), worst_error(8) / 4);  // measured: error ~ 1 / density²
}

TEST(LocalFeatureSize, IsZeroAtASharpCornerAndLinearNearIt) {
  for (const double angle : {10.0, 45.0, 90.0}) {
    const Local_feature_size lfs(sharp_corner_curve(angle));
    ASSERT_EQ(lfs.sharp_points().size(), 1u);
    EXPECT_EQ(lfs.sharp_points()[0].location, (Curve_location{0, 0.0}));
    EXPECT_NEAR(lfs.sharp_points()[0].point.x(), 1 / std::sin(angle * std::numbers::pi / 360), 1e-12);
    EXPECT_EQ(lfs.at(0, 0.0), 0);
    EXPECT_EQ(lfs.at(0, 3.0), 0);  // the same corner, one turn on
    const Curve_component& component = lfs.curve().components[0];
    for (int i = 1; i < 3000; ++i) {
      const double s = 3.0 * i / 3000;
      const double truth = sharp_corner_lfs(angle, component.point(s));
      if (truth > 0.01) {
        EXPECT_LT(std::abs(lfs.at(0, s) - truth) / truth, 1e-3) << "angle " << angle << " s " << s;
      }
      EXPECT_GE(lfs.at(0, s), truth * (1 - 1e-9)) << "converges from above";
    }
  }
}

TEST(LocalFeatureSize, IsInfiniteOnAStraightSegment) {
  const Local_feature_size lfs(open_segment(Point(0, 0), Point(2, 1)));
  EXPECT_EQ(lfs.at(0, 0.5), std::numeric_limits<double>::infinity());
  EXPECT_EQ(lfs.dense_parameters(0).front(), 0);
  EXPECT_EQ(lfs.dense_parameters(0).back(), 1);
}

TEST(LocalFeatureSize, RejectsANonPositiveDensity) {
  EXPECT_THROW(Local_feature_size(circle(1), 0), std::invalid_argument);
  EXPECT_THROW(Local_feature_size(circle(1), 32, -1), std::invalid_argument);
}

// Two unit circles a distance 1 apart cross at (1/2, ±√3/2): sharp points of both, lfs 0.
TEST(LocalFeatureSize, IsZeroWhereComponentsCross) {
  Curve curve = circle_at(Point(0, 0), 1);
  curve.components.push_back(circle_at(Point(1, 0), 1).components[0]);
  const Local_feature_size lfs(curve);
  ASSERT_EQ(lfs.sharp_points().size(), 4u);
  for (const Sharp_point& sharp : lfs.sharp_points()) {
    EXPECT_NEAR(sharp.point.x(), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(sharp.point.y()), std::sqrt(3.0) / 2, 1e-12);
    const double expected_angle = sharp.location.component == 0 ? std::numbers::pi / 3 : 2 * std::numbers::pi / 3;
    const double angle = 2 * std::numbers::pi * sharp.location.parameter;
    EXPECT_NEAR(std::min(angle, 2 * std::numbers::pi - angle), expected_angle, 1e-9);
    EXPECT_EQ(lfs.at(sharp.location.component, sharp.location.parameter), 0);
  }
}

TEST(CurveCrossings, FindsASelfCrossingOnce) {
  // An open polyline whose first and last segments cross at (1, 1).
  Curve curve{"cross", {}};
  curve.components.emplace_back(
      std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Line_segment>(Point(0, 0), Point(2, 2)),
                                                      std::make_shared<Line_segment>(Point(2, 2), Point(2, 0)),
                                                      std::make_shared<Line_segment>(Point(2, 0), Point(0, 2))},
      false);
  const std::vector<std::vector<double>> chords{{0, 0.5, 1, 1.5, 2, 2.25, 2.5, 2.75, 3}};
  const auto crossings = curve_crossings(curve, chords);
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_NEAR(crossings[0].point.x(), 1, 1e-12);
  EXPECT_NEAR(crossings[0].point.y(), 1, 1e-12);
  EXPECT_NEAR(crossings[0].first.parameter, 0.5, 1e-12);
  EXPECT_NEAR(crossings[0].second.parameter, 2.5, 1e-12);
}

RC_GTEST_PROP(LocalFeatureSize, OfAnEllipseIsWithinOnePerMilleAtRandomPoints, ()) {
  const double ratio = *testing::even_in_range(101, 800) / 100.0;
  const double s = *testing::even_in_range(0, 1000000) / 1e6;
  const double a = 2, b = a / ratio;
  static std::map<double, Local_feature_size> cache;  // one estimate per ratio drawn
  const auto& lfs = cache.try_emplace(ratio, ellipse(a, b)).first->second;
  const double truth = ellipse_lfs(a, b, lfs.curve().components[0].point(s));
  RC_ASSERT(std::abs(lfs.at(0, s) - truth) / truth < 1e-3);
}

}  // namespace
}  // namespace curvebench::geometry
