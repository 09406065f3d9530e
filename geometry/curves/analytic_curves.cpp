#include "geometry/curves/analytic_curves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <CGAL/box_intersection_d.h>

#include "geometry/curves/curve_name.h"

namespace curvebench::geometry {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

// A piece given as a function of an angle θ that runs over [start, start + sweep] as t
// runs over [0, 1]; subclasses give the point and its θ-derivatives, the chain rule the rest.
class Angular_piece : public Curve_piece {
 public:
  Angular_piece(double start, double sweep) : start_(start), sweep_(sweep) {}
  Point point(double t) const final { return at(angle(t)); }
  Vector derivative(double t) const final { return sweep_ * velocity(angle(t)); }
  Vector second_derivative(double t) const final { return sweep_ * sweep_ * acceleration(angle(t)); }

 private:
  double angle(double t) const { return start_ + sweep_ * t; }
  virtual Point at(double theta) const = 0;
  virtual Vector velocity(double theta) const = 0;
  virtual Vector acceleration(double theta) const = 0;

  double start_, sweep_;
};

class Ellipse_piece final : public Angular_piece {
 public:
  Ellipse_piece(double a, double b) : Angular_piece(0, two_pi), a_(a), b_(b) {}

 private:
  Point at(double theta) const override { return {a_ * std::cos(theta), b_ * std::sin(theta)}; }
  Vector velocity(double theta) const override { return {-a_ * std::sin(theta), b_ * std::cos(theta)}; }
  Vector acceleration(double theta) const override { return {-a_ * std::cos(theta), -b_ * std::sin(theta)}; }

  double a_, b_;
};

// |x|^n and its first two derivatives.
struct Power {
  double n;
  double value(double x) const { return std::pow(std::abs(x), n); }
  double first(double x) const { return n * std::pow(std::abs(x), n - 1) * (x < 0 ? -1 : 1); }
  double second(double x) const { return n * (n - 1) * std::pow(std::abs(x), n - 2); }
};

// The superellipse in polar form r(φ) (cos φ, sin φ), r = F^(-1/n), F = |cos φ/a|^n + |sin φ/b|^n,
// over `quarters` quarter turns from the axis point `first_quarter` quarter turns from +x.
class Superellipse_polar_piece final : public Curve_piece {
 public:
  Superellipse_polar_piece(double a, double b, double n, int first_quarter, int quarters)
      : a_(a), b_(b), power_{n}, first_quarter_(first_quarter), quarters_(quarters) {}

  Point point(double t) const override {
    const Vector e = direction(t);
    return CGAL::ORIGIN + radius(e)[0] * e;
  }
  Vector derivative(double t) const override {
    const Vector e = direction(t);
    const auto [r, dr, ddr] = radius(e);
    return speed() * (dr * e + r * e.perpendicular(CGAL::COUNTERCLOCKWISE));
  }
  Vector second_derivative(double t) const override {
    const Vector e = direction(t);
    const auto [r, dr, ddr] = radius(e);
    return speed() * speed() * ((ddr - r) * e + 2 * dr * e.perpendicular(CGAL::COUNTERCLOCKWISE));
  }

 private:
  double speed() const { return quarters_ * std::numbers::pi / 2; }  // dφ/dt

  // (cos φ, sin φ) with φ counted in quarter turns, so that it is exactly (±1, 0) or (0, ±1)
  // at the axis points: there |cos φ|^(n-1) must be 0, not (6e-17)^(n-1) (6e-4 for n = 1.2).
  Vector direction(double t) const {
    const double turns = first_quarter_ + quarters_ * t, quarter = std::round(turns);
    const double rest = (turns - quarter) * std::numbers::pi / 2;
    Vector e(std::cos(rest), std::sin(rest));
    for (int q = 0; q < (int(quarter) % 4 + 4) % 4; ++q) e = e.perpendicular(CGAL::COUNTERCLOCKWISE);
    return e;
  }

  // r and its first two φ-derivatives in the direction e = (cos φ, sin φ).
  std::array<double, 3> radius(const Vector& e) const {
    const double c = e.x(), s = e.y(), n = power_.n;
    const double X = c / a_, dX = -s / a_, Y = s / b_, dY = c / b_;  // X'' = -X, Y'' = -Y
    const double F = power_.value(X) + power_.value(Y);
    const double dF = power_.first(X) * dX + power_.first(Y) * dY;
    const double ddF = power_.second(X) * dX * dX - power_.first(X) * X + power_.second(Y) * dY * dY -
                       power_.first(Y) * Y;
    const double r = std::pow(F, -1 / n);
    const double dr = -r / (n * F) * dF;
    const double ddr = -1 / n * ((-1 / n - 1) * r / (F * F) * dF * dF + r / F * ddF);
    return {r, dr, ddr};
  }

