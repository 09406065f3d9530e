// A point sampling of a Curve with everything known about it: the ground truth that
// reconstructions are scored against and the sampling measures read (survey, "Sampling
// Tools"). Points of component c come in order along c, so the ground-truth edges are the
// chain i -> i+1, oriented along the curve, plus the closing edge of a closed component of
// three points or more. Outliers (survey, "Outliers") are in no edge.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/curves/curve_location.h"
#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::geometry {

enum class Sample_label : std::uint8_t { curve_point, outlier };

struct Sample {
  std::vector<Point> points;
  std::vector<Edge> edges;
  // Per point: lfs at the curve point it was drawn from (NaN for an outlier), that curve
  // point's location (Curve_location{} for an outlier), and its label. Noise moves a point
  // but keeps these.
  std::vector<double> lfs;
  std::vector<Curve_location> locations;
  std::vector<Sample_label> labels;
  // The lfs floor the sampler used (0 if none), and the points where lfs was below it, so
  // that their spacing was set by the floor rather than by lfs (near sharp points).
  double minimum_lfs = 0;
  std::vector<std::size_t> floored;

  std::size_t size() const { return points.size(); }
};

}  // namespace curvebench::geometry
