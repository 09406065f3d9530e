#include "geometry/image/binary_image.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>

#include "geometry/io/text_file.h"
#include "geometry/io/text_records.h"

namespace curvebench::geometry {
namespace {

// ---- netpbm ------------------------------------------------------------------------

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The bytes as netpbm tokens: a cursor that counts lines (LF, CRLF and a lone CR each end
// one) so that every error names the line a person would look at.
class Netpbm_reader {
 public:
  Netpbm_reader(std::string_view bytes, std::string_view name) : bytes_(bytes), name_(name) {}

  [[noreturn]] void fail(std::string_view message) const { fail_at(line_, message); }
  [[noreturn]] void fail_at(std::size_t line, std::string_view message) const {
    throw ParseError(name_, line, message);
  }

  std::size_t line() const { return line_; }
  // At the end: the line of the last byte, where a person looks for what is missing.
  [[noreturn]] void fail_at_end(std::string_view message) const {
    const bool ends_line = !bytes_.empty() && (bytes_.back() == '\n' || bytes_.back() == '\r');
    fail_at(line_ - (ends_line && line_ > 1 ? 1 : 0), message);
  }
  std::size_t remaining() const { return bytes_.size() - position_; }
  bool at_end() const { return position_ == bytes_.size(); }
  char peek() const { return bytes_[position_]; }

  void advance() {
    const char c = bytes_[position_++];
    if (c == '\n' || (c == '\r' && (at_end() || peek() != '\n'))) ++line_;
  }

  // Whitespace and `#` comments (to the end of the line).
  void skip_separators() {
    while (!at_end()) {
      if (peek() == '#') {
        while (!at_end() && peek() != '\n' && peek() != '\r') advance();
      } else if (is_space(peek())) {
        advance();
      } else {
        return;
      }
    }
  }

  // The next token (up to whitespace or a comment), for messages.
  std::string next_token() const {
    std::size_t end = position_;
    while (end < bytes_.size() && !is_space(bytes_[end]) && bytes_[end] != '#') ++end;
    return quoted(bytes_.substr(position_, end - position_));
  }

  // A decimal number after optional separators, at most `max` (`what` names it, and
  // `max_name` the limit in messages).
  std::uint64_t number(const char* what, std::uint64_t max, std::string_view max_name = "the limit") {
    skip_separators();
    if (at_end()) fail_at_end(std::string("the file ends where the ") + what + " should be");
    if (!is_digit(peek())) fail(std::string("expected the ") + what + ", found " + next_token());
    const std::size_t start = position_;
    std::uint64_t value = 0;
    bool too_large = false;
    while (!at_end() && is_digit(peek())) {
      value = value * 10 + static_cast<std::uint64_t>(peek() - '0');
      if (value > max) too_large = true;
      if (too_large) value = max + 1;  // saturate: no overflow however many digits follow
      advance();
    }
    if (!at_end() && !is_space(peek()) && peek() != '#') {
      position_ = start;
      fail(std::string("expected the ") + what + ", found " + next_token());
    }
    if (too_large) {
      fail(std::string("the ") + what + " " + quoted(bytes_.substr(start, position_ - start)) +
           " is above " + std::string(max_name) + " " + std::to_string(max));
    }
    return value;
  }

  // The single whitespace character (or a comment ending in one) that ends a raw header.
  void end_of_raw_header() {
    if (at_end()) fail_at_end("the file ends before the raster");
    if (peek() == '#') {
      while (!at_end() && peek() != '\n' && peek() != '\r') advance();
      if (at_end()) fail_at_end("the file ends before the raster");
    } else if (!is_space(peek())) {
      fail("expected one whitespace character before the raster, found " + next_token());
    }
    advance();
  }

  std::uint8_t byte() { return static_cast<std::uint8_t>(bytes_[position_++]); }  // raw data: no line counting

 private:
  std::string_view bytes_;
  std::string name_;
  std::size_t position_ = 0;
  std::size_t line_ = 1;
};

std::string size_text(std::size_t width, std::size_t height) {
  return std::to_string(width) + " x " + std::to_string(height);
}

void read_plain_pbm(Netpbm_reader& in, Binary_image& image) {
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    in.skip_separators();
    if (in.at_end()) in.fail_at_end("the raster ends after " + std::to_string(i) + " of " + size_text(image.width, image.height) + " pixels");
    const char c = in.peek();
    if (c != '0' && c != '1') in.fail("expected a pixel 0 or 1, found " + quoted(std::string_view(&c, 1)));
    image.pixels[i] = c == '0';  // PBM's 1 is black: the object is the white 0 bits
    in.advance();
  }
}

void read_plain_pgm(Netpbm_reader& in, Binary_image& image, std::uint64_t maxval) {
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    in.skip_separators();
    if (in.at_end()) in.fail_at_end("the raster ends after " + std::to_string(i) + " of " + size_text(image.width, image.height) + " pixels");
    const std::uint64_t value = in.number("pixel value", maxval, "maxval");
    image.pixels[i] = 2 * value > maxval;
  }
}

void read_raw_pbm(Netpbm_reader& in, Binary_image& image, std::size_t raster_line) {
  const std::size_t row_bytes = (image.width + 7) / 8;
  if (in.remaining() < row_bytes * image.height)
    in.fail_at(raster_line, "the raster has " + std::to_string(in.remaining()) + " bytes, " + size_text(image.width, image.height) +
                                " pixels need " + std::to_string(row_bytes * image.height));
  for (std::size_t y = 0; y < image.height; ++y) {
    std::uint8_t bits = 0;
    for (std::size_t x = 0; x < image.width; ++x) {
      if (x % 8 == 0) bits = in.byte();
      image.pixels[y * image.width + x] = ((bits >> (7 - x % 8)) & 1) == 0;  // 0 = white = object
    }
  }
}

void read_raw_pgm(Netpbm_reader& in, Binary_image& image, std::uint64_t maxval, std::size_t raster_line) {
  const std::size_t sample_bytes = maxval < 256 ? 1 : 2;  // big-endian when two
  if (in.remaining() / sample_bytes < image.pixels.size())
    in.fail_at(raster_line, "the raster has " + std::to_string(in.remaining()) + " bytes, " + size_text(image.width, image.height) +
                                " pixels need " + std::to_string(sample_bytes * image.pixels.size()));
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    std::uint64_t value = in.byte();
    if (sample_bytes == 2) value = value << 8 | in.byte();
    if (value > maxval)
      in.fail_at(raster_line, "pixel (" + std::to_string(i % image.width) + ", " + std::to_string(i / image.width) + ") has value " +
                                  std::to_string(value) + ", above maxval " + std::to_string(maxval));
    image.pixels[i] = 2 * value > maxval;
  }
}

