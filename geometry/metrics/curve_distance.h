// How far a reconstructed curve C' lies from the original C: the survey's "Evaluation
// Criteria". Both curves are edge chains (points + edges). Each is sampled uniformly and
// densely; every sample s of one curve is mapped to its closest point M(s) on the other
// (nearest_segment_index.h), in both directions (M : C -> C', M' : C' -> C, not inverse to
// each other), and
//   H_D   = max over both mappings of |s - M(s)|                  (Hausdorff),
//   RMS_D = sqrt(sum over both mappings of |s - M(s)|^2 / N)      (N samples in all).
// Samples sit at the midpoints of equal pieces of each edge, at most `spacing` long (but
// at most 4096 per edge), each weighted by its piece's length, so RMS_D is the arc-length
// mean that dense uniform samples approximate, whatever `spacing`; H_D also takes every
// edge's end points, where the largest distances of polylines often are.
//
// Metric values are output, never decisions: evaluated in double.
#pragma once

#include <span>

#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::geometry {

// An edge chain: edges index points.
// A view: the caller keeps the points and edges alive while it is used.
struct Polyline_view {
  std::span<const Point> points;  // the points that `edges` index
  std::span<const Edge> edges;    // pairs of indices into `points`
};

// The two distances of the survey's "Evaluation Criteria" between an original and a
// reconstruction, in the curves' units.
struct Curve_distance {
  double hausdorff = 0;  // H_D: the largest distance to the closest point, both ways
  double rms = 0;        // RMS_D: the arc-length root mean square of that distance, both ways
};

// 0 and 0 if neither curve has an edge; +infinity for both if only one has none. Throws
// std::invalid_argument if the two curves' squared extent overflows a double.
// `spacing` > 0 (a length); the default used by the benchmark is 1e-3 of the bounding-box
// diagonal of `original` (default_distance_spacing).
Curve_distance curve_distance(const Polyline_view& original, const Polyline_view& reconstruction, double spacing);

// One direction of the same mapping: the largest distance from a sample of `from` to its
// closest point on `to` (the directed Hausdorff distance) and the arc-length RMS of that
// distance over `from`. A simplifier's output (Optimal Transport) is measured both ways
// with it, since a few vertices far from the curve and a curve far from every vertex are
// different faults. An edge whose ends coincide is a point of its curve (an isolated
// vertex): it counts in the Hausdorff distance either way but weighs nothing in the RMS
// beside edges of positive length; if `from` has no length at all, its points weigh
// equally. 0 and 0 if `from` has no edge (nothing of it is far), else +infinity for both
// if `to` has none. Throws as curve_distance does.
Curve_distance one_way_curve_distance(const Polyline_view& from, const Polyline_view& to, double spacing);
// 1e-3 of the bounding-box diagonal of `original`'s points, or 1 if that is 0 or infinite.
double default_distance_spacing(const Polyline_view& original);

// The diagonal of the bounding box of a polyline's points (0 for none): the unit in which
// the benchmark reports distances.
double bounding_box_diagonal(const Polyline_view& polyline);

// The mean angle, in degrees in [0, 90], between each edge of `reconstruction` and the
// original's edge closest to its midpoint (the lines' angle, so the deviation of the
// normals, orientation ignored). 0 if `reconstruction` has no edge of positive length,
// NaN if `original` has none.
double normal_deviation_degrees(const Polyline_view& original, const Polyline_view& reconstruction);

}  // namespace curvebench::geometry
