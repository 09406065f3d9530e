#include "geometry/curves/curve_spec.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/glyph_curves.h"
#include "geometry/io/parse_error.h"
#include "tests/support/temporary_directory.h"
#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

TEST(CurveSpec, MakesEveryKindWithDefaults) {
  EXPECT_EQ(make_curve("circle").name, "circle:r=1");
  EXPECT_EQ(make_curve("circle:r=2.5").name, "circle:r=2.5");
  EXPECT_EQ(make_curve("ellipse").name, "ellipse:a=2,b=1");
  EXPECT_EQ(make_curve("ellipse:b=0.5").name, "ellipse:a=2,b=0.5");
  EXPECT_EQ(make_curve("superellipse").name, "superellipse:a=1,b=1,n=4");
  EXPECT_EQ(make_curve("superellipse:n=2.5,a=3").name, "superellipse:a=3,b=1,n=2.5");
  EXPECT_EQ(make_curve("fourier:seed=7").name, "fourier:seed=7,harmonics=5,amplitude=0.4,decay=2");
  EXPECT_EQ(make_curve("fourier").name, "fourier:seed=0,harmonics=5,amplitude=0.4,decay=2");
  EXPECT_EQ(make_curve("fourier:seed=18446744073709551615,harmonics=3").name,
            "fourier:seed=18446744073709551615,harmonics=3,amplitude=0.4,decay=2");
  EXPECT_EQ(make_curve("corner").name, "corner:angle=30");
  EXPECT_EQ(make_curve("corner:angle=45").components[0].corners().size(), 1u);
  const std::string blob = CURVEBENCH_SOURCE_DIR "/data/svg/blob2.svg";
  EXPECT_EQ(make_curve("svg:" + blob).components.size(), 1u);
  // Rounding kinks are smooth by default (svg_path.h); corner=0 keeps the joins as written.
  EXPECT_TRUE(make_curve("svg:" + blob).components[0].corners().empty());
  EXPECT_EQ(make_curve("svg:" + blob + ",corner=0").components[0].corners().size(), 6u);
  EXPECT_EQ(make_curve("svg:" + blob + ",corner=0").name, "svg:" + blob + ",corner=0");
  EXPECT_EQ(make_curve("svg:" + blob + ",corner=1").name, "svg:" + blob);
  EXPECT_EQ(make_curve("glyph:O").components.size(), 2u);
  EXPECT_EQ(make_curve("glyph:" + default_glyph_font.string() + ":B").components.size(), 3u);
  EXPECT_EQ(make_curve("glyph:U+0069").components.size(), 2u);
  EXPECT_EQ(make_curve("glyph:u+69").name, make_curve("glyph:i").name);
  EXPECT_EQ(make_curve("glyph:é").name, make_curve("glyph:U+00E9").name);
  EXPECT_EQ(make_curve("glyph:€").name, "glyph:" + default_glyph_font.string() + ":U+20AC");
}

TEST(CurveSpec, NamesAreSpecsOfTheSameCurve) {
  for (const char* spec : {"circle:r=0.1", "ellipse:a=3,b=0.25", "superellipse:a=1,b=2,n=0.5", "fourier:seed=3,amplitude=0.9", "fourier:seed=4,components=3",
                           "corner:angle=12.5", "glyph:g", "glyph:U+00E9"}) {
    const Curve curve = make_curve(spec), again = make_curve(curve.name);
    EXPECT_EQ(again.name, curve.name);
    EXPECT_EQ(again.length(), curve.length()) << spec;
  }
  for (const char* option : {"", ",corner=0", ",corner=2.5"}) {
    const Curve curve = make_curve(std::string("svg:" CURVEBENCH_SOURCE_DIR "/data/svg/Spidy.svg") + option);
    const Curve again = make_curve(curve.name);
    EXPECT_EQ(again.name, curve.name);
    EXPECT_EQ(again.length(), curve.length()) << option;
  }
}

// Component c of `fourier:seed=S,components=K` is fourier:seed=S+c moved along x, and the
// components keep component_gap between their bounding boxes.
TEST(CurveSpec, FourierComponentsAreTheSingleCurvesInARow) {
  const Curve row = make_curve("fourier:seed=11,harmonics=4,components=3");
  ASSERT_EQ(row.components.size(), 3u);
  EXPECT_EQ(make_curve("fourier:seed=11,harmonics=4,components=1").name, make_curve("fourier:seed=11,harmonics=4").name);
  double previous_right = -INFINITY;
  for (std::size_t c = 0; c < 3; ++c) {
    const Curve single = make_curve("fourier:seed=" + std::to_string(11 + c) + ",harmonics=4");
    const Curve_component &moved = row.components[c], &original = single.components.front();
    const Vector offset = moved.point(0) - original.point(0);
    EXPECT_EQ(offset.y(), 0);
    for (const double s : {0.1, 0.37, 0.8}) {
      EXPECT_NEAR(moved.point(s).x() - original.point(s).x(), offset.x(), 1e-12);
      EXPECT_NEAR(moved.point(s).y(), original.point(s).y(), 1e-12);
    }
    double left = INFINITY, right = -INFINITY;
    for (int i = 0; i < 1000; ++i) {
      left = std::min(left, moved.point(i / 1000.0).x());
      right = std::max(right, moved.point(i / 1000.0).x());
    }
    EXPECT_GE(left - previous_right, component_gap - 1e-3) << c;
    previous_right = right;
  }
  EXPECT_THROW(make_curve("fourier:components=0"), std::invalid_argument);
}

