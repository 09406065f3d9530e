// The generated families of the benchmark (issue 16) against what their names say, checked
// by means independent of the generators: brute-force exact intersection tests, point
// location in polylines, distances over all point pairs, closed forms.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <CGAL/Polygon_2.h>

#include <cmath>
#include <numbers>

#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/curves/star_polygon.h"
#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

using testing::closed_polyline_self_intersects;
using testing::derivatives_match_finite_differences;
using testing::norm;
using testing::valid_curve;

constexpr double pi = std::numbers::pi;

std::vector<Point> points_along(const Curve_component& component, int count) {
  std::vector<Point> points;
  const double end = static_cast<double>(component.piece_count());
  for (int i = 0; i < count; ++i)
    points.push_back(component.point(end * i / (component.closed() ? count : count - 1)));
  return points;
}

// Pairs of non-adjacent chords of the polyline through `points` (closed) that meet: every
// pair, by CGAL's exact do_intersect. A transversal crossing between two chord vertices
// is one pair (one through a chord vertex would count twice: improbable at 2001 steps).
int crossing_chord_pairs(const std::vector<Point>& points) {
  const std::size_t n = points.size();
  const auto chord = [&](std::size_t i) { return Kernel::Segment_2(points[i], points[(i + 1) % n]); };
  int pairs = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j)
      if (!(i == 0 && j == n - 1) && CGAL::do_intersect(chord(i), chord(j))) ++pairs;
  return pairs;
}

double smallest_distance(const std::vector<Point>& a, const std::vector<Point>& b) {
  double smallest = HUGE_VAL;
  for (const Point& p : a)
    for (const Point& q : b) smallest = std::min(smallest, CGAL::squared_distance(p, q));
  return std::sqrt(smallest);
}

TEST(FourierArc, IsTheClosedCurveWithoutItsGapAndHasTwoEnds) {
  for (const double gap : {0.05, 0.2, 0.5}) {
    const Curve closed = random_fourier_curve(4), arc = random_fourier_arc(4, {}, gap);
    ASSERT_TRUE(valid_curve(arc));
    ASSERT_EQ(arc.components.size(), 1u);
    EXPECT_FALSE(arc.components[0].closed());
    EXPECT_EQ(arc.name, "fourier:seed=4,harmonics=5,amplitude=0.4,decay=2,gap=" + std::string(gap == 0.05 ? "0.05" : gap == 0.2 ? "0.2" : "0.5"));
    // The ends are the closed curve's points at θ = π (1 ± gap), i.e. s = (1 ± gap) / 2.
    const Curve_component &whole = closed.components[0], &open = arc.components[0];
    EXPECT_LT(norm(open.point(0) - whole.point((1 + gap) / 2)), 1e-12);
    EXPECT_LT(norm(open.point(1) - whole.point((1 - gap) / 2)), 1e-12);
    EXPECT_NEAR(open.length() / whole.length(), 1, gap + 0.05);  // not the length of the gap: the speed varies
    EXPECT_LT(open.length(), whole.length());
    EXPECT_TRUE(derivatives_match_finite_differences(open.piece(0), 0.3));
  }
  EXPECT_THROW(random_fourier_arc(1, {}, 0), std::invalid_argument);
  EXPECT_THROW(random_fourier_arc(1, {}, 1), std::invalid_argument);
}

