#include "geometry/curves/cubic_bezier.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace curvebench::geometry {
namespace {

Vector position(const Point& p) { return p - CGAL::ORIGIN; }

// The roots in (0, 1) of a t^2 + b t + c, ascending.
std::vector<double> roots_in_unit_interval(double a, double b, double c) {
  std::vector<double> roots;
  if (a == 0) {
    if (b != 0) roots.push_back(-c / b);
  } else if (const double discriminant = b * b - 4 * a * c; discriminant >= 0) {
    // The cancellation-free pair: q = -(b + sign(b) √D) / 2, roots q / a and c / q.
    const double q = -(b + std::copysign(std::sqrt(discriminant), b)) / 2;
    roots.push_back(q / a);
    if (q != 0) roots.push_back(c / q);
  }
  std::erase_if(roots, [](double t) { return !(t > 0 && t < 1); });
  std::sort(roots.begin(), roots.end());
  return roots;
}

// B(t), B'(t), B''(t) of the cubic with control points q.
std::array<Vector, 3> bernstein(const std::array<Point, 4>& q, double t) {
  const Vector q0 = position(q[0]), q1 = position(q[1]), q2 = position(q[2]), q3 = position(q[3]);
  const double s = 1 - t;
  return {s * s * s * q0 + 3 * s * s * t * q1 + 3 * s * t * t * q2 + t * t * t * q3,
          3 * s * s * (q1 - q0) + 6 * s * t * (q2 - q1) + 3 * t * t * (q3 - q2),
          6 * s * (q2 - 2 * q1 + q0) + 6 * t * (q3 - 2 * q2 + q1)};
}

}  // namespace

Cubic_bezier::Cubic_bezier(const std::array<Point, 4>& control) : control_(control), oriented_(control) {
  if (control[2] == control[3] && control[1] != control[0]) {
    std::reverse(oriented_.begin(), oriented_.end());
    reversed_ = true;
  }
  degenerate_start_ = oriented_[1] == oriented_[0];
}

Point Cubic_bezier::point(double t) const {
  const double v = reversed_ ? 1 - t : t;
  return CGAL::ORIGIN + bernstein(oriented_, degenerate_start_ ? std::sqrt(v) : v)[0];
}

Vector Cubic_bezier::derivative(double t) const {
  const double v = reversed_ ? 1 - t : t;
  Vector d;
  if (degenerate_start_) {
    // B'(w) = w Q(w) with Q(w) = 6 (1-w) (q2 - q1) + 3 w (q3 - q2) as q1 = q0; w = √v, dw/dv = 1/(2w).
    const double w = std::sqrt(v);
    d = 3 * (1 - w) * (oriented_[2] - oriented_[1]) + 1.5 * w * (oriented_[3] - oriented_[2]);
  } else {
    d = bernstein(oriented_, v)[1];
  }
  return reversed_ ? -d : d;
}

Vector Cubic_bezier::second_derivative(double t) const {
  const double v = reversed_ ? 1 - t : t;
  if (!degenerate_start_) return bernstein(oriented_, v)[2];
  // d/dv of Q(√v)/2 = Q' / (4 √v); at v = 0 the smallest normal double keeps it finite.
  const Vector dQ = -6 * (oriented_[2] - oriented_[1]) + 3 * (oriented_[3] - oriented_[2]);
  return dQ / (4 * std::sqrt(std::max(v, std::numeric_limits<double>::min())));
}

namespace {

// The t in (0, 1) where the coordinate of the control values s[0..3] has zero derivative.
std::vector<double> turning_parameters(const std::array<double, 4>& s) {
  const double a1 = s[1] - s[0], a2 = s[2] - s[1], a3 = s[3] - s[2];
  return roots_in_unit_interval(a1 - 2 * a2 + a3, 2 * (a2 - a1), a1);
}

// A cubic without interior cusp: a Cubic_bezier, or Line_segments between turning points
// if its control points are collinear.
void append_cusp_free(std::vector<std::shared_ptr<const Curve_piece>>& pieces, const std::array<Point, 4>& control) {
  const auto distinct = std::find_if(control.begin() + 1, control.end(), [&](const Point& p) { return p != control[0]; });
  if (distinct == control.end()) return;
  const bool collinear = std::all_of(control.begin() + 1, control.end(),
                                     [&](const Point& p) { return CGAL::collinear(control[0], *distinct, p); });
  if (!collinear) {
    pieces.push_back(std::make_shared<Cubic_bezier>(control));
    return;
  }
  // On a line the curve runs back and forth between the zeros of B' along the line.
  const Vector direction = *distinct - control[0];
  std::array<double, 4> s;
  for (int i = 0; i < 4; ++i) s[i] = (control[i] - control[0]) * direction;
  std::vector<double> breaks = turning_parameters(s);
  breaks.push_back(1);
  Point from = control[0];
  for (const double t : breaks) {
    const Point to = t == 1 ? control[3] : CGAL::ORIGIN + bernstein(control, t)[0];
    if (to != from) pieces.push_back(std::make_shared<Line_segment>(from, to));
    from = to;
  }
}

}  // namespace

void append_cubic_bezier(std::vector<std::shared_ptr<const Curve_piece>>& pieces, const std::array<Point, 4>& control) {
  // A cusp (B' = 0 inside) is where a root of x' is a root of y'. To rounding, it becomes a
  // join: the halves of de Casteljau's split, each with its control point on the cusp.
  double size = 0;
  for (const Point& p : control) size = std::max(size, std::sqrt(CGAL::squared_distance(p, control[0])));
  std::array<double, 4> xs, ys;
  for (int i = 0; i < 4; ++i) std::tie(xs[i], ys[i]) = std::pair(control[i].x(), control[i].y());
  for (const auto& roots : {turning_parameters(xs), turning_parameters(ys)})
    for (const double t : roots) {
      const Vector d = bernstein(control, t)[1];
      if (std::sqrt(d * d) > 1e-12 * size) continue;
      const auto lerp = [t](const Point& p, const Point& q) { return p + t * (q - p); };
      const Point a = lerp(control[0], control[1]), b = lerp(control[1], control[2]), c = lerp(control[2], control[3]);
      const Point cusp = lerp(lerp(a, b), lerp(b, c));
      append_cusp_free(pieces, {control[0], a, cusp, cusp});
      append_cusp_free(pieces, {cusp, cusp, c, control[3]});
      return;
    }
  append_cusp_free(pieces, control);
}

std::array<Point, 4> elevate_quadratic_bezier(const Point& p0, const Point& c, const Point& p1) {
  return {p0, p0 + 2.0 / 3 * (c - p0), p1 + 2.0 / 3 * (c - p1), p1};
}

}  // namespace curvebench::geometry
