// libFuzzer target for geometry/curves/svg_path.h: parse_svg_path must turn any bytes into a
// curve or an Svg_syntax_error (std::invalid_argument naming a position inside the text),
// without a crash, undefined behaviour or any other exception; in particular the curve
// model's own std::invalid_argument (pieces that do not join) would be a finding. What it
// accepts must be a valid curve: regular pieces, finite lengths, finite polylines, both as
// written and with the joins that turn by less than a degree made smooth (the default of
// SVG files), which must leave the same components, closed or open alike. The
// transform-list parser gets the same bytes under the same rule.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz/fuzz_target.h"
#include "geometry/curves/svg_path.h"

namespace curvebench::fuzz {
namespace {

using geometry::Point;
using geometry::Vector;

bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }
bool regular(const Vector& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && (v.x() != 0 || v.y() != 0); }

void check_component(const geometry::Curve_component& component) {
  FUZZ_CHECK(component.piece_count() > 0, "a component has a piece");
  double magnitude = 0;
  for (std::size_t i = 0; i < component.piece_count(); ++i) {
    const auto& piece = component.piece(i);
    for (const double t : {0.0, 0.5, 1.0}) {
      FUZZ_CHECK(finite(piece.point(t)), "pieces have finite points");
      FUZZ_CHECK(regular(piece.derivative(t)), "pieces are regular: finite non-zero derivative",
                 "piece " + std::to_string(i) + " at t = " + std::to_string(t) + "\n");
      magnitude = std::max({magnitude, std::abs(piece.point(t).x()), std::abs(piece.point(t).y())});
    }
  }
  const double length = component.length();
  FUZZ_CHECK(std::isfinite(length) && length > 0, "a component has a finite positive length");
  // Chords within 1e-3 of the length, but not below the rounding noise of the coordinates.
  for (const Point& p : component.polyline(std::max(1e-3 * length, 1e-10 * magnitude)))
    FUZZ_CHECK(finite(p), "polylines have finite points");
}

}  // namespace
}  // namespace curvebench::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvebench;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const geometry::Curve drawn = geometry::parse_svg_path(text);
    const geometry::Curve smoothed = geometry::parse_svg_path(text, {}, geometry::default_svg_corner_degrees * M_PI / 180);
    for (const auto& component : drawn.components) fuzz::check_component(component);
    for (const auto& component : smoothed.components) fuzz::check_component(component);
    FUZZ_CHECK(drawn.components.size() == smoothed.components.size(), "smoothing keeps the components");
    for (std::size_t c = 0; c < drawn.components.size(); ++c)
      FUZZ_CHECK(drawn.components[c].closed() == smoothed.components[c].closed(), "smoothing keeps closed components closed");
  } catch (const geometry::Svg_syntax_error& error) {
    FUZZ_CHECK(error.position() <= size, "an error points inside the text or at its end");
  }
  try {
    geometry::parse_svg_transform(text);
  } catch (const geometry::Svg_syntax_error& error) {
    FUZZ_CHECK(error.position() <= size, "an error points inside the text or at its end");
  }
  return 0;
}