void require_consistent(const Binary_image& image, const char* who) {
  if (image.width != 0 && image.height > max_image_pixels / image.width)
    throw std::invalid_argument(std::string(who) + ": more than 2^28 pixels");
  if (image.pixels.size() != image.width * image.height)
    throw std::invalid_argument(std::string(who) + ": " + std::to_string(image.pixels.size()) + " pixels for a " +
                                size_text(image.width, image.height) + " image");
}

}  // namespace

Binary_image parse_netpbm(std::string_view bytes, std::string_view name) {
  Netpbm_reader in(bytes, name);
  if (bytes.size() < 2 || bytes[0] != 'P' || !is_digit(bytes[1]))
    in.fail("not a netpbm image: expected the magic number P1, P2, P4 or P5, found " + quoted(bytes.substr(0, 2)));
  const char kind = bytes[1];
  if (kind != '1' && kind != '2' && kind != '4' && kind != '5')
    in.fail("netpbm format " + quoted(bytes.substr(0, 2)) +
            " is not read: only PBM (P1, P4) and PGM (P2, P5); convert colour images to greyscale");
  in.advance();
  in.advance();
  if (!in.at_end() && !is_space(in.peek()) && in.peek() != '#')
    in.fail("expected whitespace after the magic number, found " + in.next_token());

  Binary_image image;
  image.width = in.number("width", max_image_pixels);
  image.height = in.number("height", max_image_pixels);
  if (image.width != 0 && image.height > max_image_pixels / image.width)
    in.fail(size_text(image.width, image.height) + " pixels is above the limit of 2^28 pixels");
  const bool grey = kind == '2' || kind == '5', raw = kind == '4' || kind == '5';
  std::uint64_t maxval = 1;
  if (grey) {
    maxval = in.number("maxval", 65535);
    if (maxval == 0) in.fail("maxval must be 1 to 65535, found 0");
  }
  // Plain rasters take at least one byte per pixel: refuse a size the bytes cannot hold
  // before allocating it (raw rasters are checked against their exact size below).
  if (!raw && in.remaining() < image.width * image.height)
    in.fail("the file is too short for a " + size_text(image.width, image.height) + " raster");
  if (raw) in.end_of_raw_header();
  const std::size_t raster_line = in.line();
  if (raw && in.remaining() * 8 < image.width * image.height)
    in.fail_at(raster_line, "the file is too short for a " + size_text(image.width, image.height) + " raster");
  image.pixels.assign(image.width * image.height, 0);

  // An image without pixels (width or height 0, allowed by the format) has no raster:
  // skip it rather than walk up to 2^28 empty rows.
  if (!image.pixels.empty()) {
    if (kind == '1') read_plain_pbm(in, image);
    if (kind == '2') read_plain_pgm(in, image, maxval);
    if (kind == '4') read_raw_pbm(in, image, raster_line);
    if (kind == '5') read_raw_pgm(in, image, maxval, raster_line);
  }
  if (!raw) {
    in.skip_separators();
    if (!in.at_end())
      in.fail("more than the " + size_text(image.width, image.height) + " pixel values of the header: " + in.next_token());
  }
  return image;
}