  double a_, b_;
  Power power_;
  int first_quarter_, quarters_;
};

// A quadrant of the superellipse with n <= 1: (1-u)^p A + u^p B, p = 1/n >= 1, from the
// axis point A to the axis point B; its derivative there is -p A or p B, never zero.
class Superellipse_quadrant_piece final : public Curve_piece {
 public:
  Superellipse_quadrant_piece(const Vector& from, const Vector& to, double n) : from_(from), to_(to), p_{1 / n} {}
  Point point(double u) const override { return CGAL::ORIGIN + p_.value(1 - u) * from_ + p_.value(u) * to_; }
  Vector derivative(double u) const override { return -p_.first(1 - u) * from_ + p_.first(u) * to_; }
  Vector second_derivative(double u) const override {
    if (p_.n == 1) return {0, 0};  // a straight side; avoids 0 * infinity at the ends
    return p_.second(1 - u) * from_ + p_.second(u) * to_;
  }

 private:
  Vector from_, to_;
  Power p_;
};

// Σ_k A_k cos kθ + B_k sin kθ over the harmonics k = 1 .. K (the first is the unit circle).
class Fourier_piece final : public Angular_piece {
 public:
  struct Harmonic {
    int k;
    Vector cosine, sine;
  };
  explicit Fourier_piece(std::vector<Harmonic> harmonics) : Angular_piece(0, two_pi), harmonics_(std::move(harmonics)) {}

 private:
  // Σ_k k^order (A_k, B_k) · (cos, sin)(kθ + order π/2): the order-th θ-derivative.
  Vector sum(double theta, int order) const {
    Vector total(0, 0);
    for (const auto& h : harmonics_) {
      const double phase = h.k * theta + order * std::numbers::pi / 2;
      total = total + std::pow(double(h.k), order) * (std::cos(phase) * h.cosine + std::sin(phase) * h.sine);
    }
    return total;
  }
  Point at(double theta) const override { return CGAL::ORIGIN + sum(theta, 0); }
  Vector velocity(double theta) const override { return sum(theta, 1); }
  Vector acceleration(double theta) const override { return sum(theta, 2); }

  std::vector<Harmonic> harmonics_;
};

void require_positive(double value, const char* what) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(what) + " must be positive and finite, not " + format_number(value));
}

Curve single_piece_curve(std::string name, std::shared_ptr<const Curve_piece> piece) {
  Curve curve{std::move(name), {}};
  curve.components.emplace_back(std::vector<std::shared_ptr<const Curve_piece>>{std::move(piece)}, true);
  return curve;
}

// A uniform double in [-1, 1) from 53 random bits: the same on every platform, unlike
// std::uniform_real_distribution whose algorithm the standard leaves open.
double symmetric_unit(std::mt19937_64& engine) { return double(engine() >> 11) * 0x1.0p-52 - 1; }

// SplitMix64's finaliser: a seed for attempt i that shares no stream with other seeds' attempts.
std::uint64_t derived_seed(std::uint64_t seed, std::uint64_t attempt) {
  if (attempt == 0) return seed;
  std::uint64_t z = seed + attempt * 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Whether the closed polyline through `points` crosses or touches itself anywhere but at
// the shared vertex of consecutive edges, by exact predicates. Candidate pairs come from
// CGAL's box intersection (bounding boxes of the edges).
bool closed_polyline_is_simple(const std::vector<Point>& points) {
  const std::size_t n = points.size();
  const auto edge = [&](std::size_t i) { return Kernel::Segment_2(points[i], points[(i + 1) % n]); };
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < n; ++i) boxes.emplace_back(edge(i).bbox(), i);
  bool simple = true;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    std::size_t i = std::min(a.info(), b.info()), j = std::max(a.info(), b.info());
    if (!simple) return;
    if (j == i + 1 || (i == 0 && j == n - 1)) {
      if (i == 0 && j == n - 1) std::swap(i, j);  // edge i ends where edge j starts
      const Point &p = points[i], &q = points[(i + 1) % n], &r = points[(j + 1) % n];
      simple = !(CGAL::collinear(p, q, r) && !CGAL::collinear_are_ordered_along_line(p, q, r));
    } else {
      simple = !CGAL::do_intersect(edge(i), edge(j));
    }
  });
  return simple;
}

constexpr int simplicity_samples = 8192;

// Whether the closed component is regular (speed at least 1% of its mean) and its tangent
// turns once round counterclockwise (Hopf's Umlaufsatz: a simple closed curve's turning
// number is ±1), turning less than 45° between samples. A polyline can step over a loop smaller
// than its chords, but the loop's extra turn of the tangent cannot hide.
bool turns_once(const Curve_component& component) {
  double slowest = HUGE_VAL, total = 0, turning = 0;
  Vector previous = component.derivative(0);
  for (int i = 1; i <= simplicity_samples; ++i) {
    const Vector d = component.derivative(double(i % simplicity_samples) / simplicity_samples);
    const double speed = std::hypot(d.x(), d.y()), step = std::atan2(CGAL::determinant(previous, d), previous * d);
    if (std::abs(step) > std::numbers::pi / 4) return false;
    slowest = std::min(slowest, speed);
    total += speed;
    turning += step;
    previous = d;
  }
  return slowest >= 1e-2 * total / simplicity_samples && std::abs(turning - two_pi) < std::numbers::pi;
}

}  // namespace

