#include "geometry/curves/analytic_curves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Search_traits_2.h>

#include "geometry/curves/closed_polyline.h"
#include "geometry/curves/curve_crossings.h"
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
  // θ runs over [start, start + sweep]: the whole closed curve by default.
  explicit Fourier_piece(std::vector<Harmonic> harmonics, double start = 0, double sweep = two_pi)
      : Angular_piece(start, sweep), harmonics_(std::move(harmonics)) {}

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

// `samples` points of a closed one-piece curve at equal parameter steps, its start first.
std::vector<Point> closed_polyline(const Curve_piece& piece, int samples) {
  std::vector<Point> points;
  for (int i = 0; i < samples; ++i) points.push_back(piece.point(double(i) / samples));
  return points;
}

constexpr int simplicity_samples = 8192;

// The tangent of a closed component sampled at `samples` equal parameter steps: its total
// turn (radians, counterclockwise positive), if no step turns it by more than 45°, and the
// slowest speed and the sum of the speeds.
struct Tangent_walk {
  std::optional<double> turning;  // none: a step turned more than 45°
  double slowest = HUGE_VAL, total_speed = 0;
};

Tangent_walk walk_tangent(const Curve_component& component, int samples) {
  Tangent_walk walk;
  double turning = 0;
  Vector previous = component.derivative(0);
  for (int i = 1; i <= samples; ++i) {
    const Vector d = component.derivative(double(i % samples) / samples);
    const double speed = std::hypot(d.x(), d.y()), step = std::atan2(CGAL::determinant(previous, d), previous * d);
    if (std::abs(step) > std::numbers::pi / 4) return walk;
    walk.slowest = std::min(walk.slowest, speed);
    walk.total_speed += speed;
    turning += step;
    previous = d;
  }
  walk.turning = turning;
  return walk;
}

// Whether the closed component is regular (speed at least 1% of its mean) and its tangent
// turns once round counterclockwise (Hopf's Umlaufsatz: a simple closed curve's turning
// number is ±1), turning less than 45° between samples. A polyline can step over a loop smaller
// than its chords, but the loop's extra turn of the tangent cannot hide.
bool turns_once(const Curve_component& component) {
  const Tangent_walk walk = walk_tangent(component, simplicity_samples);
  return walk.turning && walk.slowest >= 1e-2 * walk.total_speed / simplicity_samples &&
         std::abs(*walk.turning - two_pi) < std::numbers::pi;
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
    const auto piece = std::make_shared<Fourier_piece>(terms);
    const Curve curve = single_piece_curve("", piece);
    if (turns_once(curve.components.front()) && closed_polyline_is_simple(closed_polyline(*piece, simplicity_samples)))
      return terms;
  }
  throw std::invalid_argument("fourier: no simple regular curve in 1000 attempts; lower the amplitude");
}

}  // namespace

Curve random_fourier_curve(std::uint64_t seed, const Fourier_curve_parameters& parameters) {
  return single_piece_curve(fourier_name(seed, parameters),
                            std::make_shared<Fourier_piece>(simple_fourier_terms(seed, parameters)));
}

Curve random_fourier_curves(std::uint64_t seed, const Fourier_curve_parameters& parameters, int components,
                            double separation) {
  if (components < 1 || components > 64) throw std::invalid_argument("fourier: components must be in [1, 64]");
  require_positive(separation, "fourier: separation");
  if (components == 1) return random_fourier_curve(seed, parameters);
  std::string name = fourier_name(seed, parameters) + ",components=" + std::to_string(components);
  if (separation != component_gap) name += ",separation=" + format_number(separation);
  Curve curve{std::move(name), {}};
  double x = 0;
  for (int c = 0; c < components; ++c) {
    auto terms = simple_fourier_terms(seed + c, parameters);
    const Kernel::Iso_rectangle_2 box =
        single_piece_curve("", std::make_shared<Fourier_piece>(terms)).bounding_box(1e-6);
    // A constant term (k = 0) moves the curve: its derivatives vanish.
    terms.push_back({0, Vector(x - box.xmin(), 0), Vector(0, 0)});
    x += box.xmax() - box.xmin() + separation;
    curve.components.emplace_back(
        std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Fourier_piece>(std::move(terms))}, true);
  }
  return curve;
}

