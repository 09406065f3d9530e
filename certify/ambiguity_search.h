// The ambiguity hunt: point sets S that are epsilon-samplings of two different smooth
// simple closed curves C1, C2 whose polygons through S (in C1's order, in C2's order)
// differ, with max(epsilon(S, C1), epsilon(S, C2)) as small as we can make it.
//
// Background: Bjerkevik, "Tighter bounds for reconstruction from epsilon-samples"
// (SoCG 2022) proves that every 0.66-sample of a plane curve determines the curve's
// polygon, and constructs a 0.72-sample of two curves with different polygons; between
// the two the question is open. Epsilon is the survey's ("Definitions and Notations"):
// sup over the curve of (distance to the nearest sample) / lfs, measured exactly as the
// rest of curvebench measures it (measure_epsilon on a geometry::Local_feature_size).
//
// Method, in three lines:
//   1. a curve through S in a given cyclic order is the closed C2 cubic spline through
//      the points (centripetal knot intervals, each scaled by a free factor), as Béziers;
//   2. a start is a sparse sample of a generated (random Fourier) curve and a second
//      cyclic order from one or-opt or 2-opt move that keeps the polygon simple;
//   3. hill climbing over point positions and knot factors (deterministic from the seed)
//      minimises max(eps1, eps2), rejecting any step where a curve crosses itself or
//      has a cusp (a sharp point of its Local_feature_size).
// Or (`mirror`) the search keeps S symmetric under the mirror R: x -> -x and C2 = R(C1),
// starting from where a random curve crosses its mirror image: eps2 = eps1 throughout, and
// the orders differ globally, as a curve differs from its mirror image.
//
// Not a proof: the lfs is an estimate (local_feature_size.h: converges from above, at most
// 2e-4 high relative plus its resolution, so a measured epsilon may be low by about that
// factor), and the search only sees curves of this spline family.
// The search decides on doubles: it is an experiment's driver, not an algorithm, and
// none of its decisions feed a reconstruction.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "geometry/curves/cubic_bezier.h"
#include "geometry/curves/curve.h"
#include "geometry/curves/curve_location.h"
#include "geometry/edge.h"
#include "geometry/lfs/local_feature_size.h"

