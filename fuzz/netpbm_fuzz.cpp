// libFuzzer target for geometry/image/binary_image.h and geometry/image/image_sampling.h (survey,
// "Sampling Tools": the discrete sampling tool). parse_netpbm must turn any bytes into an
// image or a ParseError, without a crash, undefined behaviour, another exception or an
// allocation larger than the bytes call for; what it accepts must survive write_pgm and a
// second parse unchanged. A small accepted image (at most 128 x 128) is then sampled, and
// the laws are checked against oracles written here from the definitions:
//  - boundary_pixels are the object pixels with a background 8-neighbour;
//  - the boundary loops pass only boundary pixels, consecutive ones distinct 8-neighbours,
//    and every boundary pixel;
//  - for radii 1, 1.5 and one drawn from a hash of the input: the samples are distinct
//    boundary pixels, pairwise at least r apart, every boundary pixel is closer than r to
//    one, the ground truth is a chain (closed from 3 points) per loop, and the same seed
//    gives the same points. "Closer than r" is decided in exact rationals (CGAL::Exact_rational),
//    independently of erasure_threshold.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

#include <CGAL/Exact_rational.h>

#include "fuzz/fuzz_target.h"
#include "geometry/image/binary_image.h"
#include "geometry/image/image_sampling.h"

namespace curvebench::fuzz {
namespace {

using geometry::Binary_image;
using geometry::Pixel;

constexpr std::size_t max_side = 128;

struct Oracle {
  const Binary_image& image;

