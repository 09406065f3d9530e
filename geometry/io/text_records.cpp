#include "geometry/io/text_records.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <system_error>
#include <utility>

#include "geometry/io/parse_error.h"

namespace curvebench::geometry {
namespace {

constexpr std::string_view kBlanks = " \t";
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// The whole of `field` as an Integer, or nothing if any byte is left over or it does
// not fit.
template <class Integer>
std::optional<Integer> whole_integer(std::string_view field) {
  Integer value = 0;
  const char* last = field.data() + field.size();
  const auto [end, error] = std::from_chars(field.data(), last, value);
  if (error != std::errc() || end != last) return std::nullopt;
  return value;
}

// std::from_chars on `field`, but, unlike it and like strtod, taking a leading '+' (data
// files written by printf("%+g") have one; "+-1" stays malformed). The result's ptr is
// the end of `field` when all of it is read.
std::from_chars_result read_double(std::string_view field, double& value) {
  if (field.size() > 1 && field[0] == '+' && field[1] != '-') field.remove_prefix(1);
  return std::from_chars(field.data(), field.data() + field.size(), value);
}

}  // namespace

bool is_number(std::string_view field) {
  double value = 0;
  const auto [end, error] = read_double(field, value);
  return end == field.data() + field.size() && error != std::errc::invalid_argument;
}

RecordReader::RecordReader(std::string_view text, std::string name)
    : rest_(text), name_(std::move(name)) {
  if (rest_.starts_with(kByteOrderMark)) rest_.remove_prefix(kByteOrderMark.size());
}

bool RecordReader::next(Record& record, Empty_fields empty) {
  while (!rest_.empty()) {
    split_fields(take_line(), record.fields, empty);
    if (record.fields.empty()) continue;
    record.line = line_;
    record.text = std::string_view(record.fields.front().begin(), record.fields.back().end());
    return true;
  }
  return false;
}

void RecordReader::reject_empty_fields(const Record& record) const {
  if (std::ranges::any_of(record.fields, &std::string_view::empty)) fail(record.line, "stray ',' (empty field)");
}

std::string_view RecordReader::take_line() {
  const std::size_t end = std::min(rest_.find_first_of("\r\n"), rest_.size());
  const std::string_view line = rest_.substr(0, end);
  const bool crlf = rest_.substr(end).starts_with("\r\n");
  rest_.remove_prefix(std::min(rest_.size(), end + (crlf ? 2 : 1)));
  ++line_;
  return line;
}

void RecordReader::split_fields(std::string_view line, std::vector<std::string_view>& fields,
                                Empty_fields empty) const {
  fields.clear();
  const auto skip_blanks = [line](std::size_t from) {
    return std::min(line.find_first_not_of(kBlanks, from), line.size());
  };
  const auto empty_field = [&](std::size_t pos) {
    if (empty == Empty_fields::rejected) fail(line_, "stray ',' (empty field)");
    fields.push_back(line.substr(pos, 0));
  };
  bool after_comma = false;
  std::size_t pos = skip_blanks(0);
  while (pos < line.size() && line[pos] != '#') {
    if (line[pos] == ',') {
      if (fields.empty() || after_comma) empty_field(pos);
      after_comma = true;
      pos = skip_blanks(pos + 1);
      continue;
    }
    std::size_t end = 0;
    if (line[pos] == '"') {
      // To the closing quote: the first quote not followed by another.
      for (end = pos + 1;; end += 2) {
        end = line.find('"', end);
        if (end == std::string_view::npos) fail(line_, "a quoted field has no closing '\"'");
        if (end + 1 == line.size() || line[end + 1] != '"') break;
      }
      ++end;
      if (end < line.size() && kBlanks.find(line[end]) == std::string_view::npos && line[end] != ',' && line[end] != '#')
        fail(line_, "text after the closing quote of " + quoted(line.substr(pos, end - pos)));
    } else {
      end = std::min(line.find_first_of(" \t,#", pos), line.size());
    }
    fields.push_back(line.substr(pos, end - pos));
    after_comma = false;
    pos = skip_blanks(end);
  }
  if (after_comma) empty_field(pos);
}

void RecordReader::fail(std::size_t line, std::string_view message) const {
  throw ParseError(name_, line, message);
}

double RecordReader::to_real(std::string_view field, std::size_t line) const {
  double value = 0;
  const auto [end, error] = read_double(field, value);
  if (end != field.data() + field.size() || error == std::errc::invalid_argument) {
    fail(line, quoted(field) + " is not a number");
  }
  if (error == std::errc::result_out_of_range) {
    fail(line, quoted(field) + " is out of the range of double");
  }
  if (!std::isfinite(value)) fail(line, quoted(field) + " is not a finite number");
  return value;
}

std::size_t RecordReader::to_index(std::string_view field, std::size_t line) const {
  if (const auto index = whole_integer<std::size_t>(field)) return *index;
  if (field.starts_with('-') && whole_integer<std::size_t>(field.substr(1))) {
    fail(line, quoted(field) + " is negative: expected a non-negative integer");
  }
  fail(line, quoted(field) + " is not a non-negative integer (or too large)");
}

long long RecordReader::to_integer(std::string_view field, std::size_t line) const {
  if (const auto value = whole_integer<long long>(field)) return *value;
  fail(line, quoted(field) + " is not an integer (or too large)");
}

std::string quoted(std::string_view field) {
  constexpr std::size_t kShown = 40;
  constexpr std::string_view kHex = "0123456789ABCDEF";
  std::string out = "'";
  for (const char c : field.substr(0, kShown)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F) {
      out += c;
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xF];
    }
  }
  if (field.size() > kShown) out += "...";
  out += '\'';
  return out;
}

std::string unquoted(std::string_view field) {
  if (field.size() < 2 || field.front() != '"' || field.back() != '"') return std::string(field);
  std::string text;
  for (std::size_t i = 1; i + 1 < field.size(); ++i) {
    text += field[i];
    if (field[i] == '"') ++i;  // the second quote of ""
  }
  return text;
}

}  // namespace curvebench::geometry
