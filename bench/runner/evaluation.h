// The survey's evaluation criteria ("Evaluation Criteria", "Qualitative Comparison") for
// one reconstruction: exact reconstruction, Hausdorff and RMS distance to the original
// curve, normal deviation, manifoldness and components.
#pragma once

#include <optional>

#include "geometry/metrics/curve_distance.h"
#include "geometry/metrics/curve_topology.h"

namespace curvebench::bench {

// How one reconstruction compares with the original (evaluate).
struct Evaluation {
  std::optional<bool> exact;               // edge set == ground truth; none without one
  // Hausdorff distance to the original, in the input's units; none without one.
  std::optional<double> hausdorff, rms;    // to the original; none without one
  std::optional<double> diagonal;          // of the original's bounding box (results.csv's unit)
  std::optional<double> normal_deviation;  // degrees
  geometry::Curve_topology topology;       // manifoldness and components of the reconstruction
  // A simplifier's output (its edges and isolated vertices) against the original, each of
  // the survey's two mappings alone ("Evaluation Criteria": D from the output, D' from the
  // curve); none for an interpolating algorithm or without an original.
  std::optional<geometry::Curve_distance> to_curve;    // D: from the output to the curve
  std::optional<geometry::Curve_distance> from_curve;  // D': from the curve to the output
};

// `reconstruction`'s and `truth`'s edges are canonical. `on_input_points`: the
// reconstruction's points are the input points that `truth` indexes (an interpolating
// algorithm); else its points are matched to the input points first (point_matching.h).
// Distances and normals are measured against `original` (the dense true curve) when
// given, else against `truth`. `simplifies`: the reconstruction is a simplifier's
// (algorithms::Algorithm::simplifies), whose points in no edge are output vertices too,
// and to_curve and from_curve are measured.
Evaluation evaluate(const geometry::Polyline_view& reconstruction, bool on_input_points,
                    const geometry::Polyline_view* truth, const geometry::Polyline_view* original,
                    bool simplifies = false);

}  // namespace curvebench::bench
