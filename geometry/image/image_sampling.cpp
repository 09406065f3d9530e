#include "geometry/image/image_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "geometry/sampling/seeded_random.h"

namespace curvebench::geometry {
namespace {

void require_consistent(const Binary_image& image) {
  if (image.width != 0 && image.height > max_image_pixels / image.width)
    throw std::invalid_argument("image sampling: more than 2^28 pixels");
  if (image.pixels.size() != image.width * image.height)
    throw std::invalid_argument("image sampling: " + std::to_string(image.pixels.size()) + " pixels for a " +
                                std::to_string(image.width) + " x " + std::to_string(image.height) + " image");
}

// The image with everything outside it background.
class Object {
 public:
  explicit Object(const Binary_image& image) : image_(image) {}
  bool operator()(long long x, long long y) const {
    return x >= 0 && y >= 0 && x < static_cast<long long>(image_.width) && y < static_cast<long long>(image_.height) &&
           image_.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y));
  }
  bool operator()(const Pixel& p) const { return (*this)(p.first, p.second); }

 private:
  const Binary_image& image_;
};

// Boundary pixels by position: their row-major keys, sorted as boundary_pixels lists them.
class Pixel_index {
 public:
  Pixel_index(const std::vector<Pixel>& pixels, std::size_t width) : width_(width) {
    keys_.reserve(pixels.size());
    for (const Pixel& p : pixels) keys_.push_back(key(p));
  }
  // The position of `p` in the list, or size() if it is not in it.
  std::size_t find(const Pixel& p) const {
    const auto it = std::lower_bound(keys_.begin(), keys_.end(), key(p));
    return it != keys_.end() && *it == key(p) ? static_cast<std::size_t>(it - keys_.begin()) : keys_.size();
  }
  std::size_t size() const { return keys_.size(); }
  // The positions [first, last) of the listed pixels in row y from column x0 to x1, all at
  // or after position `from`: a galloping search from there, so that scanning the rows of
  // a disc in order stays near its centre in memory.
  std::pair<std::size_t, std::size_t> span(long long y, long long x0, long long x1, std::size_t from) const {
    const std::size_t first = gallop(from, key(y, x0)), last = gallop(first, key(y, x1) + 1);
    return {first, last};
  }

  // The first position at or after `from` whose key is >= target, given that none before
  // `from` is.
  std::size_t gallop(std::size_t from, std::uint64_t target) const {
    std::size_t step = 1;
    while (from + step < keys_.size() && keys_[from + step] < target) step *= 2;
    const auto begin = keys_.begin() + static_cast<std::ptrdiff_t>(from + step / 2);
    const auto end = keys_.begin() + static_cast<std::ptrdiff_t>(std::min(from + step, keys_.size()));
    return static_cast<std::size_t>(std::lower_bound(begin, end, target) - keys_.begin());
  }
  // The first position whose key is >= target, given that the key at `to` is (or `to` is
  // the end): a galloping search backwards from `to`.
  std::size_t gallop_back(std::size_t to, std::uint64_t target) const {
    std::size_t step = 1;
    while (step <= to && keys_[to - step] >= target) step *= 2;
    const auto begin = keys_.begin() + static_cast<std::ptrdiff_t>(to - std::min(step, to));
    const auto end = keys_.begin() + static_cast<std::ptrdiff_t>(to - step / 2);
    return static_cast<std::size_t>(std::lower_bound(begin, end, target) - keys_.begin());
  }
  std::uint64_t key(long long y, long long x) const {
    return static_cast<std::uint64_t>(y) * width_ + static_cast<std::uint64_t>(x);
  }
  std::uint64_t key(const Pixel& p) const { return key(p.second, p.first); }

 private:
  std::vector<std::uint64_t> keys_;
  std::uint64_t width_;
};

// Crack edges leave a lattice vertex (X, Y) (the corner shared by pixels (X - 1, Y - 1) to
// (X, Y)) in one of four directions, numbered so that +1 turns right as drawn (y down).
enum Direction { east, south, west, north };
constexpr int step_x[4] = {1, 0, -1, 0}, step_y[4] = {0, 1, 0, -1};
// The pixels on the left (object) and right (background) of the edge leaving (X, Y) in
// each direction, as offsets from (X, Y).
constexpr int left_x[4] = {0, 0, -1, -1}, left_y[4] = {-1, 0, 0, -1};
constexpr int right_x[4] = {0, -1, -1, 0}, right_y[4] = {0, 0, -1, -1};

