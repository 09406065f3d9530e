// The medial axis of a curve (survey, "Definitions and Notations": the closure of the
// points of the plane with two or more closest points on the curve), estimated as the
// Voronoi vertices of a dense point sample of the curve, i.e. the circumcenters of its
// Delaunay triangles. In the plane these converge to the medial axis, inner and outer
// parts alike, as the sample gets denser (Amenta, Bern, Eppstein 1998); all are kept.
//
// Vertices alone miss a medial edge that runs far from any vertex: across the gap between
// the two ends of an open curve the medial axis is the bisector of the two ends, a Voronoi
// edge whose vertices can be far from the ends, or a ray to infinity (on a circle's arc all
// circumcenters are the centre, and its ends' lfs, half the gap's chord, was measured as
// the radius). So a Voronoi edge dual to a Delaunay edge pq between two samples that are
// not neighbours along a component, and that comes nearer to p and q than every vertex
// does, is kept as points |pq| / 32 apart (a hull edge's ray up to |pq| past pq): about
// 5e-4 of lfs at a gap's ends. Elsewhere vertices are dense along the medial axis.
//
// Points of the medial axis' closure that a sample can only approach (sharp corners,
// crossings, the ends of branches at curvature maxima) are given exactly and added as
// they are. Local_feature_size builds the dense
// sample; this class only turns a sample into medial points and answers distances.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "geometry/kernel.h"
#include "geometry/lfs/nearest_point_index.h"

namespace curvebench::geometry {

// One component's run of the dense sample: its number of points, in order along it.
struct Sample_chain {
  std::size_t size = 0;  // its number of points
  bool closed = false;   // whether its last point neighbours its first
};

// The estimated medial axis as a set of points (see above), with a nearest-point index.
// Holds its own copy of the points.
class Medial_axis {
 public:
  // `curve_sample` holds the chains one after another. `exact_points` are medial points
  // known exactly (sharp points, branch ends), kept as they are. Throws
  // std::invalid_argument if the chains' sizes do not add up to curve_sample.size().
  Medial_axis(std::span<const Point> curve_sample, std::span<const Sample_chain> chains,
              std::span<const Point> exact_points);

  // The medial points: `exact_points` first, then the Voronoi vertices, then the points
  // along Voronoi edges.
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
