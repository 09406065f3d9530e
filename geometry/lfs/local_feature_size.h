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
// a/b = 8 (2-core machine, 2026-12-06, with the branch ends below). The error falls as
// 1 / density²; the default, 32, keeps it 10x below 1e-3 (the test
// LocalFeatureSize.MatchesTheEllipseClosedFormWithinOnePerMille):
//
//   density | max relative error | dense points (a/b = 8) | build (a/b = 8)
//   --------+--------------------+------------------------+----------------
//        4  |       5.2e-3       |          256           |     1.0 ms
//        8  |       1.3e-3       |          524           |     1.7 ms
//       16  |       2.9e-4       |         1036           |     4.6 ms
//       32  |       9.5e-5       |         1856           |     6.8 ms
//       64  |       2.7e-5       |         3512           |    16.1 ms
//      128  |       6.2e-6       |         8192           |    27.7 ms
//
// The bound it states (stated_relative_error): at the default density and resolution the
// estimate reads at most lfs (1 + 2e-4) + resolution x diagonal. Checked against an oracle
// that shares nothing with this code (maximal empty balls of a dense sample by shrinking,
// tests/certify/lfs_oracle_test.cpp) where epsilon 0.2, 0.33 and 0.5 samplings attain their
// epsilon and at 50 of their samples each, on the 19 files of data/svg/ and 8 analytic
// curves: at most 9.6e-5 above it, relative, on every curve whose curvature is bounded;
// up to 9.4e-4 relative but 9.6e-6 of the diagonal absolute (Goldi.svg: 0.76 of the
// bound's slack) within a few resolutions of a point of unbounded curvature, where the
// refinement stops at the resolution.
//
// Sharp points: the corners of each component (Curve_component::corners()), the
// crossings of components (curve_crossings.h) and the points where the curvature is
// unbounded (radius of curvature below `resolution` of the diagonal: a Bézier end whose
// handle lies on it, Inkscape's "c 0,0", where the curve goes like y ~ x^(3/2)) are
// points of the medial axis' closure, so lfs is exactly 0 there and tends to 0 linearly
// nearby; samplers floor it.
//
// Branch ends: where the radius of curvature R changes fast, Voronoi vertices reach the
// end of a medial-axis branch (the centre of curvature at a curvature maximum) only to
// within about |dR/ds| times the sample spacing. At Bézier joins that are G1 but not G2
// the curvature jumps (50-fold on f5.svg), and lfs there read 16 % high. So the centres of
// curvature at the local maxima of |curvature| (inside pieces and on either side of each
// join) whose osculating disc is empty of the dense sample are added as exact medial
// points.
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

// A point of the curve where lfs is 0 (see "Sharp points" above).
struct Sharp_point {
  // Why lfs is 0 there.
  enum class Kind {
    corner,               // Curve_component::corners()
    crossing,             // listed once for each branch through it
    unbounded_curvature,  // a Bézier end whose handle lies on it (see above)
  };
  Point point;              // where it is in the plane
  Curve_location location;  // where it is on the curve (for a crossing: on one branch)
  Kind kind = Kind::corner;  // which of the three it is
};

// The lfs estimate of one curve (see above): built once, in the constructor, then read
// from any number of threads. Holds its own copy of the curve (the pieces are shared).
class Local_feature_size {
 public:
  // Dense points per lfs: chords are at most lfs / density (see the table above).
  static constexpr double default_density = 32;
  // The shortest chord refinement makes, as a fraction of the bounding-box diagonal.
  static constexpr double default_resolution = 1e-5;
  // How far above the true lfs the estimate may read at the default density and
  // resolution: lfs (1 + stated_relative_error) + resolution x the bounding-box diagonal
  // (measured: see the header comment).
  static constexpr double stated_relative_error = 2e-4;

  // Throws std::invalid_argument unless density and resolution are positive and finite.
  explicit Local_feature_size(const Curve& curve, double density = default_density,
                              double resolution = default_resolution);

  // The curve whose lfs this is; component indices and parameters refer to it.
  const Curve& curve() const { return curve_; }

  // lfs of a curve point p (for another point: its distance to the medial axis). 0 at a
  // sharp point; +infinity if the medial axis is empty (a straight open segment).
  double at(const Point& p) const { return medial_axis_.distance(p); }
  // lfs of the point at parameter s of a component; exactly 0 at its sharp points. The
  // values at the points of grid(component, s0, s1, k) for k = 1, 2, 4, 8 that lie between
  // two dense parameters are kept once computed (safe from any number of threads).
  double at(std::size_t component, double s) const;

  // The estimated medial axis that lfs is the distance to.
  const Medial_axis& medial_axis() const { return medial_axis_; }
  // Corners, points of unbounded curvature and crossings (listed once per branch), where
  // lfs is exactly 0.
  std::span<const Sharp_point> sharp_points() const { return sharp_points_; }
  // The diagonal of the bounding box of the curve's initial sample (16 points per piece):
  // the length that `resolution` and default_minimum_lfs are fractions of.
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
