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

using Vector = Kernel::Vector_2;

// A smooth parametric arc with its first two derivatives, t in [0, 1].
class Curve_piece {
 public:
  virtual ~Curve_piece() = default;
  virtual Point point(double t) const = 0;
  virtual Vector derivative(double t) const = 0;
  virtual Vector second_derivative(double t) const = 0;
};

class Curve_component {
 public:
  // The pieces must join (each ends where the next begins; a closed component's last
  // ends where its first begins) and be regular (non-zero derivative). Throws
  // std::invalid_argument if there is no piece or a join is off by more than 1e-9 of the
  // component's size.
  Curve_component(std::vector<std::shared_ptr<const Curve_piece>> pieces, bool closed);

  bool closed() const { return closed_; }
  std::size_t piece_count() const { return pieces_.size(); }
  const Curve_piece& piece(std::size_t i) const { return *pieces_[i]; }

  Point point(double s) const;
  Vector derivative(double s) const;
  Vector second_derivative(double s) const;
  Vector unit_tangent(double s) const;  // at a join: that of the piece starting there
  Vector unit_normal(double s) const;   // the unit tangent turned +90 degrees
  double curvature(double s) const;     // signed; positive where the curve turns left

  double length() const { return cumulative_length_.back(); }
  double arc_length(double s) const;  // from s = 0 to s
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

struct Curve {
  std::string name;  // how it was made, e.g. "ellipse:a=2,b=1" or "glyph:DejaVuSans.ttf:g"
  std::vector<Curve_component> components;

  double length() const;
  Kernel::Iso_rectangle_2 bounding_box(double tolerance) const;  // of the polylines
};

// Pieces every other curve source builds on.
class Line_segment final : public Curve_piece {
 public:
  Line_segment(const Point& source, const Point& target) : source_(source), target_(target) {}
  // Blended so that t = 0 and t = 1 give the end points bit-exactly.
  Point point(double t) const override {
    return CGAL::ORIGIN + ((1 - t) * (source_ - CGAL::ORIGIN) + t * (target_ - CGAL::ORIGIN));
  }
  Vector derivative(double) const override { return target_ - source_; }
  Vector second_derivative(double) const override { return {0, 0}; }

 private:
  Point source_, target_;
};

// The arc of the circle (center, radius) from angle `start` to `start + sweep` radians
// (counterclockwise if sweep > 0).
class Circular_arc final : public Curve_piece {
 public:
  Circular_arc(const Point& center, double radius, double start, double sweep);
  Point point(double t) const override;
  Vector derivative(double t) const override;
  Vector second_derivative(double t) const override;

 private:
  Point center_;
  double radius_, start_, sweep_;
};

}  // namespace curvebench::geometry
