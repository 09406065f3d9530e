// Independent checks of the curve model's contract (geometry/curves/curve.h) for tests of the
// curve sources: derivatives against finite differences, the validity of every component
// (regular pieces that join, finite polylines), and a brute-force O(n²) self-intersection
// test of a polyline with exact predicates, independent of the box-intersection filter
// the sources use.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/curves/curve.h"

namespace curvebench::testing {

using geometry::Curve;
using geometry::Curve_component;
using geometry::Curve_piece;
using geometry::Point;
using geometry::Vector;

inline double norm(const Vector& v) { return std::hypot(v.x(), v.y()); }

// Central differences of f at t, Richardson-extrapolated from steps h and h/2: error
// O(h⁴ f⁽⁵⁾) + rounding O(ε |f| / h).
template <class F>
Vector central_difference(const F& f, double t, double h = 1e-4) {
  const auto step = [&](double k) { return (f(t + k) - f(t - k)) / (2 * k); };
  return (4 * step(h / 2) - step(h)) / 3;
}

// Finite differences of point() and derivative() at t (at least 1e-4 away from the ends)
// against derivative() and second_derivative(), relative to the size of the values involved.
inline ::testing::AssertionResult derivatives_match_finite_differences(const Curve_piece& piece, double t,
                                                                       double tolerance = 1e-6) {
  const Vector first = central_difference([&](double u) { return piece.point(u) - CGAL::ORIGIN; }, t);
  const Vector second = central_difference([&](double u) { return piece.derivative(u); }, t);
  const double size = norm(piece.point(t) - CGAL::ORIGIN) + norm(piece.derivative(t));
  const double first_error = norm(first - piece.derivative(t)) / (size + 1e-300);
  const double second_error = norm(second - piece.second_derivative(t)) / (size + norm(piece.second_derivative(t)));
  if (first_error <= tolerance && second_error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "at t = " << t << ": relative error of the derivative " << first_error
                                       << ", of the second derivative " << second_error;
}

// Every piece regular and finite at its ends and middle, consecutive pieces (and the ends
// of a closed component) joining, a finite positive length and a finite polyline.
inline ::testing::AssertionResult valid_curve(const Curve& curve) {
  const auto finite = [](const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); };
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const Curve_component& component = curve.components[c];
    const std::string where = curve.name + " component " + std::to_string(c);
    const double length = component.length();
    if (!(length > 0) || !std::isfinite(length)) return ::testing::AssertionFailure() << where << ": length " << length;
    const std::size_t n = component.piece_count();
    for (std::size_t i = 0; i < n; ++i) {
      const Curve_piece& piece = component.piece(i);
      for (const double t : {0.0, 0.5, 1.0}) {
        const double speed = norm(piece.derivative(t));
        if (!finite(piece.point(t)) || !(speed > 0) || !std::isfinite(speed))
          return ::testing::AssertionFailure() << where << " piece " << i << " at t = " << t << ": speed " << speed;
      }
      if (i + 1 < n || component.closed()) {
        const double gap = norm(component.piece((i + 1) % n).point(0) - piece.point(1));
        if (gap > 1e-9 * length) return ::testing::AssertionFailure() << where << ": gap " << gap << " after piece " << i;
      }
    }
    for (const Point& p : component.polyline(1e-3 * length))
      if (!finite(p)) return ::testing::AssertionFailure() << where << ": polyline point " << p;
  }
  return ::testing::AssertionSuccess();
}

// Whether the closed polyline crosses or touches itself other than where consecutive edges
// share a vertex: every pair of edges, by CGAL's exact do_intersect (consecutive edges:
// whether the second folds back onto the first).
inline bool closed_polyline_self_intersects(const std::vector<Point>& points) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point &a = points[i], &b = points[(i + 1) % n], &c = points[(i + 2) % n];
    if (CGAL::collinear(a, b, c) && !CGAL::collinear_are_ordered_along_line(a, b, c)) return true;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (CGAL::do_intersect(geometry::Kernel::Segment_2(a, b), geometry::Kernel::Segment_2(points[j], points[(j + 1) % n])))
        return true;
    }
  }
  return false;
}

}  // namespace curvebench::testing
