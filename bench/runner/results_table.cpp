#include "bench/runner/results_table.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace curvebench::bench {
namespace {

constexpr std::string_view names[column_count] = {
    "job",        "suite",      "input",           "level",           "algorithm",       "params",
    "n_points",   "epsilon",    "rho",             "uniformity",      "status",          "exact",           "hausdorff",
    "rms",        "hausdorff_to_curve", "rms_to_curve", "hausdorff_from_curve", "rms_from_curve",
    "normal_deviation", "manifold", "components",      "open_components", "closed_components",
    "unconnected", "output_points", "true_topology", "runtime_ms", "startup_ms", "picture", "message"};

enum class Kind { integer, real, boolean, text };

Kind kind_of(std::size_t column) {
  switch (static_cast<Column>(column)) {
    case Column::job: case Column::n_points: case Column::components: case Column::open_components:
    case Column::closed_components: case Column::unconnected: case Column::output_points:
      return Kind::integer;
    case Column::epsilon: case Column::rho: case Column::uniformity: case Column::hausdorff: case Column::rms: case Column::normal_deviation:
    case Column::hausdorff_to_curve: case Column::rms_to_curve: case Column::hausdorff_from_curve: case Column::rms_from_curve:
    case Column::runtime_ms: case Column::startup_ms:
      return Kind::real;
    case Column::exact: case Column::manifold: case Column::true_topology:
      return Kind::boolean;
    default:
      return Kind::text;
  }
}

// Splits one CSV record (RFC 4180: quoted fields, "" for a quote inside one).
std::optional<std::vector<std::string>> split_csv(std::string_view line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') fields.back() += c;
      else if (i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
      else quoted = false;
    } else if (c == '"' && fields.back().empty()) {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) return std::nullopt;
  return fields;
}

std::string header_line() {
  std::string line;
  for (const std::string_view name : names) {
    if (!line.empty()) line += ',';
    line += name;
  }
  return line;
}

}  // namespace

std::span<const std::string_view> column_names() { return names; }

std::size_t Result_row::job() const { return std::stoull((*this)[Column::job]); }

std::string Result_row::csv() const {
  std::string line;
  for (std::size_t c = 0; c < column_count; ++c) {
    if (c > 0) line += ',';
    const std::string& field = fields_[c];
    if (field.find_first_of(",\"\n\r") == std::string::npos) {
      line += field;
      continue;
    }
    line += '"';
    for (const char ch : field) line += ch == '"' ? std::string("\"\"") : std::string(1, ch == '\n' || ch == '\r' ? ' ' : ch);
    line += '"';
  }
  return line;
}

std::optional<Result_row> Result_row::parse_csv(std::string_view line) {
  const auto fields = split_csv(line);
  if (!fields || fields->size() != column_count) return std::nullopt;
  Result_row row;
  for (std::size_t c = 0; c < column_count; ++c) row.fields_[c] = (*fields)[c];
  if (row[Column::job].empty() || row[Column::job].find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  return row;
}

std::string format_number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (std::isnan(value)) return "nan";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::vector<Result_row> read_results_csv(const std::filesystem::path& file) {
  std::vector<Result_row> rows;
  std::ifstream in(file, std::ios::binary);
  if (!in) return rows;
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  std::size_t line_number = 0, at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    if (end == std::string::npos) break;  // cut off mid-line: that job runs again
    const std::string_view line(text.data() + at, end - at);
    at = end + 1;
    if (++line_number == 1) {
      if (line != header_line())
        throw std::runtime_error(file.string() + ":1: not a curvebench results.csv header");
      continue;
    }
    auto row = Result_row::parse_csv(line);
    if (!row) throw std::runtime_error(file.string() + ":" + std::to_string(line_number) + ": malformed row");
    rows.push_back(std::move(*row));
  }
  return rows;
}

void write_results_csv(const std::filesystem::path& file, std::span<const Result_row> rows) {
  const std::filesystem::path temporary = std::filesystem::path(file) += ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << header_line() << '\n';
    for (const Result_row& row : rows) out << row.csv() << '\n';
    if (!out.flush()) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, file);
}

void write_results_json(const std::filesystem::path& file, std::span<const Result_row> rows) {
  // One row per line, compact: the file is read by programs, and indenting every field
  // of tens of thousands of rows doubled it.
  std::ofstream out(file);
  out << "[";
  for (const Result_row& row : rows) {
    nlohmann::json object = nlohmann::json::object();
    for (std::size_t c = 0; c < column_count; ++c) {
      const std::string& field = row[static_cast<Column>(c)];
      nlohmann::json& value = object[std::string(names[c])];
      if (field.empty()) continue;  // null
      switch (kind_of(c)) {
        case Kind::integer: value = std::stoull(field); break;
        case Kind::real: value = std::isfinite(std::stod(field)) ? nlohmann::json(std::stod(field)) : nlohmann::json(field); break;
        case Kind::boolean: value = field == "1"; break;
        case Kind::text: value = field; break;
      }
    }
    out << (&row == rows.data() ? "\n" : ",\n") << object.dump();
  }
  out << "\n]\n";
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace curvebench::bench
