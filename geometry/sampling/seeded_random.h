// The random numbers behind every seeded sampler and noise model (survey, "Robustness to
// Noise" and "Outliers"): std::mt19937_64 (its output sequence is fixed by the C++
// standard) mapped to doubles by our own arithmetic, never by
// std::uniform_real_distribution or std::normal_distribution, whose algorithms the
// standard leaves to each library. The same seed gives the same bits everywhere.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// A seeded source of doubles that is bit-identical on every platform (see above).
class Seeded_random {
 public:
  // The sequence of std::mt19937_64 seeded with `seed`.
  explicit Seeded_random(std::uint64_t seed) : engine_(seed) {}

  // The top 53 bits of the next 64-bit output, as a double in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // low + (high - low) uniform(): in [low, high) up to rounding.
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  // A unit vector of uniformly random direction: a point drawn uniformly in the unit disc
  // by rejection, normalised with sqrt (correctly rounded, unlike sin and cos).
  Vector direction() {
    for (;;) {
      const double x = uniform(-1, 1), y = uniform(-1, 1), squared = x * x + y * y;
      if (squared <= 1 && squared > 0x1.0p-40) return Vector(x, y) / std::sqrt(squared);
    }
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace curvebench::geometry
