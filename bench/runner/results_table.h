// DIR/results.csv and DIR/results.json of a benchmark run: one tidy row per job
// (algorithm x input x parameters). Rows are kept as the text of their fields, so a row
// travels from a worker process to the file and back (resume, merge) unchanged.
#pragma once

#include <array>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::bench {

// The columns of results.csv, in order; column_names() gives their header names.
enum class Column {
  job, suite, input, level, algorithm, params, n_points, epsilon, rho, uniformity, status, exact, hausdorff, rms,
  hausdorff_to_curve, rms_to_curve, hausdorff_from_curve, rms_from_curve, normal_deviation, manifold, components,
  open_components, closed_components, unconnected, output_points, true_topology, runtime_ms, startup_ms, picture, message,
};
// The number of columns.
inline constexpr std::size_t column_count = static_cast<std::size_t>(Column::message) + 1;

// The header of results.csv, in order.
std::span<const std::string_view> column_names();

// One row of results.csv: a field of text per Column, empty when unknown.
class Result_row {
 public:
  // The field of `column`.
  std::string& operator[](Column column) { return fields_[static_cast<std::size_t>(column)]; }
  // The field of `column`, read-only.
  const std::string& operator[](Column column) const { return fields_[static_cast<std::size_t>(column)]; }
  std::size_t job() const;  // the job column as a number
  // Equal if every field is.
  bool operator==(const Result_row&) const = default;

  // One CSV line (RFC 4180 quoting), without the line end.
  std::string csv() const;
  // Parses what csv() wrote; std::nullopt if it is not one row of column_count fields.
  static std::optional<Result_row> parse_csv(std::string_view line);

 private:
  std::array<std::string, column_count> fields_;
};

// A number as results.csv writes it: the shortest text that reads back to the same double;
// "inf" for infinity.
std::string format_number(double value);

// The rows of a results.csv: the header is checked, and a last line without its line end
// (a run killed while writing) is dropped. Throws std::runtime_error naming the file and
// line for anything else malformed. A missing file has no rows.
std::vector<Result_row> read_results_csv(const std::filesystem::path& file);

// Writes header and rows (atomically: a temporary file renamed over `file`).
void write_results_csv(const std::filesystem::path& file, std::span<const Result_row> rows);
// Writes the rows as a JSON array, an object per row keyed by column name: numbers as
// numbers, an empty field as null. Throws std::runtime_error if the file cannot be written.
void write_results_json(const std::filesystem::path& file, std::span<const Result_row> rows);

}  // namespace curvebench::bench