  bool object(long long x, long long y) const {
    return x >= 0 && y >= 0 && x < static_cast<long long>(image.width) && y < static_cast<long long>(image.height) &&
           image.pixels[static_cast<std::size_t>(y) * image.width + static_cast<std::size_t>(x)] != 0;
  }
  bool boundary(long long x, long long y) const {
    if (!object(x, y)) return false;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (!object(x + dx, y + dy)) return true;
    return false;
  }
  std::vector<std::uint8_t> boundary_mask() const {
    std::vector<std::uint8_t> mask(image.pixels.size(), 0);
    for (std::size_t y = 0; y < image.height; ++y)
      for (std::size_t x = 0; x < image.width; ++x) mask[y * image.width + x] = boundary(static_cast<long long>(x), static_cast<long long>(y));
    return mask;
  }
  std::size_t at(const Pixel& p) const { return static_cast<std::size_t>(p.second) * image.width + static_cast<std::size_t>(p.first); }
};

// The smallest integer t with t >= radius², by exact rational comparisons.
long long exact_threshold(double radius) {
  const CGAL::Exact_rational square = CGAL::Exact_rational(radius) * CGAL::Exact_rational(radius);
  long long t = std::max(0LL, static_cast<long long>(radius * radius) - 2);
  while (t > 0 && CGAL::Exact_rational(static_cast<long>(t - 1)) >= square) --t;
  while (CGAL::Exact_rational(static_cast<long>(t)) < square) ++t;
  return t;
}

void check_boundary(const Oracle& oracle, const std::vector<std::uint8_t>& mask) {
  const auto found = geometry::boundary_pixels(oracle.image);
  std::size_t expected = 0;
  for (const auto m : mask) expected += m;
  FUZZ_CHECK(found.size() == expected, "boundary_pixels finds every object pixel with a background 8-neighbour");
  for (std::size_t i = 0; i < found.size(); ++i) {
    FUZZ_CHECK(mask[oracle.at(found[i])], "boundary_pixels finds only boundary pixels");
    FUZZ_CHECK(i == 0 || oracle.at(found[i - 1]) < oracle.at(found[i]), "boundary_pixels lists them in row-major order");
  }
  std::vector<std::uint8_t> on_loop(mask.size(), 0);
  for (const auto& loop : geometry::boundary_contours(oracle.image)) {
    FUZZ_CHECK(!loop.empty(), "a boundary loop passes a pixel");
    for (std::size_t k = 0; k < loop.size(); ++k) {
      FUZZ_CHECK(oracle.boundary(loop[k].first, loop[k].second), "a loop passes boundary pixels only");
      on_loop[oracle.at(loop[k])] = 1;
      const Pixel& next = loop[(k + 1) % loop.size()];
      const long long dx = next.first - loop[k].first, dy = next.second - loop[k].second;
      FUZZ_CHECK(loop.size() == 1 || (dx * dx + dy * dy >= 1 && dx * dx + dy * dy <= 2),
                 "consecutive loop pixels are distinct 8-neighbours");
    }
  }
  FUZZ_CHECK(on_loop == mask, "every boundary pixel lies on a loop");
}

void check_sampling(const Oracle& oracle, const std::vector<std::uint8_t>& mask, double radius, std::uint64_t seed) {
  const auto result = geometry::sample_image_boundary(oracle.image, radius, seed);
  const auto& sample = result.sample;
  const std::size_t n = sample.size();
  FUZZ_CHECK(result.pixels.size() == n && sample.lfs.size() == n && sample.labels.size() == n && sample.locations.size() == n,
             "per-point data for every point");
  const long long threshold = exact_threshold(radius);
  std::vector<std::uint8_t> sampled(mask.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [x, y] = result.pixels[i];
    FUZZ_CHECK(oracle.boundary(x, y), "every sample is a boundary pixel");
    FUZZ_CHECK(!sampled[oracle.at(result.pixels[i])], "no pixel is sampled twice");
    sampled[oracle.at(result.pixels[i])] = 1;
    FUZZ_CHECK(sample.points[i] == geometry::Point(x + 0.5, static_cast<double>(oracle.image.height) - y - 0.5),
               "a point is its pixel's centre, y up");
  }
  // Both distance laws by scanning the disc's bounding square around each pixel.
  const long long reach = static_cast<long long>(std::ceil(std::min(radius, 1e6)));
  const auto sample_closer_than_r = [&](long long x, long long y, bool skip_self) {
    for (long long dy = -reach; dy <= reach; ++dy)
      for (long long dx = -reach; dx <= reach; ++dx) {
        if ((dx == 0 && dy == 0 && skip_self) || dx * dx + dy * dy >= threshold) continue;
        if (oracle.object(x + dx, y + dy) && sampled[static_cast<std::size_t>(y + dy) * oracle.image.width + static_cast<std::size_t>(x + dx)])
          return true;
      }
    return false;
  };
  for (const auto& [x, y] : result.pixels)
    FUZZ_CHECK(!sample_closer_than_r(x, y, true), "samples are pairwise at least r apart");
  for (std::size_t y = 0; y < oracle.image.height; ++y)
    for (std::size_t x = 0; x < oracle.image.width; ++x)
      if (mask[y * oracle.image.width + x])
        FUZZ_CHECK(sample_closer_than_r(static_cast<long long>(x), static_cast<long long>(y), false),
                   "every boundary pixel is closer than r to a sample");

  std::vector<geometry::Edge> expected;
  std::size_t first = 0;
  for (const std::size_t count : result.loop_sizes) {
    FUZZ_CHECK(count > 0, "only loops with samples are listed");
    for (std::size_t i = first; i + 1 < first + count; ++i) expected.emplace_back(i, i + 1);
    if (count >= 3) expected.emplace_back(first + count - 1, first);
    first += count;
  }
  FUZZ_CHECK(first == n && sample.edges == expected, "the ground truth is a chain per loop, closed from 3 samples");
  FUZZ_CHECK(geometry::sample_image_boundary(oracle.image, radius, seed).sample.points == sample.points,
             "the same seed gives the same points");
}

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return hash;
}

}  // namespace
}  // namespace curvebench::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvebench;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  geometry::Binary_image image;
  try {
    image = geometry::parse_netpbm(bytes, "fuzz.pnm");
  } catch (const geometry::ParseError& error) {
    FUZZ_CHECK(std::string_view(error.what()).starts_with("fuzz.pnm:"), "errors name the input");
    return 0;
  }
  FUZZ_CHECK(image.pixels.size() == image.width * image.height, "one value per pixel");
  FUZZ_CHECK(std::all_of(image.pixels.begin(), image.pixels.end(), [](std::uint8_t v) { return v <= 1; }), "pixels are 0 or 1");
  std::ostringstream written;
  geometry::write_pgm(image, written);
  FUZZ_CHECK(geometry::parse_netpbm(written.str(), "written.pgm") == image, "write_pgm then parse_netpbm gives the same image");

  if (image.width > fuzz::max_side || image.height > fuzz::max_side) return 0;
  const fuzz::Oracle oracle{image};
  const auto mask = oracle.boundary_mask();
  fuzz::check_boundary(oracle, mask);
  const std::uint64_t hash = fuzz::fnv1a(bytes);
  for (const double radius : {1.0, 1.5, static_cast<double>(hash % 1200 + 1) / 197.0})
    fuzz::check_sampling(oracle, mask, radius, hash >> 16);
  return 0;
}
