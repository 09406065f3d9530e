// Curves named on the command line: one string per curve source, so that experiments,
// the certifier and the CLI can say which ground truth they ran on, and Curve::name of a
// generated curve is a spec that makes it again.
//
//   circle[:r=R]                                   default r=1
//   ellipse[:a=A,b=B]                              default a=2,b=1
//   superellipse[:a=A,b=B,n=N]                     default a=1,b=1,n=4
//   fourier[:seed=S,harmonics=H,amplitude=A,decay=D,components=K,separation=D]
//                                                  default seed=0, components=1,
//                                                  separation=1.5, the rest as in
//                                                  Fourier_curve_parameters
//   fourier:...,gap=G                              the same curve opened by a gap (0 < G < 1)
//   nested[:seed=S,separation=D]                   a Fourier curve inside another; D=0.1
//   spiral[:seed=S]                                an open spiral
//   lissajous[:a=A,b=B,seed=S]                     crossing itself 2ab-a-b times; a=1,b=2
//   corner[:angle=DEGREES]                         default angle=30
//   star[:seed=S,angle=DEGREES,rounding=R]         a star polygon; angle=60, rounding=0
//   svg:FILE[,corner=DEGREES]                      every path of an SVG file; joins turning
//                                                  by less than DEGREES are smooth (svg_path.h);
//                                                  default 1, 0 keeps every join as written
//   glyph:[FONTFILE:]CHAR                          CHAR: one UTF-8 character or U+XXXX
//                                                  (':' must be U+003A); default font DejaVu Sans
//   truth:POINTFILE:EDGEFILE                       a ground truth (polyline_curve.h)
//
// Parameters are key=value pairs separated by commas, in any order, each at most once.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// The rest of an svg:FILE[,corner=DEGREES] spec split into FILE and its options (",corner=..."
// or empty): a file name may hold commas, so only a last item with '=' is an option.
std::pair<std::string_view, std::string_view> split_svg_options(std::string_view rest);

// Throws std::invalid_argument with a one-line message naming the malformed part (unknown
// kind or key, bad number, missing file name, invalid character); errors of the curve
// sources themselves pass through (std::invalid_argument, or ParseError for a file).
Curve make_curve(std::string_view spec);

// The specs that `spec` stands for: glyph:[FONTFILE:]* gives one spec per character of the
// font with an outline (glyph_code_points), ascending; any other spec is itself.
std::vector<std::string> expand_curve_specs(std::string_view spec);

}  // namespace curvebench::geometry