Binary_image read_netpbm(const std::filesystem::path& path) { return parse_netpbm(read_text_file(path), path.string()); }

void write_pgm(const Binary_image& image, std::ostream& out) {
  require_consistent(image, "write_pgm");
  out << "P5\n" << image.width << ' ' << image.height << "\n255\n";
  if (image.pixels.empty()) return;
  std::string row(image.width, '\0');
  for (std::size_t y = 0; y < image.height; ++y) {
    for (std::size_t x = 0; x < image.width; ++x) row[x] = image.at(x, y) ? '\xff' : '\0';
    out.write(row.data(), static_cast<std::streamsize>(row.size()));
  }
}

void write_pgm(const Binary_image& image, const std::filesystem::path& path) {
  require_consistent(image, "write_pgm");
  write_text_file(path, [&image](std::ostream& out) { write_pgm(image, out); });
}

// ---- rasterizing -------------------------------------------------------------------

namespace {

// The smallest j in [0, limit] with j + 0.5 >= y (limit if none): a guess in floating
// point, then corrected by exact comparisons (j + 0.5 is a double exactly for j < 2^52).
std::size_t first_centre_at_or_above(double y, std::size_t limit) {
  const double guess = std::ceil(y - 0.5);
  std::size_t j = !(guess > 0) ? 0 : guess >= static_cast<double>(limit) ? limit : static_cast<std::size_t>(guess);
  while (j > 0 && static_cast<double>(j - 1) + 0.5 >= y) --j;
  while (j < limit && static_cast<double>(j) + 0.5 < y) ++j;
  return j;
}

}  // namespace

