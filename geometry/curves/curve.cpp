#include "geometry/curves/curve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <CGAL/bounding_box.h>

namespace curvebench::geometry {
namespace {

// 8-point Gauss-Legendre rule on [-1, 1]: exact for polynomials of degree 15, so the
// length of a smooth piece over 1/16 of its parameter range is exact to rounding.
constexpr std::array<double, 4> gauss_nodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                            0.9602898564975363};
constexpr std::array<double, 4> gauss_weights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                              0.1012285362903763};

double norm(const Vector& v) { return std::hypot(v.x(), v.y()); }

}  // namespace

Curve_component::Curve_component(std::vector<std::shared_ptr<const Curve_piece>> pieces, bool closed)
    : pieces_(std::move(pieces)), closed_(closed) {
  if (pieces_.empty()) throw std::invalid_argument("curve component: no piece");
  cumulative_length_.assign(1, 0.0);
  for (std::size_t i = 0; i < pieces_.size(); ++i)
    for (int j = 0; j < subdivisions; ++j)
      cumulative_length_.push_back(cumulative_length_.back() +
                                   piece_arc_length(i, double(j) / subdivisions, double(j + 1) / subdivisions));

  const double size = std::max(length(), std::numeric_limits<double>::min());
  const auto joined = [&](const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)) <= 1e-9 * size; };
  for (std::size_t i = 0; i + 1 < pieces_.size(); ++i)
    if (!joined(pieces_[i]->point(1), pieces_[i + 1]->point(0)))
      throw std::invalid_argument("curve component: piece " + std::to_string(i + 1) + " does not start where piece " +
                                  std::to_string(i) + " ends");
  if (closed_ && !joined(pieces_.back()->point(1), pieces_.front()->point(0)))
    throw std::invalid_argument("curve component: closed, but its end is not its start");
}

std::pair<std::size_t, double> Curve_component::locate(double s) const {
  const double n = static_cast<double>(pieces_.size());
  if (closed_) {
    s = std::fmod(s, n);
    if (s < 0) s += n;
  } else {
    s = std::clamp(s, 0.0, n);
  }
  const std::size_t i = std::min(static_cast<std::size_t>(s), pieces_.size() - 1);
  return {i, s - static_cast<double>(i)};
}

Point Curve_component::point(double s) const {
  const auto [i, t] = locate(s);
  return pieces_[i]->point(t);
}

Vector Curve_component::derivative(double s) const {
  const auto [i, t] = locate(s);
  return pieces_[i]->derivative(t);
}

Vector Curve_component::second_derivative(double s) const {
  const auto [i, t] = locate(s);
  return pieces_[i]->second_derivative(t);
}

Vector Curve_component::unit_tangent(double s) const {
  const Vector d = derivative(s);
  return d / norm(d);
}

Vector Curve_component::unit_normal(double s) const { return unit_tangent(s).perpendicular(CGAL::COUNTERCLOCKWISE); }

double Curve_component::curvature(double s) const {
  const Vector d = derivative(s), dd = second_derivative(s);
  const double speed = norm(d);
  return (d.x() * dd.y() - d.y() * dd.x()) / (speed * speed * speed);
}

double Curve_component::piece_arc_length(std::size_t piece, double t0, double t1) const {
  const double half = (t1 - t0) / 2, middle = (t0 + t1) / 2;
  double sum = 0;
  for (std::size_t k = 0; k < gauss_nodes.size(); ++k)
    sum += gauss_weights[k] * (norm(pieces_[piece]->derivative(middle - half * gauss_nodes[k])) +
                               norm(pieces_[piece]->derivative(middle + half * gauss_nodes[k])));
  return sum * half;
}

double Curve_component::arc_length(double s) const {
  if (!closed_ && s >= static_cast<double>(pieces_.size())) return length();
  const auto [i, t] = locate(s);
  const int j = std::min(static_cast<int>(t * subdivisions), subdivisions - 1);
  return cumulative_length_[i * subdivisions + j] + piece_arc_length(i, double(j) / subdivisions, t);
}

