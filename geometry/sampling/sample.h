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

// What a point of a Sample is: drawn from the curve (then perhaps moved by noise), or an
// outlier added off it (survey, "Outliers").
enum class Sample_label : std::uint8_t { curve_point, outlier };

// A sampling with its ground truth (see above). The per-point vectors all have size()
// entries, in the order of `points`.
struct Sample {
  std::vector<Point> points;  // the samples, each component's in order along it; outliers last
  std::vector<Edge> edges;    // the ground truth: indices into `points`
  // Per point: lfs at the curve point it was drawn from (NaN for an outlier), that curve
  // point's location (Curve_location{} for an outlier), and its label. Noise moves a point
  // but keeps these.
  std::vector<double> lfs;
  std::vector<Curve_location> locations;  // where each point was drawn on the curve
  std::vector<Sample_label> labels;       // curve point or outlier, per point
  // The lfs floor the sampler used (0 if none), and the points where lfs was below it, so
  // that their spacing was set by the floor rather than by lfs (near sharp points).
  double minimum_lfs = 0;
  std::vector<std::size_t> floored;  // indices into `points` where lfs < minimum_lfs

  // The number of points, outliers included.
  std::size_t size() const { return points.size(); }
};

}  // namespace curvebench::geometry