class Crack_tracer {
 public:
  explicit Crack_tracer(const Binary_image& image) : object_(image) {}

  bool edge(long long x, long long y, int d) const {
    return object_(x + left_x[d], y + left_y[d]) && !object_(x + right_x[d], y + right_y[d]);
  }
  Pixel left(long long x, long long y, int d) const {
    return {static_cast<int>(x + left_x[d]), static_cast<int>(y + left_y[d])};
  }
  bool object(const Pixel& p) const { return object_(p); }

 private:
  Object object_;
};

}  // namespace

std::vector<Pixel> boundary_pixels(const Binary_image& image) {
  require_consistent(image);
  const Object object(image);
  std::vector<Pixel> found;
  if (image.pixels.empty()) return found;  // not even the rows of a 0 x 2^28 image
  for (long long y = 0; y < static_cast<long long>(image.height); ++y)
    for (long long x = 0; x < static_cast<long long>(image.width); ++x) {
      if (!object(x, y)) continue;
      bool boundary = false;
      for (int dy = -1; dy <= 1 && !boundary; ++dy)
        for (int dx = -1; dx <= 1 && !boundary; ++dx) boundary = !object(x + dx, y + dy);
      if (boundary) found.emplace_back(static_cast<int>(x), static_cast<int>(y));
    }
  return found;
}

std::vector<std::vector<Pixel>> boundary_contours(const Binary_image& image) {
  const std::vector<Pixel> boundary = boundary_pixels(image);
  const Pixel_index index(boundary, image.width);
  const Crack_tracer crack(image);
  // Which of the four sides of each boundary pixel (named by the direction of its crack
  // edge, the pixel on its left) a loop has passed.
  std::vector<std::uint8_t> passed(boundary.size(), 0);
  std::vector<std::vector<Pixel>> loops;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    for (int d0 = east; d0 <= north; ++d0) {
      const long long x0 = boundary[i].first - left_x[d0], y0 = boundary[i].second - left_y[d0];
      if ((passed[i] >> d0 & 1) || !crack.edge(x0, y0, d0)) continue;
      std::vector<Pixel> loop;
      long long x = x0, y = y0;
      int d = d0;
      // Each vertex pairs its incoming edges with its outgoing ones one to one (at a saddle,
      // two of each: turning right keeps the diagonal object pixels together), so the walk
      // returns to its first edge; the bound only guards against a broken invariant.
      for (std::size_t steps = 0;; ++steps) {
        if (steps > 4 * boundary.size()) throw std::logic_error("boundary_contours: a crack loop does not close");
        const Pixel beside = crack.left(x, y, d);
        passed[index.find(beside)] |= static_cast<std::uint8_t>(1 << d);
        loop.push_back(beside);
        x += step_x[d], y += step_y[d];
        const int right = (d + 1) % 4;
        if (crack.edge(x, y, right)) {
          // A right turn goes around a background pixel: at a concave corner the object
          // pixel ahead-left is the corner pixel, a boundary pixel through its diagonal.
          if (const Pixel corner = crack.left(x, y, d); crack.object(corner)) loop.push_back(corner);
          d = right;
        } else if (!crack.edge(x, y, d)) {
          d = (d + 3) % 4;
        }
        if (x == x0 && y == y0 && d == d0) break;
      }
      loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
      while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
      loops.push_back(std::move(loop));
    }
  }
  return loops;
}

std::uint64_t erasure_threshold(double radius) {
  if (!(radius > 0)) throw std::invalid_argument("image sampling: the radius must be positive");
  if (radius <= 1) return 1;  // n < radius² <= 1 only for n = 0
  radius = std::min(radius, 0x1p29);
  // p + e = radius² exactly (the error of a product is a double, and fma computes it
  // with one rounding); p >= 1 so e does not underflow.
  const double p = radius * radius, e = std::fma(radius, radius, -p);
  // If p is not an integer, the nearest integers are at least ulp(p) away from p and
  // |e| <= ulp(p) / 2, so ceil(radius²) = ceil(p); if it is, ceil(radius²) = p + ceil(e).
  if (p != std::floor(p)) return static_cast<std::uint64_t>(std::ceil(p));
  return static_cast<std::uint64_t>(static_cast<long long>(p) + static_cast<long long>(std::ceil(e)));
}