TEST(Spiral, GrowsFromItsInnerRadiusToOneWithoutCrossingItself) {
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const Curve spiral = random_spiral(seed);
    ASSERT_TRUE(valid_curve(spiral));
    const Curve_component& component = spiral.components[0];
    EXPECT_FALSE(component.closed());
    const double inner = norm(component.point(0) - CGAL::ORIGIN), outer = norm(component.point(1) - CGAL::ORIGIN);
    EXPECT_GE(inner, 0.15);
    EXPECT_LT(inner, 0.4);
    EXPECT_NEAR(outer, 1, 1e-12);
    EXPECT_TRUE(derivatives_match_finite_differences(component.piece(0), 0.5));
    std::vector<Point> open = points_along(component, 1500);
    // An open polyline crosses itself iff the closed one does other than on its closing chord:
    // count on the closed one, where the closing chord crosses the arms the spiral winds over.
    int arm_crossings = 0;
    for (std::size_t i = 0; i + 1 < open.size(); ++i)
      for (std::size_t j = i + 2; j + 1 < open.size(); ++j)
        if (CGAL::do_intersect(Kernel::Segment_2(open[i], open[i + 1]), Kernel::Segment_2(open[j], open[j + 1])))
          ++arm_crossings;
    EXPECT_EQ(arm_crossings, 0) << spiral.name;
  }
}

TEST(Lissajous, CrossesItselfTwoABMinusAMinusBTimes) {
  for (const auto& [a, b] : {std::pair{1, 2}, {1, 3}, {2, 3}, {3, 4}})
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const Curve curve = lissajous_curve(a, b, seed);
      ASSERT_TRUE(valid_curve(curve));
      EXPECT_EQ(crossing_chord_pairs(points_along(curve.components[0], 2001)), 2 * a * b - a - b) << curve.name;
    }
  EXPECT_EQ(lissajous_crossings(2, 3), 7);
  EXPECT_THROW(lissajous_curve(2, 4, 1), std::invalid_argument);  // not coprime: retraces itself
  EXPECT_THROW(lissajous_curve(3, 2, 1), std::invalid_argument);
  EXPECT_THROW(lissajous_curve(5, 6, 1), std::invalid_argument);  // beyond the crossings a draw keeps apart
}

TEST(NestedFourierCurves, TheInnerCurveLiesInsideTheOuterAtTheStatedSeparation) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (const double separation : {0.05, 0.2}) {
      const Curve curve = nested_fourier_curves(seed, separation);
      ASSERT_TRUE(valid_curve(curve));
      ASSERT_EQ(curve.components.size(), 2u);
      const std::vector<Point> outer = points_along(curve.components[0], 1500), inner = points_along(curve.components[1], 1500);
      const CGAL::Polygon_2<Kernel> polygon(outer.begin(), outer.end());
      for (const Point& p : inner) ASSERT_EQ(polygon.bounded_side(p), CGAL::ON_BOUNDED_SIDE) << curve.name;
      EXPECT_FALSE(closed_polyline_self_intersects(inner));
      // Points 2π/1500 apart along unit-size curves: the distance of the point sets is
      // within a few thousandths of the curves'.
      EXPECT_NEAR(smallest_distance(outer, inner), separation, 0.004) << curve.name;
    }
  EXPECT_THROW(nested_fourier_curves(1, 5), std::invalid_argument);
}

TEST(RandomFourierCurves, SideBySideKeepTheirSeparationBetweenBoundingBoxes) {
  const Curve curve = random_fourier_curves(3, {}, 3, 0.1);
  ASSERT_EQ(curve.components.size(), 3u);
  EXPECT_EQ(curve.name, "fourier:seed=3,harmonics=5,amplitude=0.4,decay=2,components=3,separation=0.1");
  double previous_right = -HUGE_VAL;
  for (const Curve_component& component : curve.components) {
    const auto points = points_along(component, 4000);
    const auto box = CGAL::bbox_2(points.begin(), points.end());
    if (previous_right > -HUGE_VAL) {
      EXPECT_NEAR(box.xmin() - previous_right, 0.1, 1e-4);
    }
    previous_right = box.xmax();
  }
}

// The angle at a corner between the two sides, from points a little along each.
double corner_angle(const Curve_component& component, double s) {
  const double n = static_cast<double>(component.piece_count()), h = 1e-3;
  const Vector back = component.point(std::fmod(s - h + n, n)) - component.point(s);
  const Vector ahead = component.point(s + h) - component.point(s);
  return std::acos(back * ahead / (norm(back) * norm(ahead))) * 180 / pi;
}