Curve random_fourier_arc(std::uint64_t seed, const Fourier_curve_parameters& parameters, double gap) {
  if (!(gap > 0 && gap < 1)) throw std::invalid_argument("fourier: gap must be in (0, 1), not " + format_number(gap));
  Curve curve{fourier_name(seed, parameters) + ",gap=" + format_number(gap), {}};
  // The gap is centred on θ = π, opposite the closed curve's start.
  const double start = std::numbers::pi * (1 + gap), sweep = two_pi * (1 - gap);
  curve.components.emplace_back(std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Fourier_piece>(
                                    simple_fourier_terms(seed, parameters), start, sweep)},
                                false);
  return curve;
}

namespace {

// The smallest distance from a point of `points` to the dense points of `tree`: within
// (chord length)^2 / (8 distance) of the distance between the curves they sample.
using Point_tree = CGAL::Kd_tree<CGAL::Search_traits_2<Kernel>>;
double smallest_distance(const Point_tree& tree, const std::vector<Point>& points) {
  double smallest = HUGE_VAL;
  for (const Point& p : points) {
    const CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_2<Kernel>> nearest(tree, p, 1);
    smallest = std::min(smallest, std::sqrt(nearest.begin()->second));
  }
  return smallest;
}

}  // namespace

Curve nested_fourier_curves(std::uint64_t seed, double separation) {
  require_positive(separation, "nested: separation");
  const Fourier_curve_parameters parameters;
  const auto outer_terms = simple_fourier_terms(seed, parameters);
  const Fourier_piece outer(outer_terms);
  const std::vector<Point> outer_points = closed_polyline(outer, simplicity_samples);
  const Point_tree tree(outer_points.begin(), outer_points.end());
  const auto polygon = CGAL::Polygon_2<Kernel>(outer_points.begin(), outer_points.end());
  for (std::uint64_t attempt = 0; attempt < 100; ++attempt) {
    const auto inner_terms = simple_fourier_terms(derived_seed(seed + 1, attempt), parameters);
    const auto scaled = [&](double scale) {
      auto terms = inner_terms;
      for (auto& h : terms) h.cosine = scale * h.cosine, h.sine = scale * h.sine;
      return terms;
    };
    const auto gap_at = [&](double scale) {
      return smallest_distance(tree, closed_polyline(Fourier_piece(scaled(scale)), 2048));
    };
    // Scaling about the origin (the centre of the first harmonic, as of the outer curve's)
    // narrows the gap monotonically while the copy stays inside: bisect on the scale.
    double low = 1e-3, high = 1;
    if (gap_at(low) <= separation) break;  // the outer curve is too narrow for this separation
    for (int step = 0; step < 50; ++step) {
      const double middle = (low + high) / 2;
      const std::vector<Point> inner_points = closed_polyline(Fourier_piece(scaled(middle)), 2048);
      const bool inside = polygon.bounded_side(inner_points.front()) == CGAL::ON_BOUNDED_SIDE;
      (inside && smallest_distance(tree, inner_points) > separation ? low : high) = middle;
    }
    const Fourier_piece inner(scaled(low));
    const std::vector<Point> inner_points = closed_polyline(inner, simplicity_samples);
    if (polygon.bounded_side(inner_points.front()) != CGAL::ON_BOUNDED_SIDE || closed_polylines_meet(outer_points, inner_points))
      continue;  // not star-shaped enough about the origin: draw another inner curve
    Curve curve{"nested:seed=" + std::to_string(seed) + ",separation=" + format_number(separation), {}};
    for (const auto& terms : {outer_terms, scaled(low)}) {
      auto piece = std::make_shared<Fourier_piece>(terms);
      curve.components.emplace_back(std::vector<std::shared_ptr<const Curve_piece>>{std::move(piece)}, true);
    }
    return curve;
  }
  throw std::invalid_argument("nested: no inner curve " + format_number(separation) + " inside fourier:seed=" +
                              std::to_string(seed) + "; lower the separation");
}

namespace {

// r(θ) (cos θ, sin θ) with r growing linearly from `inner` to 1 over the sweep.
class Spiral_piece final : public Angular_piece {
 public:
  Spiral_piece(double start, double sweep, double inner)
      : Angular_piece(start, sweep), start_(start), inner_(inner), growth_((1 - inner) / sweep) {}

