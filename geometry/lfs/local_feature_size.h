// The local feature size (survey, "Definitions and Notations"): lfs(p) for a point p of
// the curve is its distance to the nearest point of the medial axis. Every sampling
// condition (epsilon, rho) and the lfs noise model are measured in it.
//
// Estimated from a Medial_axis built on a dense sample of the curve that adapts to the
// estimate itself: start from 16 points per piece, then split every chord longer than
// min(lfs at its ends, radius of curvature at its middle) / density, and rebuild, until no
// chord splits or chords reach `resolution` times the bounding-box diagonal (near sharp
// points, where lfs -> 0). lfs at a point is then its distance to the nearest point of
// the sample's Voronoi diagram that stands for the medial axis (medial_axis.h: its vertices,
// and points along its edges between samples that are not neighbours); it converges from
// above. Before the edges were kept, the ends of an open curve were measured against
// vertices only, which can be far: a circle's arc had lfs 1 at its ends instead of half
// its gap's chord (0.31 for a gap of a tenth of the circle).
//
// Measured: maximum relative error against the closed form over 2000 points of a circle
// (lfs = r) and of ellipses x²/a² + y²/b² = 1, a/b = 1.25, 2, 4, 8 (lfs = distance to the
// segment between (±(a²-b²)/a, 0)), with the size and build time of the estimate for
// a/b = 8. The error falls as 1 / density²; the default, 32, keeps it 5x below 1e-3
// (the test LocalFeatureSize.MatchesTheEllipseClosedFormWithinOnePerMille):
//
//   density | max relative error | dense points (a/b = 8) | build (a/b = 8)
//   --------+--------------------+------------------------+----------------
//        4  |       1.2e-2       |          288           |     0.6 ms
//        8  |       3.1e-3       |          532           |     1.1 ms
//       16  |       5.9e-4       |         1036           |     1.9 ms
//       32  |       1.9e-4       |         1856           |     5.2 ms
//       64  |       5.6e-5       |         3540           |     9.9 ms
//      128  |       1.3e-5       |         8192           |    17.9 ms
//
// Sharp points: the corners of each component (Curve_component::corners()) and the
// crossings of components (curve_crossings.h) are points of the medial axis' closure, so
// lfs is exactly 0 there and tends to 0 linearly nearby; samplers floor it.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "geometry/curves/curve.h"
#include "geometry/curves/curve_location.h"
#include "geometry/lfs/medial_axis.h"

namespace curvebench::geometry {

struct Sharp_point {
  Point point;
  Curve_location location;  // a crossing is listed once for each branch through it
};

class Local_feature_size {
 public:
  static constexpr double default_density = 32;
  static constexpr double default_resolution = 1e-5;

  // Throws std::invalid_argument unless density and resolution are positive and finite.
  explicit Local_feature_size(const Curve& curve, double density = default_density,
                              double resolution = default_resolution);

  const Curve& curve() const { return curve_; }

  // lfs of a curve point p (for another point: its distance to the medial axis). 0 at a
  // sharp point; +infinity if the medial axis is empty (a straight open segment).
  double at(const Point& p) const { return medial_axis_.distance(p); }
  // lfs of the point at parameter s of a component; exactly 0 at its sharp points. The
  // values at the points of grid(component, s0, s1, k) for k = 1, 2, 4, 8 that lie between
  // two dense parameters are kept once computed (safe from any number of threads).
  double at(std::size_t component, double s) const;

  const Medial_axis& medial_axis() const { return medial_axis_; }
  std::span<const Sharp_point> sharp_points() const { return sharp_points_; }
  double bounding_box_diagonal() const { return bounding_box_diagonal_; }

  // The dense sample's parameters of a component, increasing, in [0, piece_count()) if it
  // is closed, [0, piece_count()] if not: consecutive points are at most lfs / density apart.
  std::span<const double> dense_parameters(std::size_t component) const { return dense_parameters_[component]; }

  // s0, then the dense parameters strictly between s0 and s1 with each gap cut into
  // `subdivisions` equal steps, then s1: a grid along [s0, s1] finer than lfs / density.
  // On a closed component s1 may pass piece_count() (the grid goes round, s0 <= s1 < s0 + 2 n).
  std::vector<double> grid(std::size_t component, double s0, double s1, int subdivisions) const;

 private:
  struct Estimate;
  Local_feature_size(const Curve& curve, Estimate estimate);

  double uncached_at(std::size_t component, double s) const;
  std::atomic<std::uint64_t>* cached_at(std::size_t component, double s) const;

  Curve curve_;
  double bounding_box_diagonal_ = 0;
  std::vector<std::vector<double>> dense_parameters_;
  std::vector<Sharp_point> sharp_points_;
  std::vector<std::vector<double>> sharp_parameters_;  // of each component, sorted
  Medial_axis medial_axis_;
  // at(component, s) at the points of every grid (the dense parameters' gaps cut in 8, or
  // in 4 or 1: the same doubles), which the samplers and measures revisit many times:
  // filled as they are asked for, the bits of the double or `unknown`. Threads may race to
  // fill a slot; they write the same bits.
  static constexpr int cached_subdivisions = 8;
  std::vector<std::unique_ptr<std::atomic<std::uint64_t>[]>> cache_;
};

// distance / max(lfs, minimum_lfs), the ratio that epsilon and rho compare, without NaN:
// 0 / 0 = 0 (a sample at a sharp point) and d / 0 = +infinity.
double relative_distance(double distance, double lfs, double minimum_lfs);

}  // namespace curvebench::geometry
