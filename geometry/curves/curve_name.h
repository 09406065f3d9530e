// The name a generated curve carries (Curve::name): the curve_spec.h string that makes the
// same curve again, e.g. "ellipse:a=2,b=1". Numbers are written in their shortest form
// that reads back to the same double, so a name is an exact recipe.
#pragma once

#include <charconv>
#include <cstdio>
#include <string>

namespace curvebench::geometry {

// x in the shortest form that reads back to the same double (std::to_chars, independent
// of the locale), e.g. "0.1", "2", "1e-05".
inline std::string format_number(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

// A character in a glyph name: itself if it is printable ASCII other than ':' (the spec's
// separator) and '|' (the benchmark input name's, bench/runner/bench_input.h: "glyph:||epsilon=0.4"
// read as an empty glyph), otherwise U+XXXX (at least four hex digits).
inline std::string format_code_point(char32_t code_point) {
  if (code_point > ' ' && code_point < 0x7f && code_point != ':' && code_point != '|')
    return std::string(1, char(code_point));
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", unsigned(code_point));
  return buffer;
}

}  // namespace curvebench::geometry