 private:
  double radius(double theta) const { return inner_ + growth_ * (theta - start_); }
  static Vector unit(double theta) { return {std::cos(theta), std::sin(theta)}; }
  Point at(double theta) const override { return CGAL::ORIGIN + radius(theta) * unit(theta); }
  Vector velocity(double theta) const override {
    return growth_ * unit(theta) + radius(theta) * unit(theta).perpendicular(CGAL::COUNTERCLOCKWISE);
  }
  Vector acceleration(double theta) const override {
    return 2 * growth_ * unit(theta).perpendicular(CGAL::COUNTERCLOCKWISE) - radius(theta) * unit(theta);
  }

  double start_, inner_, growth_;
};

}  // namespace

Curve random_spiral(std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  const double turns = 1.75 + 0.75 * symmetric_unit(engine);         // [1, 2.5)
  const double inner = 0.275 + 0.125 * symmetric_unit(engine);       // [0.15, 0.4)
  const double start = std::numbers::pi * (1 + symmetric_unit(engine));
  Curve curve{"spiral:seed=" + std::to_string(seed), {}};
  curve.components.emplace_back(
      std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Spiral_piece>(start, two_pi * turns, inner)},
      false);
  return curve;
}

namespace {

// The crossings of a closed curve of one component if they are all clean, else -1: the
// curve regular (turning at most 45° between samples), each crossing at an angle of at
// least 20° between its branches, and the crossings at least 0.05 apart, so that a
// sampling can tell them apart.
int transversal_crossings(const Curve& curve, int samples) {
  const Curve_component& component = curve.components.front();
  if (!walk_tangent(component, samples).turning) return -1;
  std::vector<std::vector<double>> parameters(1);
  for (int i = 0; i < samples; ++i) parameters[0].push_back(double(i) / samples);
  const std::vector<Curve_crossing> crossings = curve_crossings(curve, parameters);
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const Vector u = component.unit_tangent(crossings[i].first.parameter);
    const Vector v = component.unit_tangent(crossings[i].second.parameter);
    if (std::abs(CGAL::determinant(u, v)) < std::sin(std::numbers::pi / 9)) return -1;
    for (std::size_t j = 0; j < i; ++j)
      if (CGAL::squared_distance(crossings[i].point, crossings[j].point) < 0.05 * 0.05) return -1;
  }
  return static_cast<int>(crossings.size());
}

}  // namespace

Curve lissajous_curve(int a, int b, std::uint64_t seed) {
  if (a < 1 || b <= a || b > 5 || std::gcd(a, b) != 1)
    throw std::invalid_argument("lissajous: a and b must be coprime with 1 <= a < b <= 5");
  const std::string name = "lissajous:a=" + std::to_string(a) + ",b=" + std::to_string(b) + ",seed=" + std::to_string(seed);
  const int crossings = lissajous_crossings(a, b);
  for (std::uint64_t attempt = 0; attempt < 200; ++attempt) {
    std::mt19937_64 engine(derived_seed(seed, attempt));
    const double phase = std::numbers::pi * symmetric_unit(engine);
    const double width = 1.25 + 0.25 * symmetric_unit(engine);
    // x = width sin(a θ + phase), y = sin(b θ), plus a small smooth perturbation.
    std::vector<Fourier_piece::Harmonic> terms{
        {a, Vector(width * std::sin(phase), 0), Vector(width * std::cos(phase), 0)}, {b, Vector(0, 0), Vector(0, 1)}};
    for (int k = 1; k <= 4; ++k) {
      const double scale = 0.04 / k;
      const double ax = symmetric_unit(engine), ay = symmetric_unit(engine);
      const double bx = symmetric_unit(engine), by = symmetric_unit(engine);
      terms.push_back({k, scale * Vector(ax, ay), scale * Vector(bx, by)});
    }
    Curve curve{name, {}};
    curve.components.emplace_back(
        std::vector<std::shared_ptr<const Curve_piece>>{std::make_shared<Fourier_piece>(terms)}, true);
    if (transversal_crossings(curve, simplicity_samples) == crossings) return curve;
  }
  throw std::invalid_argument(name + ": no curve with " + std::to_string(crossings) + " transversal crossings");
}

}  // namespace curvebench::geometry
