// Measuring a point sampling against its curve (survey, "Definitions and Notations" for
// epsilon and the reach, "Feature Size Criteria Reconstruction" for HNN-Crust's rho and
// "Guarantees as Sampling Conditions" for local uniformity): the numbers that the
// sampling-condition theorems are stated in, each with where it is attained.
//
// lfs comes from a geometry::Local_feature_size of the curve; below `minimum_lfs` it
// counts as `minimum_lfs` (pass Sample::minimum_lfs to measure with the sampler's floor;
// 0 measures the true ratios, infinite near a sharp point that is not a sample).
#pragma once

#include <span>

#include "geometry/curves/curve_location.h"
#include "geometry/edge.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sample.h"

namespace curvebench::certify {

using geometry::Curve_location;
using geometry::Edge;
using geometry::Point;

// A sampling's epsilon and where it is attained.
struct Epsilon_measure {
  double epsilon = 0;     // sup over the curve of distance to the nearest point / lfs
  Curve_location where;   // the curve point where it is attained
};

// The smallest epsilon for which `points` is an epsilon-sampling of the curve, searched
// along every component on the lfs grid and polished (curve_search.h). 0 for no curve;
// +infinity for no points.
Epsilon_measure measure_epsilon(const geometry::Local_feature_size& lfs, std::span<const Point> points,
                                double minimum_lfs);

// A sampling's rho (HNN-Crust's) and where it is attained.
struct Rho_measure {
  double rho = 0;        // max over ground-truth edges of (|edge| / 2) / reach(interval)
  Edge edge{0, 0};       // the edge where it is attained
  double reach = 0;      // the reach of its interval (floored)
  Curve_location where;  // where that reach is attained
};

// HNN-Crust's rho (see geometry/sampling/sampling.h): over the sample's edges between curve points
// of one component; an edge (i, j) stands for the interval from i's location forward
// along the curve to j's (Sample's orientation).
Rho_measure measure_rho(const geometry::Local_feature_size& lfs, const geometry::Sample& sample, double minimum_lfs);

// A sampling's local uniformity and where it is attained.
struct Uniformity_measure {
  double uniformity = 1;  // max over points of degree 2 of longer / shorter incident edge
  std::size_t point = 0;  // where it is attained
};

// Local uniformity u over the ground-truth edges; +infinity where an incident edge has
// length 0, 1 if no point has two edges.
Uniformity_measure measure_uniformity(std::span<const Point> points, std::span<const Edge> edges);

// The three measures of one sample (measure_sampling).
struct Sampling_measure {
  Epsilon_measure epsilon;        // over all the sample's points
  Rho_measure rho;                // over its ground-truth edges
  Uniformity_measure uniformity;  // over its ground-truth edges
};

// All three, epsilon over all the sample's points, with the sample's own lfs floor.
Sampling_measure measure_sampling(const geometry::Local_feature_size& lfs, const geometry::Sample& sample);

}  // namespace curvebench::certify
