#include "geometry/curves/curve_spec.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>

#include "geometry/curves/analytic_curves.h"
#include "geometry/curves/corner_curve.h"
#include "geometry/curves/curve_name.h"
#include "geometry/curves/glyph_curves.h"
#include "geometry/curves/polyline_curve.h"
#include "geometry/curves/star_polygon.h"
#include "geometry/curves/svg_path.h"

namespace curvebench::geometry {
namespace {

// `part` in quotes, control characters shown as '?' so that a message stays on one line.
std::string quoted(std::string_view part) {
  std::string text(part);
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return "'" + text + "'";
}

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument("curve spec: " + message); }

// The key=value list of an analytic kind, checked against the keys it takes.
class Parameters {
 public:
  Parameters(std::string_view kind, std::string_view list, std::initializer_list<std::string_view> keys) : kind_(kind) {
    while (!list.empty()) {
      const std::string_view item = list.substr(0, list.find(','));
      list.remove_prefix(std::min(list.size(), item.size() + 1));
      const auto equals = item.find('=');
      const std::string_view key = item.substr(0, equals);
      if (equals == std::string_view::npos) fail(quoted(item) + " is not key=value");
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        std::string known;
        for (const auto k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
        fail(std::string(kind) + " has no parameter " + quoted(key) + " (it takes " + known + ")");
      }
      if (!values_.emplace(key, item.substr(equals + 1)).second) fail(std::string(kind) + ": " + quoted(key) + " given twice");
    }
  }

  // The value of `key` read as a T (the whole value, finite), or `fallback` if not given.
  template <class T>
  T get(std::string_view key, T fallback) const {
    const auto found = values_.find(key);
    if (found == values_.end()) return fallback;
    const std::string_view text = found->second;
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(double(value)))
      fail(std::string(kind_) + ": " + std::string(key) + "=" + quoted(text) + " is not a finite number of the right kind");
    return value;
  }

 private:
  std::string_view kind_;
  std::map<std::string_view, std::string_view> values_;
};

// One Unicode scalar value, from U+XXXX or from UTF-8 (the shortest form only).
char32_t code_point(std::string_view text) {
  const auto bad = [&] { fail(quoted(text) + " is not one character (UTF-8) or U+XXXX"); };
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  char32_t value = 0;
  if (text.size() > 2 && (text[0] == 'U' || text[0] == 'u') && text[1] == '+') {
    std::uint32_t hex = 0;
    const auto [end, error] = std::from_chars(text.data() + 2, text.data() + text.size(), hex, 16);
    if (error != std::errc() || end != text.data() + text.size()) bad();
    value = hex;
  } else {
    const unsigned char lead = text.empty() ? 0x80 : byte(0);
    const std::size_t length = lead < 0x80 ? 1 : lead < 0xC0 ? 0 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : lead < 0xF8 ? 4 : 0;
    if (length == 0 || text.size() != length) bad();
    value = length == 1 ? lead : lead & (0x7F >> length);
    for (std::size_t i = 1; i < length; ++i) {
      if ((byte(i) & 0xC0) != 0x80) bad();
      value = value << 6 | (byte(i) & 0x3F);
    }
    constexpr char32_t shortest[] = {0, 0, 0x80, 0x800, 0x10000};  // smaller values are overlong
    if (value < shortest[length]) bad();
  }
  if ((value >= 0xD800 && value < 0xE000) || value > 0x10FFFF) bad();  // surrogates, beyond Unicode
  return value;
}

// "A:B" split at its last ':' (A empty if there is none).
std::pair<std::string_view, std::string_view> split_last(std::string_view text) {
  const auto colon = text.rfind(':');
  if (colon == std::string_view::npos) return {{}, text};
  return {text.substr(0, colon), text.substr(colon + 1)};
}

}  // namespace

std::pair<std::string_view, std::string_view> split_svg_options(std::string_view rest) {
  const auto comma = rest.rfind(',');
  if (comma == std::string_view::npos || rest.substr(comma + 1).find('=') == std::string_view::npos) return {rest, {}};
  return {rest.substr(0, comma), rest.substr(comma)};
}

