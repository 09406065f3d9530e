// A RapidCheck generator of doubles for properties that must hold over the whole range
// of finite doubles, not only the moderate values rc::gen::arbitrary<double>() draws.
#pragma once

#include <rapidcheck.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace curvebench::testing {

// Any finite double, drawn by bit pattern so that all magnitudes (subnormals up to
// 1.8e308) come up, plus the values that are most likely to be mishandled.
inline rc::Gen<double> finite_double() {
  const double min_normal = std::numeric_limits<double>::min();
  const double min_subnormal = std::numeric_limits<double>::denorm_min();
  const double max = std::numeric_limits<double>::max();
  return rc::gen::oneOf(
      rc::gen::element(0.0, -0.0, 1e300, -1e300, 1e-300, -1e-300, min_normal, min_subnormal,
                       -min_subnormal, 3 * min_subnormal, max, -max, 0.1, 1.0 / 3),
      rc::gen::suchThat(
          rc::gen::map(rc::gen::arbitrary<std::uint64_t>(),
                       [](std::uint64_t bits) { return std::bit_cast<double>(bits); }),
          [](double x) { return std::isfinite(x); }));
}

}  // namespace curvebench::testing
