// Turns drawing commands (SVG path data, font outlines) into curve components, so that
// every path-like source treats degenerate input alike: the pieces of a curve must be
// regular and join (curve.h), while drawings contain zero-length segments, lone points,
// control points on end points and closing gaps left by rounding.
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
  void move_to(const Point& p);
  void line_to(const Point& p);
  void quadratic_to(const Point& control, const Point& p);  // elevated to a cubic
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

  Point start_ = CGAL::ORIGIN, current_ = CGAL::ORIGIN;
  std::vector<std::vector<Point>> segments_;  // of the current subpath: ends of a line, or cubic control points
  std::vector<Curve_component> components_;
};

}  // namespace curvebench::geometry
