// The medial axis of a curve (survey, "Definitions and Notations": the closure of the
// points of the plane with two or more closest points on the curve), estimated as the
// Voronoi vertices of a dense point sample of the curve, i.e. the circumcenters of its
// Delaunay triangles. In the plane these converge to the medial axis, inner and outer
// parts alike, as the sample gets denser (Amenta, Bern, Eppstein 1998); all are kept.
//
// Points of the medial axis' closure that a sample can only approach (sharp corners,
// crossings) are given exactly and added as they are. Local_feature_size builds the dense
// sample; this class only turns a sample into medial points and answers distances.
#pragma once

#include <span>
#include <vector>

#include "geometry/kernel.h"
#include "geometry/lfs/nearest_point_index.h"

namespace curvebench::geometry {

class Medial_axis {
 public:
  Medial_axis(std::span<const Point> curve_sample, std::span<const Point> exact_points);

  std::span<const Point> points() const { return points_; }

  // Distance from p to the nearest medial point: lfs(p) for a curve point p. +infinity if
  // there is none (a sample with no Delaunay triangle: a straight segment).
  double distance(const Point& p) const { return index_.distance(p); }

 private:
  Medial_axis(std::vector<Point> points);
  std::vector<Point> points_;
  Nearest_point_index index_;
};

}  // namespace curvebench::geometry