TEST(StarPolygon, IsANonConvexSimplePolygonWithEveryTipAtTheStatedAngle) {
  for (const double angle : {20.0, 45.0, 90.0, 120.0})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const Curve star = star_polygon(seed, angle);
      ASSERT_TRUE(valid_curve(star));
      const Curve_component& component = star.components[0];
      const std::vector<double> corners = component.corners();
      ASSERT_EQ(corners.size(), component.piece_count()) << star.name;  // every vertex a corner
      ASSERT_EQ(corners.size() % 2, 0u);
      std::vector<Point> vertices;
      for (const double s : corners) vertices.push_back(component.point(s));
      const CGAL::Polygon_2<Kernel> polygon(vertices.begin(), vertices.end());
      EXPECT_TRUE(polygon.is_simple());
      EXPECT_FALSE(polygon.is_convex());
      EXPECT_EQ(polygon.orientation(), CGAL::COUNTERCLOCKWISE);
      for (std::size_t i = 0; i < corners.size(); i += 2) EXPECT_NEAR(corner_angle(component, corners[i]), angle, 1e-6);
      for (std::size_t i = 1; i < corners.size(); i += 2) EXPECT_GT(corner_angle(component, corners[i]), 0);
      EXPECT_GE(corners.size() / 2, 360 / (165 - angle));
    }
}

TEST(StarPolygon, RoundedIsSmoothWithArcsOfTheRoundingRadius) {
  const Curve sharp = star_polygon(7, 60), rounded = star_polygon(7, 60, 0.05);
  ASSERT_TRUE(valid_curve(rounded));
  const Curve_component& component = rounded.components[0];
  EXPECT_TRUE(component.corners().empty());
  EXPECT_EQ(component.piece_count(), 2 * sharp.components[0].piece_count());
  for (std::size_t i = 1; i < component.piece_count(); i += 2)  // the fillets
    EXPECT_NEAR(std::abs(component.curvature(i + 0.5)), 1 / 0.05, 1e-6);
  // Rounding cuts every corner: shorter, but by less than the corners' tangent lengths.
  EXPECT_LT(component.length(), sharp.components[0].length());
  EXPECT_THROW(star_polygon(7, 60, 1), std::invalid_argument);  // fillets longer than the sides
  EXPECT_THROW(star_polygon(7, 150), std::invalid_argument);
  EXPECT_THROW(star_polygon(7, 60, 1e-300), std::invalid_argument);  // a corner in all but name
}

TEST(CurveSpec, NamesOfTheGeneratedFamiliesMakeThemAgain) {
  for (const std::string spec : {"fourier:seed=2,harmonics=5,amplitude=0.4,decay=2,gap=0.25", "nested:seed=2,separation=0.1",
                                 "spiral:seed=2", "lissajous:a=1,b=3,seed=2", "star:seed=2,angle=30",
                                 "star:seed=2,angle=30,rounding=0.02"}) {
    const Curve curve = make_curve(spec);
    EXPECT_EQ(curve.name, spec);
    EXPECT_EQ(make_curve(curve.name).components[0].point(0.3), curve.components[0].point(0.3));
  }
  EXPECT_THROW(make_curve("fourier:seed=1,gap=0.2,components=2"), std::invalid_argument);
}

RC_GTEST_PROP(StarPolygon, EverySeedGivesASimpleStar, (std::uint16_t seed, std::uint8_t angle_step)) {
  const double angle = 10 + (angle_step % 13) * 10;  // 10 .. 130
  const Curve star = star_polygon(seed, angle);
  std::vector<Point> vertices;
  for (const double s : star.components[0].corners()) vertices.push_back(star.components[0].point(s));
  RC_ASSERT(vertices.size() == star.components[0].piece_count());
  RC_ASSERT(!closed_polyline_self_intersects(vertices));
}

}  // namespace
}  // namespace curvebench::geometry
