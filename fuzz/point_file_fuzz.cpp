// libFuzzer target for geometry/io/point_io.h: parse_point_file must turn any bytes into
// points or a ParseError, under both naming rules (".xy": the format is guessed from the
// first data line; ".node": a Triangle header is required), without a crash, undefined
// behaviour, another exception or an allocation larger than the text calls for. What it
// accepts must be consistent and survive write_points and a second parse bit for bit, and a
// UTF-8 byte-order mark in front of the bytes must change nothing.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/fuzz_target.h"
#include "geometry/io/point_io.h"

namespace curvebench::fuzz {
namespace {

using geometry::Point;

bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

bool bit_identical(const Point& p, const Point& q) {
  return std::bit_cast<std::uint64_t>(p.x()) == std::bit_cast<std::uint64_t>(q.x()) &&
         std::bit_cast<std::uint64_t>(p.y()) == std::bit_cast<std::uint64_t>(q.y());
}

bool bit_identical(const std::vector<Point>& p, const std::vector<Point>& q) {
  return std::equal(p.begin(), p.end(), q.begin(), q.end(), [](const Point& a, const Point& b) { return bit_identical(a, b); });
}

std::optional<geometry::PointFile> parsed(std::string_view text, std::string_view name) {
  try {
    return geometry::parse_point_file(text, name);
  } catch (const geometry::ParseError&) {
    return std::nullopt;  // rejecting malformed bytes with a message is the reader's job
  }
}

void check_point_file(std::string_view text, std::string_view name) {
  const auto result = parsed(text, name);
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (!text.starts_with(kByteOrderMark)) {
    const auto marked = parsed(std::string(kByteOrderMark) + std::string(text), name);
    FUZZ_CHECK(marked.has_value() == result.has_value() && (!result || bit_identical(result->points, marked->points)),
               "a byte-order mark in front changes nothing");
  }
  if (!result) return;
  const geometry::PointFile& file = *result;
  const auto& points = file.points;
  FUZZ_CHECK(file.lines.size() == points.size(), "every point has its source line");
  FUZZ_CHECK(std::adjacent_find(file.lines.begin(), file.lines.end(), std::greater_equal<>()) == file.lines.end() &&
                 (file.lines.empty() || file.lines.front() >= 1),
             "points come from distinct 1-based lines, in order");
  FUZZ_CHECK(file.values.empty() || file.values.size() == points.size(), "a third column on every line or none");
  FUZZ_CHECK(std::all_of(points.begin(), points.end(), finite), "only finite coordinates are accepted");

  std::ostringstream written;
  geometry::write_points(written, points);
  const auto again = geometry::parse_point_file(written.str(), "written.xy").points;
  FUZZ_CHECK(bit_identical(points, again),
             "write_points then parse_point_file gives the same points bit for bit");
}

}  // namespace
}  // namespace curvebench::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const std::string_view name : {"fuzz.xy", "fuzz.node"}) curvebench::fuzz::check_point_file(text, name);
  return 0;
}
