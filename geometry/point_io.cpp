#include "geometry/point_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "geometry/text_file.h"
#include "geometry/text_records.h"

namespace curvebench::geometry {
namespace {

bool is_digits(std::string_view field) {
  return !field.empty() && std::ranges::all_of(field, [](char c) { return c >= '0' && c <= '9'; });
}

bool has_triangle_extension(std::string_view name) {
  std::string extension = std::filesystem::path(name).extension().string();
  std::ranges::transform(extension, extension.begin(),
                         [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".node" || extension == ".gtn";
}

bool looks_like_triangle_header(const Record& record) {
  return record.fields.size() == 4 && std::ranges::all_of(record.fields, is_digits);
}

void add_point(const RecordReader& reader, std::size_t line, std::string_view x, std::string_view y,
               PointFile& file) {
  const double x_value = reader.to_real(x, line);  // before y, so errors read left to right
  file.points.emplace_back(x_value, reader.to_real(y, line));
  file.lines.push_back(line);
}

void require_finite(std::span<const Point> points) {
  const auto not_finite = std::ranges::find_if(
      points, [](const Point& p) { return !std::isfinite(p.x()) || !std::isfinite(p.y()); });
  if (not_finite != points.end()) {
    throw std::invalid_argument("write_points: point " +
                                std::to_string(not_finite - points.begin()) +
                                " has a non-finite coordinate");
  }
}

// `record` holds the first data line on entry.
void read_plain(RecordReader& reader, Record& record, PointFile& file) {
  const std::size_t first_line = record.line;
  std::optional<std::size_t> announced;
  bool more = true;
  if (record.fields.size() == 1 && is_digits(record.fields[0])) {
    announced = reader.to_index(record.fields[0], record.line);
    more = reader.next(record);
  }
  std::size_t columns = 0;
  std::size_t columns_line = 0;
  for (; more; more = reader.next(record)) {
    const std::size_t found = record.fields.size();
    if (columns == 0) {
      if (found != 2 && found != 3) {
        reader.fail(record.line, "expected 2 or 3 columns (x y [value]), found " +
                                     std::to_string(found) + ": " + quoted(record.text));
      }
      columns = found;
      columns_line = record.line;
    } else if (found != columns) {
      reader.fail(record.line, "expected " + std::to_string(columns) + " columns as on line " +
                                   std::to_string(columns_line) + ", found " +
                                   std::to_string(found) + ": " + quoted(record.text));
    }
    add_point(reader, record.line, record.fields[0], record.fields[1], file);
    if (columns == 3) file.values.push_back(reader.to_real(record.fields[2], record.line));
  }
  if (announced && *announced != file.points.size()) {
    reader.fail(first_line, "the count line announces " + std::to_string(*announced) +
                                " points, the file has " + std::to_string(file.points.size()));
  }
}

// `record` holds the header on entry.
void read_triangle(RecordReader& reader, Record& record, PointFile& file) {
  const std::size_t header_line = record.line;
  if (record.fields.size() != 4) {
    reader.fail(header_line, "expected a Triangle .node header 'N 2 nattr nbound', found " +
                                 quoted(record.text));
  }
  const std::size_t count = reader.to_index(record.fields[0], header_line);
  if (reader.to_index(record.fields[1], header_line) != 2) {
    reader.fail(header_line, "dimension " + quoted(record.fields[1]) + " is not 2");
  }
  const std::size_t attributes = reader.to_index(record.fields[2], header_line);
  const std::size_t markers = reader.to_index(record.fields[3], header_line);
  if (markers > 1) {
    reader.fail(header_line,
                "boundary marker count " + quoted(record.fields[3]) + " is not 0 or 1");
  }

  std::size_t first_index = 0;
  while (reader.next(record)) {
    const auto& fields = record.fields;
    const std::size_t line = record.line;
    if (file.points.size() == count) {
      reader.fail(line, "more vertices than the " + std::to_string(count) +
                            " announced by the header on line " + std::to_string(header_line));
    }
    // Compared without forming 3 + attributes + markers, which a bogus header could overflow.
    if (fields.size() < 3 + markers || fields.size() - 3 - markers != attributes) {
      reader.fail(line, "expected index, x, y, " + std::to_string(attributes) +
                            " attribute(s) and " + std::to_string(markers) +
                            " boundary marker(s), found " + std::to_string(fields.size()) +
                            " fields: " + quoted(record.text));
    }
    const std::size_t index = reader.to_index(fields[0], line);
    if (file.points.empty()) {
      if (index > 1)
        reader.fail(line, "first vertex index " + quoted(fields[0]) + " is neither 0 nor 1");
      first_index = index;
    } else if (index != first_index + file.points.size()) {
      reader.fail(line, "vertex index " + quoted(fields[0]) + " breaks the sequence: expected " +
                            std::to_string(first_index + file.points.size()));
    }
    add_point(reader, line, fields[1], fields[2], file);
    for (std::size_t a = 0; a < attributes; ++a) reader.to_real(fields[3 + a], line);
    if (markers == 1) reader.to_integer(fields.back(), line);
  }
  if (file.points.size() != count) {
    reader.fail(header_line, "the header announces " + std::to_string(count) +
                                 " vertices, the file has " + std::to_string(file.points.size()));
  }
}

}  // namespace

PointFile parse_point_file(std::string_view text, std::string_view name) {
  RecordReader reader(text, std::string(name));
  Record record;
  PointFile file;
  if (!reader.next(record)) return file;
  if (has_triangle_extension(name) || looks_like_triangle_header(record)) {
    read_triangle(reader, record, file);
  } else {
    read_plain(reader, record, file);
  }
  return file;
}

PointFile read_point_file(const std::filesystem::path& path) {
  return parse_point_file(read_text_file(path), path.string());
}

void write_points(std::ostream& out, std::span<const Point> points) {
  require_finite(points);
  for (const Point& p : points) write_number_pair(out, p.x(), p.y());
}

void write_points(const std::filesystem::path& path, std::span<const Point> points) {
  require_finite(points);  // before the file is truncated
  write_text_file(path, [points](std::ostream& out) { write_points(out, points); });
}

}  // namespace curvebench::geometry
