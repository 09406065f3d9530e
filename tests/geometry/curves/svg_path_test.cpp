#include "geometry/curves/svg_path.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <regex>
#include <string>

#include "geometry/curves/cubic_bezier.h"
#include "geometry/io/parse_error.h"
#include "tests/support/temporary_directory.h"
#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

using testing::norm;
using testing::valid_curve;

// Whether two curves have the same components, pieces and points at many parameters.
::testing::AssertionResult same_curve(const Curve& a, const Curve& b, double tolerance = 0) {
  if (a.components.size() != b.components.size())
    return ::testing::AssertionFailure() << a.components.size() << " vs " << b.components.size() << " components";
  for (std::size_t c = 0; c < a.components.size(); ++c) {
    const auto &p = a.components[c], &q = b.components[c];
    if (p.closed() != q.closed() || p.piece_count() != q.piece_count())
      return ::testing::AssertionFailure() << "component " << c << " differs in closure or piece count";
    for (int i = 0; i <= 64; ++i) {
      const double s = i / 64.0 * double(p.piece_count());
      if (norm(p.point(s) - q.point(s)) > tolerance)
        return ::testing::AssertionFailure() << "component " << c << " at s = " << s << ": " << p.point(s) << " vs " << q.point(s);
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(SvgPath, UnitSquareHasLengthFourAndFourCorners) {
  const Curve square = parse_svg_path("M0 0 H1 V1 H0 Z");
  ASSERT_EQ(square.components.size(), 1u);
  const auto& c = square.components[0];
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.piece_count(), 4u);
  EXPECT_DOUBLE_EQ(c.length(), 4);
  EXPECT_EQ(c.corners(), (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ(c.point(2.5), Point(0.5, 1));
}

TEST(SvgPath, RelativeCommandsEqualTheirAbsoluteVersions) {
  EXPECT_TRUE(same_curve(parse_svg_path("m 1 1 l 2 0 0 2 h -1 v -1 z"), parse_svg_path("M1 1 L3 1 3 3 H2 V2 Z")));
  EXPECT_TRUE(same_curve(parse_svg_path("m1 1 c 1 1 2 1 3 0 s 2 -1 3 0 q 1 1 2 0 t 2 0"),
                         parse_svg_path("M1 1 C2 2 3 2 4 1 S6 0 7 1 Q8 2 9 1 T11 1")));
  // Random paths of integer coordinates, where relative offsets are exact.
  EXPECT_TRUE(rc::check("relative = absolute", [] {
    const auto coordinate = rc::gen::inRange(-20, 21);
    const auto put = [](std::string& text, int value) {
      text += ' ';
      text += std::to_string(value);
    };
    int x = *coordinate, y = *coordinate;
    std::string absolute = "M", relative = "m";
    put(absolute, x), put(absolute, y), put(relative, x), put(relative, y);
    for (int segment = *rc::gen::inRange(1, 8); segment > 0; --segment) {
      const char command = *rc::gen::element('L', 'H', 'V', 'C', 'S', 'Q', 'T');
      const int count = command == 'C' ? 3 : command == 'S' || command == 'Q' ? 2 : 1;  // points
      absolute += command;
      relative += char(command - 'A' + 'a');
      for (int point = 0; point < count; ++point) {
        const int px = *coordinate, py = *coordinate;
        if (command != 'V') put(absolute, px), put(relative, px - x);
        if (command != 'H') put(absolute, py), put(relative, py - y);
        if (point == count - 1) {
          if (command != 'V') x = px;
          if (command != 'H') y = py;
        }
      }
    }
    if (*rc::gen::arbitrary<bool>()) absolute += "Z", relative += "z";
    RC_ASSERT(same_curve(parse_svg_path(absolute), parse_svg_path(relative)));
  }));
}

TEST(SvgPath, ReadsCompactNumbersAndImplicitCommands) {
  const Curve curve = parse_svg_path("M-.5.5L1e-3,2E+1-1-2");
  ASSERT_EQ(curve.components.size(), 1u);
  const auto& c = curve.components[0];
  ASSERT_EQ(c.piece_count(), 2u);
  EXPECT_EQ(c.point(0), Point(-0.5, 0.5));
  EXPECT_EQ(c.point(1), Point(0.001, 20));
  EXPECT_EQ(c.piece(1).point(0), Point(0.001, 20));
  EXPECT_NEAR(norm(c.point(2) - Point(-1, -2)), 0, 1e-15);
  // After M further pairs are lines; after m relative lines.
  EXPECT_TRUE(same_curve(parse_svg_path("M0 0 1 0 1 1"), parse_svg_path("M0 0 L1 0 L1 1")));
  EXPECT_TRUE(same_curve(parse_svg_path("m1 1 1 0 0 1"), parse_svg_path("M1 1 L2 1 L2 2")));
  EXPECT_TRUE(same_curve(parse_svg_path("M0,0C0,1,1,1,1,0,1,-1,2,-1,2,0"), parse_svg_path("M0 0 C0 1 1 1 1 0 C1 -1 2 -1 2 0")));
  EXPECT_TRUE(parse_svg_path("").components.empty());
  EXPECT_TRUE(parse_svg_path(" \t\r\n").components.empty());
}

TEST(SvgPath, SmoothCommandsReflectThePreviousControlPoint) {
  EXPECT_TRUE(same_curve(parse_svg_path("M0 0 C0 1 1 1 1 0 S2 -1 2 0"), parse_svg_path("M0 0 C0 1 1 1 1 0 C1 -1 2 -1 2 0")));
  EXPECT_TRUE(same_curve(parse_svg_path("M0 0 Q1 1 2 0 T4 0"), parse_svg_path("M0 0 Q1 1 2 0 Q3 -1 4 0")));
  // Without a preceding curve of the same kind the first control point is the current point.
  EXPECT_TRUE(same_curve(parse_svg_path("M0 0 L1 0 S2 1 3 0"), parse_svg_path("M0 0 L1 0 C1 0 2 1 3 0")));
  EXPECT_TRUE(same_curve(parse_svg_path("M0 0 C0 1 1 1 1 0 T3 0"), parse_svg_path("M0 0 C0 1 1 1 1 0 L3 0")));
  EXPECT_TRUE(same_curve(parse_svg_path("M0 0 C1 1 2 1 3 0 Z S1 1 2 0"), parse_svg_path("M0 0 C1 1 2 1 3 0 Z C0 0 1 1 2 0")));
}

TEST(SvgPath, QuadraticsAreElevatedToCubics) {
  const Curve curve = parse_svg_path("M0 0 Q3 3 6 0");
  const auto* cubic = dynamic_cast<const Cubic_bezier*>(&curve.components[0].piece(0));
  ASSERT_NE(cubic, nullptr);
  const std::array<Point, 4> expected{Point(0, 0), Point(2, 2), Point(4, 2), Point(6, 0)};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(norm(cubic->control_points()[i] - expected[i]), 0, 1e-15);
  EXPECT_NEAR(curve.components[0].point(0.5).y(), 1.5, 1e-15);  // (1-t)² 0 + 2(1-t)t 3 + t² 0 at t = 1/2
}

TEST(SvgPath, SubpathsBecomeComponentsClosedByZ) {
  const Curve curve = parse_svg_path("M0 0 L1 0 L1 1 Z M5 5 L6 6 m1 1 l1 0");
  ASSERT_EQ(curve.components.size(), 3u);
  EXPECT_TRUE(curve.components[0].closed());
  EXPECT_EQ(curve.components[0].piece_count(), 3u);
  EXPECT_FALSE(curve.components[1].closed());
  EXPECT_EQ(curve.components[2].point(0), Point(7, 7));
  // After Z, a drawing command starts the next subpath at the same start.
  const Curve again = parse_svg_path("M1 1 L2 1 L2 2 Z L1 0");
  ASSERT_EQ(again.components.size(), 2u);
  EXPECT_EQ(again.components[1].point(0), Point(1, 1));
  EXPECT_EQ(again.components[1].point(1), Point(1, 0));
}

TEST(SvgPath, DropsZeroLengthSegmentsAndLonePoints) {
  const Curve curve = parse_svg_path("M0 0 L0 0 L1 0 L1 0 C1 0 1 0 1 0 l0 0 h0 v0 M3 3 M4 4 Z M5 5 L5 5");
  ASSERT_EQ(curve.components.size(), 1u);
  EXPECT_EQ(curve.components[0].piece_count(), 1u);
  EXPECT_TRUE(parse_svg_path("M1 2").components.empty());
  EXPECT_TRUE(parse_svg_path("M1 2 Z").components.empty());
}

TEST(SvgPath, ClosesRoundingGapsWithoutATinySegment) {
  // The end misses the start by 1.4e-6 (1e-6 of the size): moved onto the start.
  const Curve snapped_curve = parse_svg_path("M0 0 L1 0 L1 1 L1e-6 1e-6 Z");
  const auto& snapped = snapped_curve.components[0];
  EXPECT_EQ(snapped.piece_count(), 3u);
  EXPECT_EQ(snapped.point(3), Point(0, 0));
  EXPECT_EQ(snapped.corners().size(), 3u);
  // A gap of 1e-2 of the size is a segment of the drawing.
  EXPECT_EQ(parse_svg_path("M0 0 L1 0 L1 1 L0.01 0.01 Z").components[0].piece_count(), 4u);
}

TEST(SvgPath, ControlPointsOnEndPointsGiveRegularPieces) {
  // Inkscape's "c 0,0 ...": B'(0) = 0, yet the piece's tangent there is that of p2 - p0.
  const Curve curve = parse_svg_path("m 0,0 c 0,0 1,1 2,0 c 1,-1 2,0 2,0 Z");
  EXPECT_TRUE(valid_curve(curve));
  const auto& c = curve.components[0];
  EXPECT_GT(norm(c.derivative(0)), 0);
  EXPECT_NEAR(c.unit_tangent(0).x(), std::sqrt(0.5), 1e-15);
}

TEST(SvgPath, CuspsBecomeCorners) {
  const Curve c_curve = parse_svg_path("M0 0 C1 1 0 1 1 0");  // B'(1/2) = 0
  const auto& c = c_curve.components[0];
  EXPECT_EQ(c.piece_count(), 2u);
  EXPECT_EQ(c.corners().size(), 1u);
  EXPECT_TRUE(valid_curve(parse_svg_path("M0 0 C1 1 0 1 1 0")));
}

TEST(SvgPath, MalformedDataIsRejectedWithItsPosition) {
  const std::pair<const char*, std::size_t> bad[] = {
      {"L 0 0", 0},  {"M 0", 3},     {"M 0 0 A 1 1 0 0 0 1 1", 6}, {"M 1e999 0", 2}, {"M0 0 Z 5", 7},
      {"M 0 0 L 1 x", 10}, {"M0 0 Q 1 1", 10}, {"M0 0 L .", 7}, {"M0 0 L 1e", 8}, {"M 1e49 0 l 1e50 0", 11}, {"M 0 0 L 1e-51 0", 8},
      {"M 0 0 L +-1 0", 8}, {"M0 0 L1 1 nan", 10}, {"5 5", 0}};
  for (const auto& [data, position] : bad) {
    try {
      parse_svg_path(data);
      ADD_FAILURE() << "accepted " << data;
    } catch (const Svg_syntax_error& error) {
      EXPECT_EQ(error.position(), position) << data << ": " << error.what();
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    }
  }
}

TEST(SvgPath, ArbitraryTextGivesACurveOrInvalidArgument) {
  const auto parses_or_rejects = [](const std::string& text) {
    try {
      RC_ASSERT(valid_curve(parse_svg_path(text)));
    } catch (const std::invalid_argument&) {
    }
  };
  EXPECT_TRUE(rc::check("any bytes", [&](const std::string& text) { parses_or_rejects(text); }));
  EXPECT_TRUE(rc::check("path-like text", [&] {
    const auto symbol = rc::gen::element<std::string>("M", "m", "L", "l", "H", "h", "V", "v", "C", "c", "S", "s", "Q", "q",
                                                      "T", "t", "Z", "z", " ", ",", "-", ".", "e", "0", "1", "7",
                                                      "1e308", "1e-320", "1e45", "1e-45", "0.5", "-3");
    std::string text;
    for (const auto& s : *rc::gen::container<std::vector<std::string>>(symbol)) text += s;
    parses_or_rejects(text);
  }));
}

TEST(SvgTransform, ParsesEveryKindAndComposesRightToLeft) {
  const auto image = [](std::string_view list, Point p) { return parse_svg_transform(list)(p); };
  const auto near = [](const Point& p, const Point& q) { return norm(p - q) < 1e-12; };
  EXPECT_TRUE(near(image("matrix(1 2 3 4 5 6)", Point(1, 1)), Point(1 + 3 + 5, 2 + 4 + 6)));
  EXPECT_TRUE(near(image("translate(3)", Point(1, 1)), Point(4, 1)));
  EXPECT_TRUE(near(image("translate(3,-1)", Point(1, 1)), Point(4, 0)));
  EXPECT_TRUE(near(image("scale(2)", Point(1, 3)), Point(2, 6)));
  EXPECT_TRUE(near(image("scale(2 -1)", Point(1, 3)), Point(2, -3)));
  EXPECT_TRUE(near(image("rotate(90)", Point(1, 0)), Point(0, 1)));
  EXPECT_TRUE(near(image("rotate(180 1 1)", Point(2, 1)), Point(0, 1)));
  EXPECT_TRUE(near(image("skewX(45)", Point(0, 1)), Point(1, 1)));
  EXPECT_TRUE(near(image("skewY(45)", Point(1, 0)), Point(1, 1)));
  EXPECT_TRUE(near(image("translate(10,5) rotate(90) scale(2)", Point(1, 0)), Point(10, 7)));
  EXPECT_TRUE(near(image(" translate(1 0),scale(2) ", Point(1, 0)), Point(3, 0)));
  EXPECT_TRUE(near(image("", Point(1, 2)), Point(1, 2)));
  for (const char* bad : {"translate(", "scale(1 2 3)", "rotate(1 2)", "shear(1)", "matrix(1 2 3 4 5)", "translate 1"})
    EXPECT_THROW(parse_svg_transform(bad), Svg_syntax_error) << bad;
}

// The bundled drawings and what data/README.md says of them.
std::filesystem::path svg_data(const std::string& name) {
  return std::filesystem::path(CURVEBENCH_SOURCE_DIR) / "data" / "svg" / name;
}

TEST(SvgFile, EveryBundledDrawingLoadsWithOneComponentPerSubpath) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(svg_data(""))) {
    if (entry.path().extension() != ".svg") continue;
    ++files;
    // Independently: each d="..." value, its subpaths counted by their M/m and closures by Z/z
    // (none of these files continues a subpath after Z without M).
    const std::string text = testing::read_bytes(entry.path());
    std::size_t subpaths = 0, closed = 0;
    const std::regex d_attribute(R"(\sd="([^"]*)\")");
    for (auto match = std::sregex_iterator(text.begin(), text.end(), d_attribute); match != std::sregex_iterator(); ++match)
      for (const char c : (*match)[1].str()) subpaths += c == 'M' || c == 'm', closed += c == 'Z' || c == 'z';
    const Curve curve = read_svg_curve(entry.path());
    EXPECT_EQ(curve.name, "svg:" + entry.path().string());
    EXPECT_EQ(curve.components.size(), subpaths) << entry.path();
    EXPECT_EQ(std::size_t(std::count_if(curve.components.begin(), curve.components.end(),
                                        [](const Curve_component& c) { return c.closed(); })),
              closed)
        << entry.path();
    EXPECT_TRUE(valid_curve(curve));
  }
  EXPECT_EQ(files, 19);
  for (const char* name : {"simple.svg", "complex.svg", "blob2.svg", "spiral.svg"}) {
    const Curve curve = read_svg_curve(svg_data(name));
    ASSERT_EQ(curve.components.size(), 1u) << name;
    EXPECT_TRUE(curve.components[0].closed()) << name;
  }
}

TEST(SvgFile, ClosedBundledBlobsAreSmooth) {
  // Their Z gaps are rounding of relative coordinates, and so are their kinks of 1e-8 to
  // 1.1e-5 rad: smooth curves, as the survey samples them.
  for (const char* name : {"simple.svg", "complex.svg", "blob2.svg", "spiral.svg"})
    EXPECT_TRUE(read_svg_curve(svg_data(name)).components[0].corners().empty()) << name;
  // As written, blob2's kinks are joins whose tangent turns by more than 1e-6 rad.
  EXPECT_FALSE(read_svg_curve(svg_data("blob2.svg"), 0).components[0].corners().empty());
  EXPECT_TRUE(read_svg_curve(svg_data("blob2.svg"), 0).components[0].corners(1e-4).empty());
}

// The turn of the unit tangent at each join of a component (its start too if closed).
std::vector<double> join_turns(const Curve_component& c) {
  std::vector<double> turns;
  const std::size_t n = c.piece_count();
  for (std::size_t i = c.closed() ? 0 : 1; i < n; ++i) {
    const Vector a = c.piece((i + n - 1) % n).derivative(1), b = c.piece(i).derivative(0);
    turns.push_back(std::atan2(std::abs(CGAL::determinant(a, b)), a * b));
  }
  return turns;
}

TEST(SvgFile, CornersAreTheJoinsTurningByADegreeOrMoreAsDrawn) {
  // Counted on the curve as written; the default keeps exactly those as corners (Spidy, f2
  // and f6 have corners of 3.4 degrees and more; every other join turns by under 0.1).
  std::size_t all = 0;
  for (const auto& entry : std::filesystem::directory_iterator(svg_data(""))) {
    if (entry.path().extension() != ".svg") continue;
    const Curve drawn = read_svg_curve(entry.path(), 0), smoothed = read_svg_curve(entry.path());
    ASSERT_EQ(drawn.components.size(), smoothed.components.size());
    for (std::size_t c = 0; c < drawn.components.size(); ++c) {
      const std::vector<double> turns = join_turns(drawn.components[c]);
      const auto corners = std::count_if(turns.begin(), turns.end(), [](double t) { return t >= std::numbers::pi / 180; });
      EXPECT_EQ(smoothed.components[c].corners().size(), std::size_t(corners)) << entry.path() << " component " << c;
      all += smoothed.components[c].corners().size();
    }
    EXPECT_TRUE(valid_curve(smoothed));
  }
  EXPECT_EQ(all, 11u);  // the check can fail: Spidy's 7, f2's 3 and f6's 1
}

// The control points of piece i, which must be a cubic.
const std::array<Point, 4>& controls(const Curve& curve, std::size_t i) {
  return dynamic_cast<const Cubic_bezier&>(curve.components[0].piece(i)).control_points();
}

constexpr double one_degree = std::numbers::pi / 180;

TEST(SvgPath, NearSmoothJoinsBecomeExactlySmooth) {
  // Two cubics meeting at (3, 0), tangents (1, -1e-5) in and (1, 1e-5) out: a kink of 2e-5.
  const std::string data = "M0 0 C1 1 2 1e-5 3 0 C4 1e-5 5 -1 6 0";
  const Curve drawn = parse_svg_path(data), smoothed = parse_svg_path(data, {}, one_degree);
  EXPECT_EQ(drawn.components[0].corners().size(), 1u);
  EXPECT_TRUE(smoothed.components[0].corners().empty());
  // Both handles turned onto the bisector (the x axis) about the join, keeping their length.
  const double handle = std::hypot(1, 1e-5);
  EXPECT_EQ(controls(smoothed, 0)[2], Point(3 - handle, 0));
  EXPECT_EQ(controls(smoothed, 1)[1], Point(3 + handle, 0));
  // A handle moves by |h| * 1e-5, the curve by at most 4/9 of that.
  EXPECT_TRUE(same_curve(drawn, smoothed, 4.0 / 9 * handle * 1e-5 * (1 + 1e-9)));
  EXPECT_FALSE(same_curve(drawn, smoothed, 1e-7 * 4.0 / 9 * handle * 1e-5));
}

TEST(SvgPath, ALineSetsTheDirectionOfTheCubicBesideIt) {
  const Curve smoothed = parse_svg_path("M0 0 L3 0 C4 1e-5 5 1 6 0", {}, one_degree);
  EXPECT_TRUE(smoothed.components[0].corners().empty());
  EXPECT_EQ(smoothed.components[0].point(1), Point(3, 0));
  EXPECT_EQ(controls(smoothed, 1)[1], Point(3 + std::hypot(1, 1e-5), 0));
  // Two lines have no handle to turn: their kink stays a corner, as drawn.
  EXPECT_EQ(parse_svg_path("M0 0 L3 0 L6 1e-5", {}, one_degree).components[0].corners().size(), 1u);
  // So does a turn of a degree or more.
  EXPECT_EQ(parse_svg_path("M0 0 C1 1 2 0.1 3 0 C4 0 5 -1 6 0", {}, one_degree).components[0].corners().size(), 1u);
}

TEST(SvgPath, AHandleSettingBothTangentsGoesWhereTheirLinesCross) {
  // The cubic's first control point is on its start, so its second one sets both of its
  // tangents: along the line y = 0 before it and the line y = x - 2 after it.
  const Curve smoothed = parse_svg_path("M0 0 L1 0 C1 0 2 1e-5 3 1 L4 2", {}, one_degree);
  EXPECT_TRUE(smoothed.components[0].corners().empty());
  const Point moved = controls(smoothed, 1)[2];
  EXPECT_NEAR(moved.x(), 2, 1e-12);
  EXPECT_NEAR(moved.y(), 0, 1e-12);
}

TEST(SvgPath, TheClosingJoinIsSmoothedToo) {
  const Curve smoothed = parse_svg_path("M0 0 C1 1e-5 2 2 0 2 C-2 2 -1 1e-5 0 0 Z", {}, one_degree);
  ASSERT_TRUE(smoothed.components[0].closed());
  EXPECT_TRUE(smoothed.components[0].corners().empty());
  EXPECT_EQ(parse_svg_path("M0 0 C1 1e-5 2 2 0 2 C-2 2 -1 1e-5 0 0 Z").components[0].corners(), std::vector<double>{0});
}

TEST(SvgPath, KinksBelowTheCornerAngleAreSmoothAndTheRestCorners) {
  // Closed chains of cubics through points of a circle, each join's handles turned apart by
  // a random kink, some below one degree (0.9 degrees to 1.6e-7 rad) and some above (2 to 20 degrees).
  EXPECT_TRUE(rc::check("corners = joins kinked by a degree or more", [] {
    const int joins = *rc::gen::inRange(2, 7);
    std::vector<Point> at;
    std::vector<Vector> in, out;
    std::size_t kinked = 0;
    double longest = 0;
    for (int j = 0; j < joins; ++j) {
      const double angle = 2 * std::numbers::pi * j / joins;
      const bool corner = *rc::gen::arbitrary<bool>();
      kinked += corner;
      const double kink = corner ? one_degree * (2 + *rc::gen::inRange(0, 1000) * 0.018)
                                 : one_degree * 0.9 * std::pow(10, -5e-3 * *rc::gen::inRange(0, 1001));
      const double direction = angle + std::numbers::pi / 2 + (*rc::gen::inRange(-100, 101)) * 1e-3;
      const double lengths[] = {0.5 + *rc::gen::inRange(0, 150) * 0.01, 0.5 + *rc::gen::inRange(0, 150) * 0.01};
      longest = std::max({longest, lengths[0], lengths[1]});
      at.emplace_back(10 * std::cos(angle), 10 * std::sin(angle));
      in.push_back(lengths[0] * Vector(std::cos(direction - kink / 2), std::sin(direction - kink / 2)));
      out.push_back(lengths[1] * Vector(std::cos(direction + kink / 2), std::sin(direction + kink / 2)));
    }
    char number[64];
    std::string data;
    const auto put = [&](const Point& p) {
      std::snprintf(number, sizeof number, " %.17g %.17g", p.x(), p.y());
      data += number;
    };
    data += "M";
    put(at[0]);
    for (int j = 0; j < joins; ++j) {
      const int next = (j + 1) % joins;
      data += " C";
      put(at[j] + out[j]);
      put(at[next] - in[next]);
      put(at[next]);
    }
    data += " Z";
    const Curve drawn = parse_svg_path(data), smoothed = parse_svg_path(data, {}, one_degree);
    RC_ASSERT(smoothed.components.size() == 1u);
    RC_ASSERT(smoothed.components[0].corners().size() == kinked);
    for (const double turn : join_turns(smoothed.components[0])) RC_ASSERT(turn < 1e-9 || turn > one_degree);
    RC_ASSERT(same_curve(drawn, smoothed, 4.0 / 9 * longest * one_degree));
  }));
}

TEST(SvgFile, AppliesTransformsOfThePathAndItsAncestors) {
  const testing::TemporaryDirectory directory;
  const auto file = directory.write("t.svg", R"svg(<?xml version="1.0"?>
<!-- a <path d="M 9 9 L 8 8"/> in a comment is not read -->
<svg xmlns="http://www.w3.org/2000/svg" xmlns:svg="http://www.w3.org/2000/svg">
  <g transform="translate(10,0)">
    <g transform='scale(2)'>
      <svg:path id="a" d="M 0 0 L 1 0" transform="rotate(90)" />
    </g>
    <path d="M 0 0 L 1 0"></path>
  </g>
  <path
     d="M 0 0 L 1 0"/>
</svg>)svg");
  const Curve curve = read_svg_curve(file);
  ASSERT_EQ(curve.components.size(), 3u);
  EXPECT_LT(norm(curve.components[0].point(1) - Point(10, 2)), 1e-15);
  EXPECT_EQ(curve.components[1].point(1), Point(11, 0));
  EXPECT_EQ(curve.components[2].point(1), Point(1, 0));
}

TEST(SvgFile, ErrorsNameTheFileAndLine) {
  const testing::TemporaryDirectory directory;
  for (const auto& [text, line] : std::vector<std::pair<std::string, std::size_t>>{
           {"<svg>\n<path\n d=\"M 0 0 L 1\"/>\n</svg>", 3},
           {"<svg>\n<g transform=\"scale(\">\n</g></svg>", 2},
           {"<svg>\n\n<path d='M0 0 L 1 1'", 3},
           {"<svg>\n<!-- never closed", 2},
           {"<svg>\n<path d=M0/>", 2}}) {
    const auto file = directory.write("bad.svg", text);
    try {
      read_svg_curve(file);
      ADD_FAILURE() << "accepted " << text;
    } catch (const ParseError& error) {
      EXPECT_EQ(error.file(), file.string());
      EXPECT_EQ(error.line(), line) << error.what();
    }
  }
  EXPECT_THROW(read_svg_curve(directory.path() / "missing.svg"), ParseError);
}

}  // namespace
}  // namespace curvebench::geometry
