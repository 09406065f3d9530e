// Turns drawing commands (SVG path data, font outlines) into curve components, so that
// every path-like source treats degenerate input alike: the pieces of a curve must be
// regular and join (curve.h), while drawings contain zero-length segments, lone points,
// control points on end points, closing gaps and kinks left by rounding.
//
// Corners. A drawing program writes a node meant to be smooth with its two handles
// collinear, then rounds every coordinate (Inkscape: 6 digits), so the tangent turns there
// by a little (data/svg/: 1e-9 to 1.7e-3 rad). Taken as drawn, each is a sharp corner, where
// lfs is 0 and every sampling condition needs samples piling up. With a `corner_angle`, a
// join whose tangent turns by less than it is made exactly G1 before the pieces are made:
// the Bézier handle(s) that set the two tangents there are turned onto one line (the
// bisector of the two tangents, or the line segment's direction if one side is a line),
// each keeping its length. So the curve that is sampled, measured and scored is smooth
// there by construction, and lies within (4/9) |handle| * angle of the drawing (the
// largest Bernstein weight of an inner control point times its move). A join of two line
// segments has no handle to turn and stays a corner, and so does a join that a cubic with
// one free control point shares with its other end, if the point where both lines cross
// is farther than `corner_angle` times the handle lengths from where it was.
#pragma once

#include <vector>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// Subpaths as in SVG: move_to starts one, close() ends it closed (a later drawing command
// starts the next one at the same start point), move_to and finish() end it open. The
// pieces are made when a subpath ends: zero-length segments are dropped (and a subpath
// left without any segment with them), cubics become pieces by append_cubic_bezier().
class Path_builder {
 public:
  // Joins whose unit tangent turns by less than `corner_angle` radians are made smooth (see
  // above); 0, the default, keeps every join as drawn.
  Path_builder() = default;
  // A builder that smooths the joins turning by less than `corner_angle` radians.
  explicit Path_builder(double corner_angle) : corner_angle_(corner_angle) {}

  // Ends the current subpath open, if it has any segment, and starts one at p.
  void move_to(const Point& p);
  // A line segment from the current point to p, which becomes the current point. Before
  // the first move_to the current point is the origin.
  void line_to(const Point& p);
  void quadratic_to(const Point& control, const Point& p);  // elevated to a cubic
  // A cubic Bézier from the current point with these inner control points, ending at p.
  void cubic_to(const Point& control1, const Point& control2, const Point& p);
  // Ends the subpath closed. If its end misses its start by at most `close_gap` of its size
  // (the diagonal of its control points' bounding box), the end is moved onto the start
  // (with the control point before it); otherwise a line segment closes the gap.
  void close();
  // Ends the subpath open and hands over the components made so far.
  std::vector<Curve_component> finish();

  // Gaps of up to 1e-4 are rounding: drawing programs write relative coordinates with 5
  // to 8 digits (up to 2e-5 in data/svg/); a closing segment that short would only
  // contribute two corners at directions made of noise.
  static constexpr double close_gap = 1e-4;

 private:
  void end_subpath(bool closed);

  double corner_angle_ = 0;
  Point start_ = CGAL::ORIGIN, current_ = CGAL::ORIGIN;
  std::vector<std::vector<Point>> segments_;  // of the current subpath: ends of a line, or cubic control points
  std::vector<Curve_component> components_;
};

}  // namespace curvebench::geometry