Binary_image fill_even_odd(const std::vector<std::vector<Point>>& polygons, std::size_t width, std::size_t height) {
  if (width != 0 && height > max_image_pixels / width) throw std::invalid_argument("fill_even_odd: more than 2^28 pixels");
  for (const auto& polygon : polygons)
    for (const Point& p : polygon)
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) throw std::invalid_argument("fill_even_odd: a non-finite vertex");
  Binary_image image{width, height, std::vector<std::uint8_t>(width * height, 0)};
  if (image.pixels.empty()) return image;
  // Pass 1: for each edge and each pixel row it crosses, the first column whose centre is
  // on or right of the edge; every pixel left of it is toggled, marked here at the last
  // such pixel. Pass 2 turns the marks into the parity of the marks at or right of each pixel.
  for (const auto& polygon : polygons) {
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      Point lower = polygon[k], upper = polygon[(k + 1) % polygon.size()];
      if (lower.y() == upper.y()) continue;
      if (upper.y() < lower.y()) std::swap(lower, upper);
      const std::size_t row_end = first_centre_at_or_above(upper.y(), height);
      for (std::size_t y = first_centre_at_or_above(lower.y(), height); y < row_end; ++y) {
        const double centre_y = static_cast<double>(y) + 0.5;
        const auto left_of_edge = [&](std::size_t x) {
          return CGAL::orientation(lower, upper, Point(static_cast<double>(x) + 0.5, centre_y)) == CGAL::LEFT_TURN;
        };
        // Where the edge crosses the row, approximately; then exactly by orientation.
        const double crossing =
            lower.x() + (centre_y - lower.y()) / (upper.y() - lower.y()) * (upper.x() - lower.x());
        const double guess = std::ceil(crossing - 0.5);
        std::size_t x = !(guess > 0) ? 0 : guess >= static_cast<double>(width) ? width : static_cast<std::size_t>(guess);
        while (x > 0 && !left_of_edge(x - 1)) --x;
        while (x < width && left_of_edge(x)) ++x;
        if (x > 0) image.pixels[y * width + x - 1] ^= 1;
      }
    }
  }
  for (std::size_t y = 0; y < height; ++y) {
    std::uint8_t parity = 0;
    for (std::size_t x = width; x-- > 0;) parity = image.pixels[y * width + x] ^= parity;
  }
  return image;
}

Binary_image rasterize(const Curve& curve, std::size_t resolution, Raster_frame* frame) {
  if (resolution < 8 || resolution > 16384)
    throw std::invalid_argument("rasterize: the resolution must be 8 to 16384 pixels, not " + std::to_string(resolution));
  if (curve.components.empty()) throw std::invalid_argument("rasterize: " + curve.name + " has no component");
  for (std::size_t c = 0; c < curve.components.size(); ++c)
    if (!curve.components[c].closed())
      throw std::invalid_argument("rasterize: component " + std::to_string(c) + " of " + curve.name +
                                  " is open; only closed curves bound a region to fill");
  // The pixel size from a coarse bounding box; then polylines within 0.05 pixel, and the
  // exact bounding box of their vertices (the curve strays at most 0.05 pixel beyond it,
  // well inside the 2-pixel margin).
  const double margin = 2;
  const auto coarse = curve.bounding_box(1e-3 * curve.length());
  const double coarse_side = std::max(coarse.xmax() - coarse.xmin(), coarse.ymax() - coarse.ymin());
  if (!(coarse_side > 0) || !std::isfinite(coarse_side))
    throw std::invalid_argument("rasterize: " + curve.name + " has no extent");
  const double tolerance = 0.05 * coarse_side / (static_cast<double>(resolution) - 2 * margin);
  std::vector<std::vector<Point>> polygons;
  double x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY, y_max = -INFINITY;
  for (const auto& component : curve.components) {
    polygons.push_back(component.polyline(tolerance));
    for (const Point& p : polygons.back()) {
      x_min = std::min(x_min, p.x()), x_max = std::max(x_max, p.x());
      y_min = std::min(y_min, p.y()), y_max = std::max(y_max, p.y());
    }
  }
  const double side = std::max(x_max - x_min, y_max - y_min);
  if (!(side > 0) || !std::isfinite(side)) throw std::invalid_argument("rasterize: " + curve.name + " has no extent");
  const double scale = (static_cast<double>(resolution) - 2 * margin) / side;
  const auto pixels_for = [&](double extent) {
    return std::min(resolution, static_cast<std::size_t>(std::ceil(extent * scale)) + 2 * static_cast<std::size_t>(margin));
  };
  const std::size_t width = pixels_for(x_max - x_min), height = pixels_for(y_max - y_min);
  const Raster_frame map{scale, (x_min + x_max) / 2 - static_cast<double>(width) / 2 / scale,
                         (y_min + y_max) / 2 + static_cast<double>(height) / 2 / scale};
  for (auto& polygon : polygons)
    for (Point& p : polygon) p = map.to_image(p);
  if (frame) *frame = map;
  return fill_even_odd(polygons, width, height);
}

}  // namespace curvebench::geometry