Image_sample sample_image_boundary(const Binary_image& image, double radius, std::uint64_t seed,
                                   const Raster_frame* frame) {
  const std::uint64_t threshold = erasure_threshold(radius);
  const std::vector<Pixel> boundary = boundary_pixels(image);
  const std::size_t n = boundary.size();
  Image_sample result;
  if (n == 0) return result;

  // A random order: Fisher-Yates, j = floor(u (i + 1)) with u in [0, 1) from Seeded_random
  // (exact IEEE arithmetic, so the same on every machine; the bias of this mapping is
  // below 2^-25 for the at most 2^28 pixels).
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  Seeded_random random(seed);
  for (std::size_t i = n; i-- > 1;)
    std::swap(order[i], order[std::min(i, static_cast<std::size_t>(random.uniform() * static_cast<double>(i + 1)))]);

  // The erasure disc row by row: rows are the buckets of the boundary pixels (they are
  // sorted row-major), and in row p.y + dy the disc is the run |dx| <= half_width(dy²),
  // found by binary search. So a sample costs O(radius log n) plus the pixels it erases,
  // and no memory beyond the pixels' keys.
  const Pixel_index index(boundary, image.width);
  const std::uint64_t largest = threshold - 1;  // the largest dx² + dy² erased
  const auto half_width = [](std::uint64_t v) {   // floor(sqrt(v)), exactly
    auto root = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(v)));
    while (root * root > v) --root;
    while ((root + 1) * (root + 1) <= v) ++root;
    return static_cast<long long>(root);
  };
  const long long reach = half_width(largest);
  const long long last_row = static_cast<long long>(image.height) - 1, last_column = static_cast<long long>(image.width) - 1;
  std::vector<std::uint8_t> erased(n, 0);
  std::vector<std::size_t> picked;
  for (const std::size_t k : order) {
    if (erased[k]) continue;
    picked.push_back(k);
    const long long px = boundary[k].first, py = boundary[k].second;
    const long long top = std::max(0LL, py - reach);
    std::size_t from = index.gallop_back(k, index.key(top, 0));  // the first pixel of the disc's top row or later
    for (long long y = top; y <= std::min(last_row, py + reach); ++y) {
      const auto dy = static_cast<std::uint64_t>(y > py ? y - py : py - y);
      const long long dx = half_width(largest - dy * dy);
      const auto [first, last] = index.span(y, std::max(0LL, px - dx), std::min(last_column, px + dx), from);
      std::fill(erased.begin() + static_cast<std::ptrdiff_t>(first), erased.begin() + static_cast<std::ptrdiff_t>(last), 1);
      from = last;
    }
  }

  // Ground truth: the picked pixels in the order the boundary loops pass them.
  std::vector<std::size_t> sample_of(n, std::numeric_limits<std::size_t>::max());
  for (std::size_t s = 0; s < picked.size(); ++s) sample_of[picked[s]] = s;
  std::vector<std::uint8_t> placed(picked.size(), 0);
  Sample& sample = result.sample;
  for (const auto& loop : boundary_contours(image)) {
    const std::size_t first = sample.points.size();
    for (const Pixel& p : loop) {
      const std::size_t s = sample_of[index.find(p)];
      if (s == std::numeric_limits<std::size_t>::max() || placed[s]) continue;
      placed[s] = 1;
      result.pixels.push_back(p);
      const double u = p.first + 0.5, v = p.second + 0.5;
      sample.points.push_back(frame ? frame->to_curve(u, v) : Point(u, static_cast<double>(image.height) - v));
    }
    const std::size_t count = sample.points.size() - first;
    if (count == 0) continue;
    result.loop_sizes.push_back(count);
    for (std::size_t i = first; i + 1 < first + count; ++i) sample.edges.emplace_back(i, i + 1);
    if (count >= 3) sample.edges.emplace_back(first + count - 1, first);
  }
  if (sample.points.size() != picked.size())
    throw std::logic_error("sample_image_boundary: a sampled pixel lies on no boundary loop");
  sample.lfs.assign(sample.size(), std::numeric_limits<double>::quiet_NaN());
  sample.locations.assign(sample.size(), Curve_location{});
  sample.labels.assign(sample.size(), Sample_label::curve_point);
  return result;
}

}  // namespace curvebench::geometry