TEST(CurveSpec, ReadsAGroundTruth) {
  const testing::TemporaryDirectory directory;
  const auto points = directory.write("square.xy", "0 0\n1 0\n1 1\n0 1\n");
  const auto edges = directory.write("square.edges", "0 1\n1 2\n2 3\n3 0\n");
  const Curve curve = make_curve("truth:" + points.string() + ":" + edges.string());
  ASSERT_EQ(curve.components.size(), 1u);
  EXPECT_TRUE(curve.components[0].closed());
  EXPECT_DOUBLE_EQ(curve.length(), 4);
}

TEST(CurveSpec, MalformedSpecsNameTheBadPart) {
  const std::pair<const char*, const char*> bad[] = {
      {"", "''"},
      {"square", "'square'"},
      {"circle:r", "'r'"},
      {"circle:radius=1", "'radius'"},
      {"circle:r=abc", "'abc'"},
      {"circle:r=1x", "'1x'"},
      {"circle:r=1,r=2", "'r'"},
      {"circle:r=inf", "'inf'"},
      {"circle:r=-1", "-1"},
      {"ellipse:a=1,,b=2", "''"},
      {"fourier:seed=-3", "'-3'"},
      {"fourier:harmonics=2.5", "'2.5'"},
      {"corner:angle=0", "angle"},
      {"svg", "svg:FILE"},
      {"svg:", "svg:FILE"},
      {"svg:,corner=1", "svg:FILE"},
      {"svg:a.svg,corner=-1", "[0, 180]"},
      {"svg:a.svg,corner=181", "[0, 180]"},
      {"svg:a.svg,corner=x", "'x'"},
      {"svg:a.svg,sharp=1", "'sharp'"},
      {"glyph:", "''"},
      {"glyph:ab", "'ab'"},
      {"glyph:U+110000", "'U+110000'"},
      {"glyph:U+D800", "'U+D800'"},
      {"glyph:U+", "'U+'"},
      {"glyph:\xC3", "is not one character"},           // truncated UTF-8
      {"glyph:\xC0\x81", "is not one character"},        // overlong
      {"glyph:\xED\xA0\x80", "is not one character"},   // a surrogate
      {"circle:r=1\n2", "'1?2'"},
      {"truth:onlyone", "truth:POINTFILE:EDGEFILE"},
  };
  for (const auto& [spec, mention] : bad) {
    try {
      make_curve(spec);
      ADD_FAILURE() << "accepted " << spec;
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(mention), std::string::npos) << spec << " -> " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  EXPECT_THROW(make_curve("svg:/nonexistent.svg"), ParseError);
}

TEST(CurveSpec, ArbitrarySpecsGiveACurveOrAnError) {
  EXPECT_TRUE(rc::check("no crash, only std::invalid_argument or ParseError", [] {
    const std::string kind = *rc::gen::element<std::string>("circle:", "ellipse:", "superellipse:", "corner:", "fourier:", "glyph:", "");
    const std::string spec = kind + *rc::gen::arbitrary<std::string>();
    try {
      RC_ASSERT(testing::valid_curve(make_curve(spec)));
    } catch (const std::invalid_argument&) {
    } catch (const ParseError&) {
    }
  }));
}

TEST(CurveSpec, GlyphStarExpandsToEveryGlyph) {
  const auto specs = expand_curve_specs("glyph:*");
  EXPECT_EQ(specs.size(), glyph_code_points().size());
  EXPECT_NE(std::find(specs.begin(), specs.end(), "glyph:A"), specs.end());
  EXPECT_NE(std::find(specs.begin(), specs.end(), "glyph:U+003A"), specs.end());  // ':' itself
  EXPECT_EQ(make_curve("glyph:U+003A").components.size(), 2u);
  // '|' is the benchmark input name's separator ("glyph:||epsilon=0.4" named an empty glyph
  // and failed for every algorithm in the full glyph sweep): no expanded name holds one.
  EXPECT_NE(std::find(specs.begin(), specs.end(), "glyph:U+007C"), specs.end());
  EXPECT_TRUE(std::none_of(specs.begin(), specs.end(), [](const std::string& spec) { return spec.find('|') != std::string::npos; }));
  EXPECT_EQ(make_curve("glyph:U+007C").components.size(), 1u);
  const std::string font = default_glyph_font.string();
  EXPECT_EQ(expand_curve_specs("glyph:" + font + ":*").size(), specs.size());
  EXPECT_EQ(expand_curve_specs("glyph:" + font + ":*")[0].rfind("glyph:" + font + ":", 0), 0u);
  EXPECT_EQ(expand_curve_specs("circle:r=2"), std::vector<std::string>{"circle:r=2"});
  EXPECT_EQ(expand_curve_specs("glyph:A"), std::vector<std::string>{"glyph:A"});
}

}  // namespace
}  // namespace curvebench::geometry
