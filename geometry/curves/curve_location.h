// A place on a Curve: which component, and the parameter s in [0, piece_count()] along it
// (survey, "Definitions and Notations": a curve is one or several components). Samplers
// record where each point was drawn; lfs, sharp points and measures report where they are.
#pragma once

#include <cstddef>
#include <limits>

namespace curvebench::geometry {

// Where on a Curve a point lies, or Curve_location{} (no component) for one that is not
// on it.
struct Curve_location {
  // For a point that is not on the curve (an outlier): no component, parameter NaN.
  static constexpr std::size_t no_component = std::numeric_limits<std::size_t>::max();

  std::size_t component = no_component;  // index into Curve::components
  double parameter = std::numeric_limits<double>::quiet_NaN();  // s along that component

  // Memberwise; so two outlier locations compare unequal, as NaN != NaN.
  friend bool operator==(const Curve_location&, const Curve_location&) = default;
};

}  // namespace curvebench::geometry
