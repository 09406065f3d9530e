// A planar curve whose geometry is known exactly: the ground truth that samplers draw
// points from and that lfs, the sampling conditions and the metrics are measured on.
//
// A Curve is a set of components (survey, "Definitions and Notations": one or several
// closed or open curves). A component is a chain of smooth pieces c_i(t), t in [0, 1],
// each ending where the next begins; a join may be a sharp corner. A component is
// addressed by one parameter s in [0, piece_count()]: piece floor(s) at t = s - floor(s).
//
// Curves are constructions: they produce coordinates and measured values, never
// decisions inside an algorithm, so they are evaluated in double.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/kernel.h"

namespace curvebench::geometry {

// A vector of the plane: derivatives, tangents and normals of curves.
using Vector = Kernel::Vector_2;

// A smooth parametric arc with its first two derivatives, t in [0, 1].
class Curve_piece {
 public:
  virtual ~Curve_piece() = default;
  // The point at parameter t; point(0) is the start of the piece and point(1) its end.
  virtual Point point(double t) const = 0;
  // d point / dt at t: non-zero on [0, 1] (the piece is regular); its length is the speed
  // in curve units per unit of t, not 1.
  virtual Vector derivative(double t) const = 0;
  // d² point / dt² at t.
  virtual Vector second_derivative(double t) const = 0;
};

// One connected component of a Curve: a chain of Curve_pieces, open or closed,
// addressed by s in [0, piece_count()] (piece floor(s) at t = s - floor(s)). Copies share
// the pieces, which are immutable.
class Curve_component {
 public:
  // The pieces must join (each ends where the next begins; a closed component's last
  // ends where its first begins) and be regular (non-zero derivative). Throws
  // std::invalid_argument if there is no piece or a join is off by more than 1e-9 of the
  // component's size.
  Curve_component(std::vector<std::shared_ptr<const Curve_piece>> pieces, bool closed);

  // Whether the last piece ends where the first begins (a closed curve, not an arc).
  bool closed() const { return closed_; }
  // At least 1; the parameter s runs over [0, piece_count()].
  std::size_t piece_count() const { return pieces_.size(); }
  // Piece i, for i < piece_count() (not checked).
  const Curve_piece& piece(std::size_t i) const { return *pieces_[i]; }

  // The point at parameter s. A closed component takes s modulo piece_count(); an open
  // one clamps s to [0, piece_count()]. At a join: the start of the next piece.
  Point point(double s) const;
  // d point / ds of the piece that holds s (s handled as in point()): at a join, that of
  // the piece starting there.
  Vector derivative(double s) const;
  // d² point / ds² of the piece that holds s, as derivative().
  Vector second_derivative(double s) const;
  Vector unit_tangent(double s) const;  // at a join: that of the piece starting there
  Vector unit_normal(double s) const;   // the unit tangent turned +90 degrees
  double curvature(double s) const;     // signed; positive where the curve turns left

  // The arc length of the whole component (8-point Gauss-Legendre on 16 steps per piece).
  double length() const { return cumulative_length_.back(); }
  double arc_length(double s) const;  // from s = 0 to s
  // The inverse of arc_length(): the s in [0, piece_count()] at which the arc length from
  // s = 0 is `length`, clamped to [0, length()] (Newton's method, to 1e-15 of length()).
  double parameter_at_arc_length(double length) const;

  // Parameters of the joins where the unit tangent turns by more than `angle` radians.
  std::vector<double> corners(double angle = 1e-6) const;

  // Points along the component, each chord within `tolerance` (at least 1e-12 of the
  // length) of the curve; a closed component does not repeat its first point.
  std::vector<Point> polyline(double tolerance) const;

 private:
  std::pair<std::size_t, double> locate(double s) const;  // piece and local t
  double piece_arc_length(std::size_t piece, double t0, double t1) const;

  std::vector<std::shared_ptr<const Curve_piece>> pieces_;
  bool closed_;
  // Arc length at the start of each of `subdivisions` equal steps of every piece.
  static constexpr int subdivisions = 16;
  std::vector<double> cumulative_length_;
};

// A curve of the survey ("Definitions and Notations"): one or several components, each a
// closed or open curve, and the spec that makes it again (curve_spec.h).
struct Curve {
  std::string name;  // how it was made, e.g. "ellipse:a=2,b=1" or "glyph:DejaVuSans.ttf:g"
  std::vector<Curve_component> components;  // may be empty (a glyph without outline)

  // The sum of the components' lengths; 0 for no component.
  double length() const;
  Kernel::Iso_rectangle_2 bounding_box(double tolerance) const;  // of the polylines
};

// Pieces every other curve source builds on.
class Line_segment final : public Curve_piece {
 public:
  // The straight piece from `source` (t = 0) to `target` (t = 1); they must differ for the
  // piece to be regular (not checked).
  Line_segment(const Point& source, const Point& target) : source_(source), target_(target) {}
  // Blended so that t = 0 and t = 1 give the end points bit-exactly.
  Point point(double t) const override {
    return CGAL::ORIGIN + ((1 - t) * (source_ - CGAL::ORIGIN) + t * (target_ - CGAL::ORIGIN));
  }
  // target - source, at every t.
  Vector derivative(double) const override { return target_ - source_; }
  // The zero vector.
  Vector second_derivative(double) const override { return {0, 0}; }

 private:
  Point source_, target_;
};

// The arc of the circle (center, radius) from angle `start` to `start + sweep` radians
// (counterclockwise if sweep > 0).
class Circular_arc final : public Curve_piece {
 public:
  // Throws std::invalid_argument unless radius > 0 and sweep != 0.
  Circular_arc(const Point& center, double radius, double start, double sweep);
  // center + radius (cos a, sin a) at the angle a = start + sweep t.
  Point point(double t) const override;
  // radius sweep (-sin a, cos a): speed |radius sweep|.
  Vector derivative(double t) const override;
  // -radius sweep² (cos a, sin a), towards the center.
  Vector second_derivative(double t) const override;

 private:
  Point center_;
  double radius_, start_, sweep_;
};

}  // namespace curvebench::geometry