namespace curvebench::certify {

using geometry::Edge;
using geometry::Point;

//---- the closed interpolating spline -------------------------------------------------

// The centripetal knot intervals sqrt(|q_i q_{i+1}|) of the closed polygon q_0 .. q_{n-1}
// (they keep a cubic spline free of cusps and loops inside a span better than chord length).
std::vector<double> centripetal_knot_intervals(std::span<const Point> points);

// The closed C2 cubic spline through q_0 .. q_{n-1} (n >= 3, consecutive points distinct,
// intervals positive and finite): segment i runs from q_i to q_{i+1 mod n} over a knot
// interval of length h_i, and value, first and second derivative agree at every knot.
// Returned as the Bézier control points of each segment. O(n): the knot derivatives
// solve a cyclic tridiagonal system (strictly diagonally dominant) by Sherman-Morrison.
// Throws std::invalid_argument on bad input.
std::vector<std::array<Point, 4>> closed_spline_controls(std::span<const Point> points,
                                                         std::span<const double> knot_intervals);

// The same as a one-component closed geometry::Curve (append_cubic_bezier per segment).
geometry::Curve closed_spline_curve(std::span<const Point> points, std::span<const double> knot_intervals,
                                    std::string name = "spline");

//---- an ambiguous case ----------------------------------------------------------------

// A candidate: the point set S and, for each of the two curves, its order of S, its knot
// factors and its via points. Curve k (0 or 1) is C1 or C2.
struct Ambiguity_case {
  std::vector<Point> points;                       // S
  std::array<std::vector<std::size_t>, 2> orders;  // the cyclic order of S along C1, C2
  // Natural logarithms of the factors on each curve's centripetal knot intervals, one per
  // interval between the points it interpolates (ordered_points); empty means all 0.
  std::array<std::vector<double>, 2> log_knot_factors;
  // Points a curve passes through that are not samples, so that it can bend between two
  // samples more freely than one spline segment: via[k][e] lies between orders[k][e] and
  // orders[k][e+1]. Empty: none.
  std::array<std::vector<Point>, 2> via;
};

// The points curve k interpolates in order (S in its order, each via point after its
// sample), its knot intervals, its curve and its polygon's edges (canonical_edges form).
std::vector<Point> ordered_points(const Ambiguity_case& c, int k);
std::vector<double> knot_intervals(const Ambiguity_case& c, int k);  // centripetal, times the knot factors
std::vector<std::array<Point, 4>> curve_controls(const Ambiguity_case& c, int k);  // Bézier controls per segment
geometry::Curve ambiguity_curve(const Ambiguity_case& c, int k);  // named "spline C1" or "spline C2"
std::vector<Edge> order_edges(std::span<const std::size_t> order);  // the closed polygon of a cyclic order

// A case measured: whether it counts, and each curve's epsilon with where it is attained.
struct Ambiguity_measure {
  bool valid = false;  // both curves smooth and simple, the two polygons differ
  std::array<double, 2> epsilon{};                  // epsilon(S, C1), epsilon(S, C2); read only if valid
  std::array<geometry::Curve_location, 2> where{};  // where each epsilon is attained
  std::array<Point, 2> worst_point{};               // and that curve point
  // The larger of the two epsilons; infinity unless valid.
  double max_epsilon() const { return valid ? std::max(epsilon[0], epsilon[1]) : INFINITY; }
};

// Builds both curves' Local_feature_size at `density` and measures S against each with
// measure_epsilon(lfs, S, 0), the project's unfloored epsilon. A curve is smooth and simple
// iff its lfs estimate found no sharp point (no corner from a cusp, no crossing from
// geometry/curves/curve_crossings.h).
Ambiguity_measure measure_ambiguity(const Ambiguity_case& c,
                                    double density = geometry::Local_feature_size::default_density);

//---- the search -----------------------------------------------------------------------

// How search_ambiguity searches: how many starts, how far each climbs, which cases.
struct Ambiguity_search_options {
  std::size_t count = 6;          // independent starts
  std::size_t points = 0;         // |S| per start; 0: drawn from 6 .. 16 for each start
  std::uint64_t seed = 0;         // of every random choice (each start has its own stream)
  std::size_t evaluations = 1500;  // hill-climbing steps per start (two lfs builds each)
  double search_density = 8;      // lfs density while searching (error ~3e-3, 6x faster)
  // How close two points of S may come, relative to the start's mean polygon edge. At 0
  // the climb typically ends in a trap: two swapped points merge and both curves make a
  // tiny Z-fold there, which measures about 1.31 however the rest moves. Measured: 0.2
  // keeps out of it but ends higher (1.51 for 6 starts x 1500 steps, seed 0), so 0.
  double minimum_separation = 0;
  // After the climb, give each curve a via point between every two consecutive samples
  // (Ambiguity_case::via), placed on the curve, and climb `evaluations` steps more, moving
  // them like the samples. Measured (mirror, seed 0, 3000 steps per stage): the best of 30
  // starts goes from 1.223 to 1.197; via points from the first step instead ended at
  // 1.337 (20 starts), the larger space slowing the climb.
  bool via_points = false;
  // Search mirror-symmetric cases only: S = R(S) and C2 = R(C1) for the mirror R: x -> -x,
  // from the crossings of a random curve with its mirror image (`points`, if set, is then
  // the exact size of S; otherwise 6 to 20).
  bool mirror = false;
};

// The best case over all starts, and what the search did to find it.
struct Ambiguity_search_result {
  Ambiguity_case best;        // the case of least max epsilon at the default lfs density
  Ambiguity_measure measure;  // of `best`, re-measured at the default lfs density
  std::size_t best_start = 0;  // the start it came from, 0-based
  std::vector<double> start_results;  // each start's final max epsilon (default density)
  std::size_t evaluations = 0;        // measure_ambiguity calls in all
};

// Deterministic: the same options give the same result, bit for bit, on one machine.
Ambiguity_search_result search_ambiguity(const Ambiguity_search_options& options);

//---- output ---------------------------------------------------------------------------

// The paths write_ambiguity_case wrote, all in its directory.
struct Ambiguity_files {
  // points.xy: S.
  std::filesystem::path points, edges[2], curves[2], picture, summary, replay;  // replay.sh
  // \var edges
  // edges_1.edges and edges_2.edges: the polygons of C1 and C2.
  // \var curves
  // curve_1.svg and curve_2.svg: C1 and C2 as SVG cubic paths.
  // \var picture
  // picture.svg: S, C1 and C2.
  // \var summary
  // summary.json.
};

// Writes the case into `directory` (created if needed): points.xy, edges_1.edges,
// edges_2.edges (the two polygons, point_io / edge_io formats), curve_1.svg, curve_2.svg
// (each curve as an SVG cubic path, readable as the curve spec svg:FILE), picture.svg (S,
// C1 and C2 in two colours), summary.json ({points, epsilon_1, epsilon_2, max_epsilon,
// lfs_error_bound, seed, ...}) and replay.sh (re-measures both with `curvebench measure`).
// `extra` adds numeric fields to the summary (e.g. the search's running time).
Ambiguity_files write_ambiguity_case(const std::filesystem::path& directory, const Ambiguity_case& c,
                                     const Ambiguity_measure& measure, std::uint64_t seed,
                                     std::span<const std::pair<std::string, double>> extra = {});

// The relative error of the lfs estimate at the default density as measured on circles and
// ellipses against closed forms before the ends of medial-axis branches were given exactly
// (now 9.5e-5; local_feature_size.h states 2e-4 plus the resolution): kept, so that the
// committed cases' summaries replay. Not a proof bound: on a found case with a tight
// Z-fold, re-measuring at density 128 moved epsilon by 3.9e-4.
inline constexpr double lfs_relative_error_bound = 1.9e-4;

}  // namespace curvebench::certify
