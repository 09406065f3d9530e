// The lexical layer under curvebench's text formats (point files, edge lists, Triangle
// .node): a text is a sequence of records, one per line that holds data, and each record
// is a list of fields. The rules, shared by every format so they cannot drift apart:
//
//  - a UTF-8 byte-order mark at the start of the text is skipped (editors and
//    spreadsheets on Windows write one);
//  - a line ends at LF, CRLF or a lone CR (old Mac files), so CRLF counts as one line;
//  - `#` starts a comment that runs to the end of the line; lines with no fields are
//    skipped (blank lines and comment lines may stand anywhere);
//  - fields are separated by spaces and tabs, or by one comma with optional spaces and
//    tabs around it; an empty field (",,", or a comma at either end) is an error, except
//    in a line read with Empty_fields::allowed (a CSV header, whose first column pandas
//    leaves unnamed);
//  - a field in double quotes runs to the closing quote ("" inside stands for one quote)
//    and may hold blanks, commas and '#'. It keeps its quotes, so it is never a number;
//    unquoted() gives its text.
//
// Conversions of fields to numbers throw ParseError("FILE:LINE: 'field' is ...").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::geometry {

// Whether RecordReader::next accepts empty fields in a line (see above).
enum class Empty_fields { rejected, allowed };

// One line that holds data, split into fields. Views into the text being read, valid
// while that text is.
struct Record {
  std::size_t line = 0;                  // 1-based line number in the text
  std::string_view text;                 // first to last field of the line, for messages
  std::vector<std::string_view> fields;  // views into the text being read
};

// Reads a text record by record under the rules above, and turns fields into numbers with
// error messages that name the file and line.
class RecordReader {
 public:
  // `name` (usually the path) prefixes every error message; `text` must outlive the reader.
  RecordReader(std::string_view text, std::string name);

  // Fills `record` with the next line that holds data; false at the end of the text.
  // Reuses the storage of `record.fields`, so reading a file allocates once. With
  // Empty_fields::allowed an empty field is an empty view instead of an error; a caller
  // that then finds the line is not what it allowed it for calls reject_empty_fields.
  bool next(Record& record, Empty_fields empty = Empty_fields::rejected);
  // Throws ParseError if `record` has an empty field.
  void reject_empty_fields(const Record& record) const;

  // Throws ParseError("NAME:LINE: MESSAGE"), for the caller's own checks of a record.
  [[noreturn]] void fail(std::size_t line, std::string_view message) const;

  // A finite double; rejects NaN, infinities, values out of the range of double
  // (overflow and underflow) and anything that is not entirely a number.
  double to_real(std::string_view field, std::size_t line) const;
  // A non-negative integer that fits std::size_t (point indices, counts).
  std::size_t to_index(std::string_view field, std::size_t line) const;
  // Any integer that fits long long (Triangle boundary markers).
  long long to_integer(std::string_view field, std::size_t line) const;

 private:
  // Removes the next line and its line end from the text and returns it.
  std::string_view take_line();
  void split_fields(std::string_view line, std::vector<std::string_view>& fields, Empty_fields empty) const;

  std::string_view rest_;
  std::string name_;
  std::size_t line_ = 0;
};

// Whether all of `field` reads as a number, as RecordReader::to_real reads it, in the
// range of double and finite or not: a header line has no such field.
bool is_number(std::string_view field);

// `field` in single quotes, with control and non-ASCII bytes escaped as `\xNN` and long
// fields cut, so that an error message stays one printable line whatever the input.
std::string quoted(std::string_view field);

// The text of a field in double quotes, without them and with "" read as one quote; any
// other field as it is.
std::string unquoted(std::string_view field);

}  // namespace curvebench::geometry