Curve circle(double r) {
  require_positive(r, "circle: r");
  return single_piece_curve("circle:r=" + format_number(r), std::make_shared<Circular_arc>(CGAL::ORIGIN, r, 0, two_pi));
}

Curve ellipse(double a, double b) {
  require_positive(a, "ellipse: a");
  require_positive(b, "ellipse: b");
  return single_piece_curve("ellipse:a=" + format_number(a) + ",b=" + format_number(b),
                            std::make_shared<Ellipse_piece>(a, b));
}

Curve superellipse(double a, double b, double n) {
  require_positive(a, "superellipse: a");
  require_positive(b, "superellipse: b");
  require_positive(n, "superellipse: n");
  std::string name = "superellipse:a=" + format_number(a) + ",b=" + format_number(b) + ",n=" + format_number(n);
  if (n >= 2) return single_piece_curve(std::move(name), std::make_shared<Superellipse_polar_piece>(a, b, n, 0, 4));
  const std::array<Vector, 5> axis_points{Vector(a, 0), Vector(0, b), Vector(-a, 0), Vector(0, -b), Vector(a, 0)};
  std::vector<std::shared_ptr<const Curve_piece>> quadrants;
  for (int q = 0; q < 4; ++q) {
    if (n > 1)
      quadrants.push_back(std::make_shared<Superellipse_polar_piece>(a, b, n, q, 1));
    else
      quadrants.push_back(std::make_shared<Superellipse_quadrant_piece>(axis_points[q], axis_points[q + 1], n));
  }
  Curve curve{std::move(name), {}};
  curve.components.emplace_back(std::move(quadrants), true);
  return curve;
}

namespace {

std::string fourier_name(std::uint64_t seed, const Fourier_curve_parameters& parameters) {
  return "fourier:seed=" + std::to_string(seed) + ",harmonics=" + std::to_string(parameters.harmonics) +
         ",amplitude=" + format_number(parameters.amplitude) + ",decay=" + format_number(parameters.decay);
}

// The harmonics of random_fourier_curve(seed, parameters).
std::vector<Fourier_piece::Harmonic> simple_fourier_terms(std::uint64_t seed, const Fourier_curve_parameters& parameters) {
  const auto& [harmonics, amplitude, decay] = parameters;
  if (harmonics < 0 || harmonics > 64) throw std::invalid_argument("fourier: harmonics must be in [0, 64]");
  if (!(amplitude >= 0) || !std::isfinite(amplitude) || !(decay >= 0) || !std::isfinite(decay))
    throw std::invalid_argument("fourier: amplitude and decay must be finite and non-negative");
  for (std::uint64_t attempt = 0; attempt < 1000; ++attempt) {
    std::mt19937_64 engine(derived_seed(seed, attempt));
    std::vector<Fourier_piece::Harmonic> terms{{1, Vector(1, 0), Vector(0, 1)}};
    for (int k = 2; k <= harmonics + 1; ++k) {
      const double scale = amplitude / std::pow(double(k), decay);
      const double ax = symmetric_unit(engine), ay = symmetric_unit(engine);
      const double bx = symmetric_unit(engine), by = symmetric_unit(engine);
      terms.push_back({k, scale * Vector(ax, ay), scale * Vector(bx, by)});
    }
    const Curve curve = single_piece_curve("", std::make_shared<Fourier_piece>(terms));
    const auto& component = curve.components.front();
    std::vector<Point> polyline;
    for (int i = 0; i < simplicity_samples; ++i) polyline.push_back(component.point(double(i) / simplicity_samples));
    if (turns_once(component) && closed_polyline_is_simple(polyline)) return terms;
  }
  throw std::invalid_argument("fourier: no simple regular curve in 1000 attempts; lower the amplitude");
}

}  // namespace

Curve random_fourier_curve(std::uint64_t seed, const Fourier_curve_parameters& parameters) {
  return single_piece_curve(fourier_name(seed, parameters),
                            std::make_shared<Fourier_piece>(simple_fourier_terms(seed, parameters)));
}

Curve random_fourier_curves(std::uint64_t seed, const Fourier_curve_parameters& parameters, int components) {
  if (components < 1 || components > 64) throw std::invalid_argument("fourier: components must be in [1, 64]");
  if (components == 1) return random_fourier_curve(seed, parameters);
  Curve curve{fourier_name(seed, parameters) + ",components=" + std::to_string(components), {}};
  double x = 0;
  for (int c = 0; c < components; ++c) {
    auto terms = simple_fourier_terms(seed + c, parameters);
    const Kernel::Iso_rectangle_2 box =
        single_piece_curve("", std::make_shared<Fourier_piece>(terms)).bounding_box(1e-6);
    // A constant term (k = 0) moves the curve: its derivatives vanish.
    terms.push_back({0, Vector(x - box.xmin(), 0), Vector(0, 0)});
    x += box.xmax() - box.xmin() + component_gap;
    curve.components.emplace_back(
        std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Fourier_piece>(std::move(terms))}, true);
  }
  return curve;
}

}  // namespace curvebench::geometry