Curve make_curve(std::string_view spec) {
  const auto colon = spec.find(':');
  const std::string_view kind = spec.substr(0, colon), rest = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  if (kind == "circle") return circle(Parameters(kind, rest, {"r"}).get("r", 1.0));
  if (kind == "ellipse") {
    const Parameters p(kind, rest, {"a", "b"});
    return ellipse(p.get("a", 2.0), p.get("b", 1.0));
  }
  if (kind == "superellipse") {
    const Parameters p(kind, rest, {"a", "b", "n"});
    return superellipse(p.get("a", 1.0), p.get("b", 1.0), p.get("n", 4.0));
  }
  if (kind == "fourier") {
    const Parameters p(kind, rest, {"seed", "harmonics", "amplitude", "decay", "components", "separation", "gap"});
    const Fourier_curve_parameters defaults;
    const Fourier_curve_parameters parameters{p.get("harmonics", defaults.harmonics),
                                              p.get("amplitude", defaults.amplitude), p.get("decay", defaults.decay)};
    const auto seed = p.get<std::uint64_t>("seed", 0);
    const double gap = p.get("gap", 0.0);
    if (gap == 0) return random_fourier_curves(seed, parameters, p.get("components", 1), p.get("separation", component_gap));
    if (p.get("components", 1) != 1 || p.get("separation", component_gap) != component_gap)
      fail("fourier: a gap opens one curve; it takes no components or separation");
    return random_fourier_arc(seed, parameters, gap);
  }
  if (kind == "nested") {
    const Parameters p(kind, rest, {"seed", "separation"});
    return nested_fourier_curves(p.get<std::uint64_t>("seed", 0), p.get("separation", 0.1));
  }
  if (kind == "spiral") return random_spiral(Parameters(kind, rest, {"seed"}).get<std::uint64_t>("seed", 0));
  if (kind == "lissajous") {
    const Parameters p(kind, rest, {"a", "b", "seed"});
    return lissajous_curve(p.get("a", 1), p.get("b", 2), p.get<std::uint64_t>("seed", 0));
  }
  if (kind == "corner") return sharp_corner_curve(Parameters(kind, rest, {"angle"}).get("angle", 30.0));
  if (kind == "star") {
    const Parameters p(kind, rest, {"seed", "angle", "rounding"});
    return star_polygon(p.get<std::uint64_t>("seed", 0), p.get("angle", 60.0), p.get("rounding", 0.0));
  }
  if (kind == "svg") {
    const auto [file, options] = split_svg_options(rest);
    if (file.empty()) fail("svg needs a file: svg:FILE[,corner=DEGREES]");
    const double corner =
        Parameters(kind, options.empty() ? options : options.substr(1), {"corner"}).get("corner", default_svg_corner_degrees);
    return read_svg_curve(file, corner);  // which checks the angle before reading the file
  }
  if (kind == "glyph") {
    const auto [font, character] = split_last(rest);
    return glyph_curve(font.empty() ? default_glyph_font : std::filesystem::path(font), code_point(character));
  }
  if (kind == "truth") {
    const auto [points, edges] = split_last(rest);
    if (points.empty() || edges.empty()) fail("truth needs two files: truth:POINTFILE:EDGEFILE");
    return polyline_curve(read_ground_truth(points, edges), std::string(spec));
  }
  fail("unknown kind " + quoted(kind) +
       " (circle, ellipse, superellipse, fourier, nested, spiral, lissajous, corner, star, svg, glyph, truth)");
}

std::vector<std::string> expand_curve_specs(std::string_view spec) {
  if (!spec.starts_with("glyph:") || split_last(spec.substr(6)).second != "*") return {std::string(spec)};
  const std::string_view font = split_last(spec.substr(6)).first;
  std::vector<std::string> specs;
  for (const char32_t c : glyph_code_points(font.empty() ? default_glyph_font : std::filesystem::path(font)))
    specs.push_back(std::string(spec.substr(0, spec.size() - 1)) + format_code_point(c));
  return specs;
}

}  // namespace curvebench::geometry
