// Curves drawn in SVG: the survey's benchmark data (stefango74/sampling2d, data/svg/) are
// Inkscape drawings of cubic Bézier paths, from which the survey's sampling tool ("Sampling
// Tools") draws epsilon-samplings with exact ground truth.
//
// Path data (the `d` attribute) supports M m L l H h V v C c S s Q q T t Z z with implicit
// repetition, numbers like "1e-3" or "-.5.5" (two numbers) and optional commas and white
// space. Each subpath becomes one component, closed iff it ends with Z; quadratic Béziers
// are elevated to cubic (cubic_bezier.h). Zero-length segments are dropped, and so is a
// subpath left without any segment (a lone point). Z closes a subpath whose end misses its
// start by at most 1e-4 of its size (rounded relative coordinates) by moving the end onto
// the start, not by a tiny segment with two spurious corners. Arcs (A a) are not supported.
//
// Corners: a join of two pieces is a corner of the curve (lfs 0 there, a sample on it, a
// corner of the ground truth) if its tangent turns by at least the corner angle, by
// default 1 degree. Below that the join is taken as the smooth node the drawing meant, and
// made exactly G1 by turning its Bézier handles (path_builder.h): the curve sampled and
// measured is then smooth there, within (4/9) |handle| * angle of the file's. Why 1
// degree: the 19 files of data/svg/ have joins turning by 1e-9 to 1.7e-3 rad (0.1
// degree: Inkscape's rounding of smooth nodes) and 11 corners of 3.4 degrees and more
// (Spidy, f2, f6), nothing in between. The survey's sampling tool has no notion of a
// corner: its lfs, from 1000 points per Bézier, does not see kinks that small. Corner
// angle 0 keeps every join as written (curve spec svg:FILE,corner=0).
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// An affine map of the plane (CGAL), as an SVG `transform` attribute gives one; the
// default-constructed one is the identity.
using Affine_transformation = Kernel::Aff_transformation_2;

// Malformed path data or transform list: the message starts "character N:" (0-based).
class Svg_syntax_error : public std::invalid_argument {
 public:
  // what() is "character POSITION: MESSAGE".
  Svg_syntax_error(std::size_t position, const std::string& message)
      : std::invalid_argument("character " + std::to_string(position) + ": " + message), position_(position) {}
  // The 0-based index, in the path data or transform list, of the character at fault.
  std::size_t position() const noexcept { return position_; }

 private:
  std::size_t position_;
};

// The curve of the path data, its control points mapped by `transform`. Throws
// Svg_syntax_error for anything outside the grammar, for numbers outside the double
// range, and for coordinates (after relative offsets and the transform) that are neither 0
// nor of a magnitude in [1e-50, 1e50], where products of squared distances would overflow
// or underflow.
// Joins turning by less than `corner_angle` radians are made smooth; 0 keeps them as written.
Curve parse_svg_path(std::string_view data, const Affine_transformation& transform = {}, double corner_angle = 0);

// An SVG transform list ("matrix(a b c d e f) translate(x [y]) scale(x [y]) rotate(a [x y])
// skewX(a) skewY(a)", applied right to left). Throws Svg_syntax_error.
Affine_transformation parse_svg_transform(std::string_view list);

// Joins of SVG drawings turning by less than this many degrees are smooth (see above).
inline constexpr double default_svg_corner_degrees = 1;

// Every `<path d="...">` of an SVG file (those in `<defs>` included), in document order, each
// mapped by the `transform` attributes of the path and its ancestors; units and viewBox
// are ignored (the curve is in user units); joins turning by less than `corner_degrees`
// are made smooth. Named "svg:" + file, with ",corner=DEGREES" unless the default. Throws
// std::invalid_argument for an angle outside [0, 180]. There is no XML library
// on the build machines, so a small tag scanner reads the file: comments, processing
// instructions, CDATA and DOCTYPE are skipped, character entities are not decoded.
// Throws ParseError naming the file and line of a malformed tag, path or transform.
Curve read_svg_curve(const std::filesystem::path& file, double corner_degrees = default_svg_corner_degrees);

}  // namespace curvebench::geometry
