#include "geometry/io/point_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "geometry/io/text_file.h"
#include "geometry/io/text_records.h"

namespace curvebench::geometry {
namespace {

bool is_digits(std::string_view field) {
  return !field.empty() && std::ranges::all_of(field, [](char c) { return c >= '0' && c <= '9'; });
}

std::string lower_case(std::string text) {
  std::ranges::transform(text, text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool has_triangle_extension(std::string_view name) {
  const std::string extension = lower_case(std::filesystem::path(name).extension().string());
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

// Which field of a line is what: x, y and the optional value column, out of `count`.
struct Columns {
  std::size_t count = 0;
  std::size_t x = 0, y = 1;
  std::optional<std::size_t> value;
  std::size_t line = 0;  // where the count was set: the header, or the first data line
  bool named = false;
};

Columns positional_columns(const RecordReader& reader, const Record& record, bool header) {
  const std::size_t found = record.fields.size();
  if (found != 2 && found != 3) {
    reader.fail(record.line, "expected 2 or 3 columns (x y [value]), found " + std::to_string(found) + ": " +
                                 quoted(record.text));
  }
  return {.count = found, .value = found == 3 ? std::optional<std::size_t>(2) : std::nullopt, .line = record.line,
          .named = header};
}

// A header names the columns. Where it names x and y (in any case), those are the point;
// unnamed columns (pandas' index) are skipped, and one more named column is the value.
// Otherwise its columns are x y [value] by position.
Columns header_columns(const RecordReader& reader, const Record& header) {
  std::vector<std::string> names;
  for (const std::string_view field : header.fields) names.push_back(lower_case(unquoted(field)));
  const auto x = std::ranges::find(names, "x"), y = std::ranges::find(names, "y");
  if (x == names.end() || y == names.end()) return positional_columns(reader, header, true);
  Columns columns{.count = names.size(), .x = std::size_t(x - names.begin()), .y = std::size_t(y - names.begin()), .value = {},
                  .line = header.line, .named = true};
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i == columns.x || i == columns.y || names[i].empty()) continue;
    if (columns.value || names[i] == "x" || names[i] == "y") {
      reader.fail(header.line, "the header names more columns than x, y and one value: " + quoted(header.text));
    }
    columns.value = i;
  }
  return columns;
}

// `record` holds the first data line on entry, read with empty fields allowed.
void read_plain(RecordReader& reader, Record& record, PointFile& file) {
  const std::size_t first_line = record.line;
  std::optional<std::size_t> announced;
  std::optional<Columns> columns;
  bool more = true;
  if (std::ranges::none_of(record.fields, is_number)) {
    columns = header_columns(reader, record);
    more = reader.next(record);
  } else {
    reader.reject_empty_fields(record);
    if (record.fields.size() == 1 && is_digits(record.fields[0])) {
      announced = reader.to_index(record.fields[0], record.line);
      more = reader.next(record);
    }
  }
  for (; more; more = reader.next(record)) {
    if (!columns) columns = positional_columns(reader, record, false);
    const std::size_t found = record.fields.size();
    if (found != columns->count) {
      reader.fail(record.line, "expected " + std::to_string(columns->count) + " columns as " +
                                   (columns->named ? "named by the header" : "found") + " on line " +
                                   std::to_string(columns->line) + ", found " + std::to_string(found) + ": " +
                                   quoted(record.text));
    }
    // Every field is read, left to right, so that any malformed one is an error.
    for (std::size_t i = 0; i < found; ++i) {
      if (i == columns->y) continue;
      if (i == columns->x) {
        add_point(reader, record.line, record.fields[columns->x], record.fields[columns->y], file);
      } else if (i == columns->value) {
        file.values.push_back(reader.to_real(record.fields[i], record.line));
      } else {
        reader.to_real(record.fields[i], record.line);
      }
    }
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
  if (!reader.next(record, Empty_fields::allowed)) return file;
  if (has_triangle_extension(name) || looks_like_triangle_header(record)) {
    reader.reject_empty_fields(record);
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
