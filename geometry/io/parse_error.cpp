#include "geometry/io/parse_error.h"

#include <utility>

namespace curvebench::geometry {

ParseError::ParseError(std::string file, std::size_t line, std::string_view message)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + std::string(message)),
      file_(std::move(file)),
      line_(line) {}

}  // namespace curvebench::geometry
