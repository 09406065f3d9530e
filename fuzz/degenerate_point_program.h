// The decoder of the proximity-graph fuzzer: it reads the fuzzer's bytes as a short
// program that draws points, so that random mutations land on the inputs exact
// geometry finds hard (duplicates, collinear runs, cocircular lattice points, points one
// ulp apart, coordinates near 1e-300 or 1e300) far more often than random doubles would.
//
// Each instruction is an opcode byte (taken mod 8) and its operand bytes:
//   0 g       point (g % 16 - 8, g / 16 - 8) of a 16 x 16 grid
//   1 x y     point (x, y) of a 256 x 256 grid, x and y as signed bytes
//   2 c s     lattice point on a circle around grid point c (as in 0): radius 5, 25 or 65,
//             so every such circle holds 12 to 36 exactly cocircular integer points
//   3 i       copy of the earlier point i (mod count)
//   4 m       collinear run: m % 8 + 1 points continuing the last two a, b with 2b - a
//   5 i d     an earlier point moved one ulp in direction d % 8 (of the 8 neighbours)
//   6 16 raw  a point of two raw doubles (skipped unless both are finite)
//   7 t ...   sets the scale or shift of later grid and lattice points (x -> scale x +
//             shift): t % 4 = 0: scale 2^e with e from 2 more bytes, in [-1000, 1000];
//             1: scale 1e300; 2: scale 1e-300; 3: shift by 2^e (a, b) from 3 more bytes:
//             a, b signed, e in [0, 255]. Powers of two keep degeneracies exact.
// Multi-byte operands are little-endian.
// Points that come out non-finite are skipped. Decoding stops at the end of the input
// or at `max_points` points; duplicates are kept, for geometry::PointSet to merge.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "geometry/kernel.h"

namespace curvebench::fuzz {

using geometry::Point;

namespace degenerate_point_program {

// (a, b) with a^2 + b^2 = r^2 for r = 5, 25, 65: each with its 8 sign and order
// variants gives every integer point of the circle (the axis points several times).
constexpr std::array<std::pair<int, int>, 10> circle_lattice = {{
    {5, 0}, {3, 4},                                   // r = 5
    {25, 0}, {7, 24}, {15, 20},                       // r = 25
    {65, 0}, {16, 63}, {25, 60}, {33, 56}, {39, 52},  // r = 65
}};

inline std::pair<int, int> small_grid_point(std::uint8_t g) { return {g % 16 - 8, g / 16 - 8}; }

inline std::pair<int, int> circle_point(std::uint8_t center, std::uint8_t selector) {
  const auto [cx, cy] = small_grid_point(center);
  auto [a, b] = circle_lattice[selector % circle_lattice.size()];
  const unsigned variant = selector / circle_lattice.size() % 8;
  if (variant & 4) std::swap(a, b);
  return {cx + (variant & 1 ? -a : a), cy + (variant & 2 ? -b : b)};
}

// p moved by one ulp towards neighbour `direction` (< 8) of the 8 around it; 8 stays put.
inline Point one_ulp_away(const Point& p, unsigned direction) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  constexpr int steps[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {0, 0}};
  const auto step = [](double v, int s) { return s == 0 ? v : std::nextafter(v, s * infinity); };
  const auto [sx, sy] = steps[direction];
  return {step(p.x(), sx), step(p.y(), sy)};
}

class Decoder {
 public:
  Decoder(Fuzz_input& input, std::size_t max_points) : input_(input), max_points_(max_points) {}

  std::vector<Point> run() {
    while (!input_.exhausted() && points_.size() < max_points_) step();
    return std::move(points_);
  }

 private:
  void step() {
    switch (input_.byte() % 8) {
      case 0: return add_transformed(small_grid_point(input_.byte()));
      case 1: {
        const auto x = input_.raw<std::int8_t>();
        return add_transformed({x, input_.raw<std::int8_t>()});
      }
      case 2: {
        const std::uint8_t center = input_.byte();
        return add_transformed(circle_point(center, input_.byte()));
      }
      case 3: return add_earlier(input_.byte(), 8);
      case 4: return add_collinear_run(input_.byte() % 8 + 1);
      case 5: {
        const std::uint8_t i = input_.byte();
        return add_earlier(i, input_.byte() % 8);
      }
      case 6: {
        const auto x = input_.raw<double>();
        return add({x, input_.raw<double>()});
      }
      default: return set_transform();
    }
  }

  void add(const Point& p) {
    if (std::isfinite(p.x()) && std::isfinite(p.y())) points_.push_back(p);
  }

  void add_transformed(std::pair<int, int> grid) {
    add({scale_ * grid.first + shift_x_, scale_ * grid.second + shift_y_});
  }

  void add_earlier(std::uint8_t i, unsigned ulp_direction) {
    if (!points_.empty()) add(one_ulp_away(points_[i % points_.size()], ulp_direction));
  }

  void add_collinear_run(int length) {
    for (int i = 0; i < length && points_.size() >= 2 && points_.size() < max_points_; ++i) {
      const Point& a = points_[points_.size() - 2];
      const Point& b = points_.back();
      add({2 * b.x() - a.x(), 2 * b.y() - a.y()});
    }
  }

  void set_transform() {
    switch (input_.byte() % 4) {
      case 0: scale_ = std::ldexp(1.0, input_.raw<std::uint16_t>() % 2001 - 1000); return;
      case 1: scale_ = 1e300; return;
      case 2: scale_ = 1e-300; return;
      default: {
        const auto a = input_.raw<std::int8_t>();
        const auto b = input_.raw<std::int8_t>();
        const int e = input_.byte();
        shift_x_ = std::ldexp(a, e);
        shift_y_ = std::ldexp(b, e);
      }
    }
  }

  Fuzz_input& input_;
  std::size_t max_points_;
  std::vector<Point> points_;
  double scale_ = 1, shift_x_ = 0, shift_y_ = 0;
};

}  // namespace degenerate_point_program

// Runs the program in `input` (see above): at most `max_points` points, duplicates kept.
inline std::vector<Point> decode_degenerate_points(Fuzz_input& input, std::size_t max_points) {
  return degenerate_point_program::Decoder(input, max_points).run();
}

}  // namespace curvebench::fuzz
