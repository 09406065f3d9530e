// The cubic Bézier piece: SVG paths and font outlines (cubic, and quadratic elevated to
// cubic) are chains of them, and the survey's sampling tool ("Sampling Tools") and its
// bunny data set work on cubic Bézier curves.
//
// The curve model needs regular pieces, and drawing programs often write a control point
// on its end point (Inkscape's "c 0,0 ..."), where B'(t) = 0. append_cubic_bezier() turns
// any four control points into regular pieces covering the same point set.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// The cubic Bézier curve B(u) = Σ (3 choose i) (1-u)^(3-i) u^i p_i of four control points
// as a Curve_piece, t in [0, 1] from p0 to p3.
class Cubic_bezier final : public Curve_piece {
 public:
  // Requires that the control points are not all collinear (append_cubic_bezier() turns
  // those into Line_segments). At an end whose control point coincides with the end point,
  // the piece is B(√u) (start) or B(1 - √(1-u)) (end) instead of B(u): the same points,
  // a non-zero derivative at that end (3 (p2 - p0), resp. 3 (p3 - p1)), and a second
  // derivative that grows like 1/√u towards it, as the curvature there is unbounded.
  explicit Cubic_bezier(const std::array<Point, 4>& control);

  // The four control points as given to the constructor, p0 first.
  const std::array<Point, 4>& control_points() const { return control_; }
  // B(t); with a degenerate end, B at the reparametrised value (see the constructor).
  Point point(double t) const override;
  // B'(t); with a degenerate end, that of the reparametrised piece, non-zero at that end.
  Vector derivative(double t) const override;
  // B''(t); with a degenerate end, that of the reparametrised piece, which grows like 1/√u
  // towards that end and stays finite at the end itself.
  Vector second_derivative(double t) const override;

 private:
  std::array<Point, 4> control_;
  std::array<Point, 4> oriented_;  // control_, reversed if the degenerate end is the last
  bool reversed_ = false;           // the piece is oriented_ traversed backwards
  bool degenerate_start_ = false;   // oriented_[1] == oriented_[0]: reparametrised by √u
};

// Appends pieces tracing the cubic with these control points: nothing if all four
// coincide; if they are collinear, the Line_segments between the points where it turns
// back; otherwise one Cubic_bezier, or two joined at a cusp (where B' vanishes inside,
// to within 1e-12 of the control points' extent), which is then a corner of the curve.
void append_cubic_bezier(std::vector<std::shared_ptr<const Curve_piece>>& pieces, const std::array<Point, 4>& control);

// The cubic control points of the quadratic Bézier (p0, c, p1): the same curve.
std::array<Point, 4> elevate_quadratic_bezier(const Point& p0, const Point& c, const Point& p1);

}  // namespace curvebench::geometry
