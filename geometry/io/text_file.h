// Whole-file text I/O for curvebench's readers and writers: one place that turns an
// unreadable or unwritable file into an error naming the path, so that every format
// reports it the same way.
#pragma once

#include <array>
#include <charconv>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <utility>

namespace curvebench::geometry {

// The bytes of `path`, unchanged (no line-ending translation: the parsers handle LF,
// CRLF and CR themselves). Throws ParseError with line 0 if the file cannot be read.
std::string read_text_file(const std::filesystem::path& path);

// Creates or truncates `path` and lets `write` fill it. Throws
// std::filesystem::filesystem_error if the file cannot be opened or a write fails.
void write_text_file(const std::filesystem::path& path,
                     const std::function<void(std::ostream&)>& write);

// Writes the line "a b\n" with std::to_chars: independent of the locale, and for doubles
// the shortest decimal that reads back to the same value.
template <class Number>
void write_number_pair(std::ostream& out, Number a, Number b) {
  std::array<char, 32> digits;  // a number takes at most 24 (-2.2250738585072014e-308)
  for (const auto& [value, separator] : {std::pair(a, ' '), std::pair(b, '\n')}) {
    const char* end = std::to_chars(digits.data(), digits.data() + digits.size(), value).ptr;
    out.write(digits.data(), end - digits.data());
    out.put(separator);
  }
}

}  // namespace curvebench::geometry
