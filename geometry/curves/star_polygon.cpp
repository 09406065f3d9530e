#include "geometry/curves/star_polygon.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "geometry/curves/closed_polyline.h"
#include "geometry/curves/curve_name.h"

namespace curvebench::geometry {
namespace {

constexpr double degree = std::numbers::pi / 180;

Vector rotated(const Vector& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

double length(const Vector& v) { return std::sqrt(v.squared_length()); }

// The vertices of one draw (tip, inner corner, tip, ...), or none if the draw is unusable.
std::vector<Point> star_vertices(std::mt19937_64& engine, double angle) {
  const auto uniform = [&] { return double(engine() >> 11) * 0x1.0p-53; };  // [0, 1), the same on every platform
  const int fewest = static_cast<int>(std::floor(360 / (165 - angle))) + 1;
  const int tips = std::max(3, fewest) + static_cast<int>(engine() % 6);
  const double spacing = 2 * std::numbers::pi / tips, rotation = spacing * uniform();
  std::vector<Point> tip_points;
  for (int j = 0; j < tips; ++j) {
    const double phi = rotation + spacing * (j + (uniform() - 0.5) / 4), radius = 0.8 + 0.2 * uniform();
    tip_points.emplace_back(radius * std::cos(phi), radius * std::sin(phi));
  }
  std::vector<Point> vertices;
  const double half = angle * degree / 2;
  for (int j = 0; j < tips; ++j) {
    const Point &t0 = tip_points[j], &t1 = tip_points[(j + 1) % tips];
    // The side leaving t0 and the side arriving at t1, each at half the opening from the ray to the centre.
    const Vector u = rotated(CGAL::ORIGIN - t0, -half), v = rotated(CGAL::ORIGIN - t1, half);
    const double det = CGAL::determinant(u, -v);
    if (det == 0) return {};
    const Vector offset = t1 - t0;
    const double s = CGAL::determinant(offset, -v) / det, r = CGAL::determinant(u, offset) / det;
    if (!(s > 0 && r > 0)) return {};
    const Point inner = t0 + s * u;
    if ((inner - CGAL::ORIGIN).squared_length() < 0.15 * 0.15) return {};
    vertices.push_back(t0);
    vertices.push_back(inner);
  }
  if (!closed_polyline_is_simple(vertices)) return {};
  for (std::size_t i = 1; i < vertices.size(); i += 2) {  // every inner corner turns right, by 10° or more
    const Vector in = vertices[i] - vertices[i - 1], out = vertices[(i + 1) % vertices.size()] - vertices[i];
    if (std::atan2(CGAL::determinant(in, out), in * out) > -10 * degree) return {};
  }
  return vertices;
}

// The sides and fillets of the polygon: side i runs from vertex i to vertex i + 1, cut back
// at both ends by the tangent length of its corners' fillets.
std::vector<std::shared_ptr<const Curve_piece>> star_pieces(const std::vector<Point>& vertices, double rounding) {
  const std::size_t n = vertices.size();
  std::vector<std::shared_ptr<const Curve_piece>> pieces;
  if (rounding == 0) {
    for (std::size_t i = 0; i < n; ++i) pieces.push_back(std::make_shared<Line_segment>(vertices[i], vertices[(i + 1) % n]));
    return pieces;
  }
  struct Fillet {
    Point from, to, center;
    double start, sweep;
  };
  std::vector<Fillet> fillets;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& corner = vertices[i];
    const Vector in = (corner - vertices[(i + n - 1) % n]), out = vertices[(i + 1) % n] - corner;
    const Vector d_in = in / length(in), d_out = out / length(out);
    const double turn = std::atan2(CGAL::determinant(d_in, d_out), d_in * d_out);
    const double tangent = rounding * std::tan(std::abs(turn) / 2);
    if (tangent > 0.45 * std::min(length(in), length(out))) return {};
    const Point from = corner - tangent * d_in, to = corner + tangent * d_out;
    const Vector left = d_in.perpendicular(CGAL::COUNTERCLOCKWISE);
    const Point center = from + (turn > 0 ? rounding : -rounding) * left;
    fillets.push_back({from, to, center, std::atan2(from.y() - center.y(), from.x() - center.x()), turn});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Fillet& next = fillets[(i + 1) % n];
    pieces.push_back(std::make_shared<Line_segment>(fillets[i].to, next.from));
    pieces.push_back(std::make_shared<Circular_arc>(next.center, rounding, next.start, next.sweep));
  }
  return pieces;
}

}  // namespace

Curve star_polygon(std::uint64_t seed, double angle, double rounding) {
  if (!(angle > 0 && angle < 150)) throw std::invalid_argument("star: angle must be in (0, 150) degrees");
  // A fillet far below the size of the star (1) is a corner in all but name: lfs 1e-300.
  if (!(rounding == 0 || rounding >= 1e-6) || !std::isfinite(rounding))
    throw std::invalid_argument("star: rounding must be 0 or in [1e-6, ...), finite");
  std::string name = "star:seed=" + std::to_string(seed) + ",angle=" + format_number(angle);
  if (rounding > 0) name += ",rounding=" + format_number(rounding);
  std::mt19937_64 engine(seed);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const std::vector<Point> vertices = star_vertices(engine, angle);
    if (vertices.empty()) continue;
    auto pieces = star_pieces(vertices, rounding);
    if (pieces.empty()) continue;
    Curve curve{name, {}};
    curve.components.emplace_back(std::move(pieces), true);
    return curve;
  }
  throw std::invalid_argument(name + ": no star polygon fits; lower the rounding");
}

}  // namespace curvebench::geometry
