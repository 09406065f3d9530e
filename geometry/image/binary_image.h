// Binary images for the survey's discrete sampling tool (survey, "Sampling Tools": "a
// discrete sampling tool ... for extracting points from a given binary white-on-black
// image"): the image type, netpbm files, and rasterizing a Curve into an image, so that
// the image pipeline (image_sampling.h) runs on generated curves with known geometry too.
//
// Files: netpbm only, PBM (P1 plain, P4 raw) and PGM (P2 plain, P5 raw, maxval up to
// 65535). No PNG library is in curvebench's dependency stack; convert other formats with
// any tool (`convert in.png out.pgm`, `pngtopnm in.png | ppmtopgm > out.pgm`).
//
// Foreground is WHITE in every format, as the survey's tool expects white objects on a
// black background: in a PGM a value above maxval / 2; in a PBM, whose 1 means black, the
// 0 bits. So a picture means the same object whatever format a converter chose.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string_view>
#include <vector>

#include "geometry/curves/curve.h"
#include "geometry/kernel.h"
#include "geometry/io/parse_error.h"

namespace curvebench::geometry {

// At most 2^28 pixels (16384 x 16384): every pixel coordinate and squared pixel distance
// then fits comfortably in 64-bit integers, and a file cannot make us allocate gigabytes.
inline constexpr std::size_t max_image_pixels = std::size_t{1} << 28;

// A black-and-white image: object (foreground) pixels and background pixels.
// Consistent when pixels.size() == width * height, which the writers check.
struct Binary_image {
  // The number of columns.
  std::size_t width = 0, height = 0;  // the number of rows
  std::vector<std::uint8_t> pixels;  // row-major, row 0 at the top; 1 = object (foreground), 0 = background

  // Whether pixel (x, y), column x and row y from the top, is object. Not checked: x <
  // width, y < height.
  bool at(std::size_t x, std::size_t y) const { return pixels[y * width + x] != 0; }
  // Same size and same pixel values.
  friend bool operator==(const Binary_image&, const Binary_image&) = default;
};

// Throws ParseError ("FILE:LINE: what is wrong") on malformed input: an unsupported magic
// number (P3, P6, P7: convert to greyscale), a missing or non-numeric header field, maxval
// outside 1..65535, more than max_image_pixels, a value above maxval, a character other
// than 0 / 1 in a P1 raster, a raster that ends early, or extra values after a plain
// raster. `#` comments may stand wherever whitespace may (header and plain rasters). The
// line of an error inside a raw (P4, P5) raster is the line where the raster starts.
// Whatever follows a raw raster is ignored (netpbm streams may hold further images).
// Memory use is bounded by the size of the input, whatever the header claims.
Binary_image read_netpbm(const std::filesystem::path& path);
// The same from the bytes of a file in memory; `name` stands for the path in messages.
// Safe on arbitrary bytes (fuzz/netpbm_fuzz.cpp).
Binary_image parse_netpbm(std::string_view bytes, std::string_view name);

// P5 with maxval 255: object 255 (white), background 0. Throws std::invalid_argument if
// pixels.size() != width * height, and the path version std::filesystem::filesystem_error
// if the file cannot be written.
void write_pgm(const Binary_image& image, const std::filesystem::path& path);
// The same to a stream, which must be in binary mode.
void write_pgm(const Binary_image& image, std::ostream& out);

// The affine map between image coordinates (u to the right, v downwards, in pixels; pixel
// (x, y) covers [x, x + 1] x [y, y + 1]) and curve coordinates, with y flipped so that the
// image shows the curve upright. Both directions are floating-point constructions.
struct Raster_frame {
  double scale = 1;     // pixels per curve unit
  double x_origin = 0;  // curve x of the image's left edge, u = 0
  double y_origin = 0;  // curve y of the image's top edge, v = 0

  // The image coordinates (u, v) of curve point p.
  Point to_image(const Point& p) const { return {(p.x() - x_origin) * scale, (y_origin - p.y()) * scale}; }
  // The curve point at image coordinates (u, v): the inverse of to_image, up to rounding.
  Point to_curve(double u, double v) const { return {x_origin + u / scale, y_origin - v / scale}; }
};

// The interior of a curve of closed components by the even-odd rule, decided at pixel
// centres. The curve's bounding box plus 2 pixels on each side is scaled uniformly so that
// its longer side spans `resolution` pixels (the shorter side: as many as it needs), and
// centred. Each component becomes its polyline (chords within 0.05 pixel of the curve),
// mapped to image coordinates in floating point; what is inside that polygon is then
// decided exactly (fill_even_odd). `frame`, if given, receives the map. Throws
// std::invalid_argument for a curve with no component, an open component, no extent, or a
// resolution outside 8..16384.
Binary_image rasterize(const Curve& curve, std::size_t resolution, Raster_frame* frame = nullptr);

// The even-odd fill of closed polygons given in image coordinates (each polygon's last
// vertex joins its first): pixel (x, y) is foreground iff an odd number of polygon edges
// cross the ray from its centre c = (x + 0.5, y + 0.5) to the right, where an edge from
// `lower` to `upper` (lower.y < upper.y; horizontal edges never cross) crosses it iff
// lower.y <= c.y < upper.y (double comparisons, exact) and c lies strictly to the left of
// it (CGAL::orientation, exact). So a centre exactly on an edge does not count that edge:
// centres on the boundary go one way or the other, but always the same way. Throws
// std::invalid_argument for a non-finite vertex or more than max_image_pixels.
Binary_image fill_even_odd(const std::vector<std::vector<Point>>& polygons, std::size_t width, std::size_t height);

}  // namespace curvebench::geometry
