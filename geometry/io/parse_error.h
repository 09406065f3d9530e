// The one exception every curvebench file reader throws for bad input, so that a
// message always points a person at the exact place to fix: "FILE:LINE: what is wrong".
// Line 0 means the file as a whole (it could not be read).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace curvebench::geometry {

// Bad input in a file, or a file that cannot be read; what() is "FILE:LINE: MESSAGE".
class ParseError : public std::runtime_error {
 public:
  // `file` as it should appear in the message (usually the path), `line` 1-based or 0.
  ParseError(std::string file, std::size_t line, std::string_view message);

  // The file named in the message.
  const std::string& file() const noexcept { return file_; }
  // The 1-based line at fault; 0 for the file as a whole.
  std::size_t line() const noexcept { return line_; }

 private:
  std::string file_;
  std::size_t line_;
};

}  // namespace curvebench::geometry
