#include "geometry/curves/glyph_curves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <stdexcept>

#include "geometry/io/parse_error.h"
#include "tests/support/curve_checks.h"

namespace curvebench::geometry {
namespace {

std::size_t components(char32_t c) { return glyph_curve(default_glyph_font, c).components.size(); }

TEST(GlyphCurves, LettersHaveTheirContours) {
  EXPECT_EQ(components(U'O'), 2u);
  EXPECT_EQ(components(U'B'), 3u);
  EXPECT_EQ(components(U'i'), 2u);
  EXPECT_EQ(components(U'l'), 1u);
  EXPECT_EQ(components(U'8'), 3u);
  EXPECT_EQ(components(U' '), 0u);
  const Curve l = glyph_curve(default_glyph_font, U'l');
  EXPECT_EQ(l.name, "glyph:" + default_glyph_font.string() + ":l");
  EXPECT_TRUE(l.components[0].closed());
  EXPECT_EQ(l.components[0].corners().size(), 4u);  // a rectangle of lines
  // Outlines in integer font units turn by up to about 1° where conics join: "corners"
  // of the exact outline, but not visible ones.
  const Curve o = glyph_curve(default_glyph_font, U'O');
  for (const auto& contour : o.components) {
    EXPECT_FALSE(contour.corners().empty());
    EXPECT_TRUE(contour.corners(2 * std::numbers::pi / 180).empty());
  }
  EXPECT_EQ(glyph_curve(default_glyph_font, U'é').name, "glyph:" + default_glyph_font.string() + ":U+00E9");
}

TEST(GlyphCurves, AreScaledToTheEm) {
  // DejaVu Sans: units_per_EM 2048, 'l' spans the ascender 1556 from the baseline 0.
  const auto box = glyph_curve(default_glyph_font, U'l').bounding_box(1e-4);
  EXPECT_NEAR(box.ymin(), 0, 1e-12);
  EXPECT_NEAR(box.ymax(), 1556.0 / 2048, 1e-12);
}

TEST(GlyphCurves, EveryGlyphOfDejaVuSansIsAValidCurve) {
  const auto code_points = glyph_code_points();
  std::cout << "DejaVuSans.ttf: " << code_points.size() << " code points with an outline\n";
  ::testing::Test::RecordProperty("glyphs", int(code_points.size()));
  EXPECT_GT(code_points.size(), 5000u);
  EXPECT_TRUE(std::is_sorted(code_points.begin(), code_points.end()));
  EXPECT_TRUE(std::binary_search(code_points.begin(), code_points.end(), U'A'));
  EXPECT_FALSE(std::binary_search(code_points.begin(), code_points.end(), U' '));
  std::size_t contours = 0;
  for (const char32_t c : code_points) {
    const Curve curve = glyph_curve(default_glyph_font, c);
    ASSERT_FALSE(curve.components.empty()) << std::hex << unsigned(c);
    ASSERT_TRUE(testing::valid_curve(curve)) << std::hex << unsigned(c);
    for (const auto& component : curve.components) ASSERT_TRUE(component.closed()) << std::hex << unsigned(c);
    contours += curve.components.size();
    const auto box = curve.bounding_box(1e-3);
    ASSERT_TRUE(box.xmin() > -2 && box.xmax() < 3 && box.ymin() > -2 && box.ymax() < 3) << std::hex << unsigned(c) << " " << box;
  }
  std::cout << contours << " contours\n";
}

TEST(GlyphCurves, MissingCharacterOrFontIsAnError) {
  EXPECT_THROW(glyph_curve(default_glyph_font, U'\U0010FFFD'), std::invalid_argument);
  EXPECT_THROW(glyph_curve("/nonexistent/font.ttf", U'A'), ParseError);
  EXPECT_THROW(glyph_code_points(CURVEBENCH_SOURCE_DIR "/data/README.md"), ParseError);
}

}  // namespace
}  // namespace curvebench::geometry