double Curve_component::parameter_at_arc_length(double target) const {
  target = std::clamp(target, 0.0, length());
  const auto step = std::upper_bound(cumulative_length_.begin(), cumulative_length_.end() - 1, target);
  const std::size_t k = std::max<std::ptrdiff_t>(step - cumulative_length_.begin() - 1, 0);
  const std::size_t i = k / subdivisions;
  double low = double(k % subdivisions) / subdivisions, high = low + 1.0 / subdivisions;
  const double start = low, base = cumulative_length_[k], span = cumulative_length_[k + 1] - base;
  double t = span > 0 ? low + (target - base) / span / subdivisions : low;
  // Newton's method on the arc length, kept inside the bracket by bisection.
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double error = base + piece_arc_length(i, start, t) - target;
    if (std::abs(error) <= 1e-15 * std::max(length(), 1e-300)) break;
    (error > 0 ? high : low) = t;
    const double speed = norm(pieces_[i]->derivative(t));
    const double newton = t - error / speed;
    t = speed > 0 && newton > low && newton < high ? newton : (low + high) / 2;
  }
  return static_cast<double>(i) + t;
}

std::vector<double> Curve_component::corners(double angle) const {
  std::vector<double> found;
  const auto turns = [&](const Curve_piece& in, const Curve_piece& out) {
    const Vector a = in.derivative(1), b = out.derivative(0);
    return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a * b) > angle;
  };
  if (closed_ && turns(*pieces_.back(), *pieces_.front())) found.push_back(0);
  for (std::size_t i = 1; i < pieces_.size(); ++i)
    if (turns(*pieces_[i - 1], *pieces_[i])) found.push_back(static_cast<double>(i));
  return found;
}

std::vector<Point> Curve_component::polyline(double tolerance) const {
  // Below the rounding noise of the coordinates the refinement would never stop.
  tolerance = std::max(tolerance, 1e-12 * length());
  std::vector<Point> points;
  // Split each piece in 8, then halve a step while its midpoint strays from the chord.
  const auto refine = [&](const Curve_piece& piece, double t0, double t1, auto& self, int depth) -> void {
    const Point a = piece.point(t0), b = piece.point(t1), m = piece.point((t0 + t1) / 2);
    const double stray = a == b ? std::sqrt(CGAL::squared_distance(a, m))
                                : std::sqrt(CGAL::squared_distance(Kernel::Segment_2(a, b), m));
    if (depth < 40 && stray > tolerance) {
      self(piece, t0, (t0 + t1) / 2, self, depth + 1);
      self(piece, (t0 + t1) / 2, t1, self, depth + 1);
    } else {
      points.push_back(a);
    }
  };
  for (const auto& piece : pieces_)
    for (int k = 0; k < 8; ++k) refine(*piece, k / 8.0, (k + 1) / 8.0, refine, 0);
  if (!closed_) points.push_back(pieces_.back()->point(1));
  return points;
}

double Curve::length() const {
  double total = 0;
  for (const auto& c : components) total += c.length();
  return total;
}

Kernel::Iso_rectangle_2 Curve::bounding_box(double tolerance) const {
  std::vector<Point> all;
  for (const auto& c : components) {
    const auto points = c.polyline(tolerance);
    all.insert(all.end(), points.begin(), points.end());
  }
  return all.empty() ? Kernel::Iso_rectangle_2() : CGAL::bounding_box(all.begin(), all.end());
}

Circular_arc::Circular_arc(const Point& center, double radius, double start, double sweep)
    : center_(center), radius_(radius), start_(start), sweep_(sweep) {
  if (!(radius > 0) || !(sweep != 0)) throw std::invalid_argument("circular arc: radius and sweep must be non-zero");
}

Point Circular_arc::point(double t) const {
  const double angle = start_ + sweep_ * t;
  return center_ + radius_ * Vector(std::cos(angle), std::sin(angle));
}

Vector Circular_arc::derivative(double t) const {
  const double angle = start_ + sweep_ * t;
  return radius_ * sweep_ * Vector(-std::sin(angle), std::cos(angle));
}

Vector Circular_arc::second_derivative(double t) const {
  const double angle = start_ + sweep_ * t;
  return -radius_ * sweep_ * sweep_ * Vector(std::cos(angle), std::sin(angle));
}

}  // namespace curvebench::geometry
