#include "geometry/io/text_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

#include "geometry/io/parse_error.h"

namespace curvebench::geometry {

std::string read_text_file(const std::filesystem::path& path) {
  // A directory opens fine as a stream and then reads as empty: refuse it up front,
  // or it would pass for a valid file with 0 points.
  if (std::error_code ignored; std::filesystem::is_directory(path, ignored)) {
    throw ParseError(path.string(), 0, "cannot read: is a directory");
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ParseError(
        path.string(), 0,
        std::string("cannot open: ") + (errno ? std::strerror(errno) : "unknown error"));
  }
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw ParseError(path.string(), 0, "read error");
  return text;
}

void write_text_file(const std::filesystem::path& path,
                     const std::function<void(std::ostream&)>& write) {
  const auto fail = [&path](const char* what) {
    throw std::filesystem::filesystem_error(
        what, path, std::error_code(errno ? errno : EIO, std::generic_category()));
  };
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) fail("cannot open for writing");
  write(out);
  out.close();
  if (!out) fail("write failed");
}

}  // namespace curvebench::geometry
