// Font glyph outlines as curves: thousands of real closed curves with holes (several
// components), sharp corners and features at many scales, each an exact union of lines
// and Bézier pieces, for benchmarks in the spirit of the survey's Classic/Image sets with
// exact ground truth (survey, "Data Sets and Associated Ground Truth").
#pragma once

#include <filesystem>
#include <vector>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// The font of a glyph spec that names none: DejaVu Sans where Debian and Ubuntu install it.
inline const std::filesystem::path default_glyph_font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The outline of the glyph of `code_point`, read by FreeType (FT_Outline_Decompose) in font
// units and scaled so that the em square has size 1: each contour a closed component of
// lines and cubic Béziers (TrueType conics elevated), in the font's orientation (outer
// contours clockwise in TrueType). Zero-length pieces and contours of fewer than two
// distinct points are dropped (path_builder.h), so a glyph without outline, like the
// space, has no component. Named "glyph:FONT:C" (C as in format_code_point()).
// Throws ParseError (line 0) if FreeType cannot open the font, std::invalid_argument if
// the font maps no glyph to the code point.
Curve glyph_curve(const std::filesystem::path& font, char32_t code_point);

// The code points the font maps to a glyph whose curve has at least one component, ascending.
std::vector<char32_t> glyph_code_points(const std::filesystem::path& font = default_glyph_font);

}  // namespace curvebench::geometry
