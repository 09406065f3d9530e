// A reconstruction algorithm as the registry describes it: how to call it, its
// parameters, its capability row from the survey's Table 1 ("Algorithms grouped by
// categories, with their input and output capabilities") and its proven sampling
// condition from the survey's table in "Guarantees as Sampling Conditions".
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

#include "algorithms/parameters.h"
#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::algorithms {

using geometry::Edge;
using geometry::Point;

// A curve as edges between points. `points` is empty when the edges index the input
// points; an algorithm that moves or drops points (denoising, outlier removal) returns
// its own points and the edges index those.
struct Reconstruction {
  std::vector<Edge> edges;  // each (i, j) with i < j, sorted, no repeats
  std::vector<Point> points;  // the points the edges index; empty: the input points
};

// Table 1's yes / no, and "only" (the EMST reconstructs only open curves).
enum class Support { no, yes, only };

// An algorithm's row of the survey's Table 1: the input it handles, the output it gives.
struct Capabilities {
  Support non_uniform = Support::no;  // input: non-uniform sampling
  Support noise = Support::no;        // input: noisy points
  Support outliers = Support::no;     // input: outliers
  Support manifold = Support::no;     // output: a manifold curve
  Support open = Support::no;         // output: open curves (curves with ends)
  Support multiple = Support::no;     // several components
  Support sharp = Support::no;        // sharp corners
  bool guarantee = false;              // a proven sampling condition
  std::string_view time_complexity;    // as Table 1 states it: "O(n log n)"
};

// The condition under which a manifold curve is provably reconstructed exactly. The
// bounds are strict (epsilon < bound); unset means the paper states no such bound.
struct Sampling_condition {
  std::string_view statement;               // as the survey writes it, "none" if there is none
  std::optional<double> epsilon_below = {};       // epsilon-sampling (Amenta, Bern)
  std::optional<double> rho_below = {};           // HNN-Crust's reach-based rho-sampling
  std::optional<double> corner_angle_above = {};  // GathanG: sharp corners' opening angle, degrees
  std::optional<double> uniformity_below = {};    // Connect2D: longer / shorter edge at every point
  bool covers_open_curves = false;                 // the bound holds for curves with ends too
};

// Reconstructs from distinct points (the registry's reconstruct() merges duplicates
// first), with checked parameter values. The same points and values must give the same
// result in any process, at any time (a random generator seeded by the call, ties broken
// by point index, never by address or clock): the runner, the hunt, the fuzzers and the
// determinism test compare runs, and a merged or resumed run is one run only then.
using Reconstruct = std::function<Reconstruction(std::span<const Point>, const Parameter_values&)>;

// Runs `edges_of` on `points` sorted by x, then y, and names the ends of its edges by their
// index in `points`: a tie the function breaks by index is then broken by coordinates, so
// its result cannot follow the order the points came in.
std::vector<Edge> edges_in_lexicographic_order(std::span<const Point> points,
                                               const std::function<std::vector<Edge>(std::span<const Point>)>& edges_of);

// The registry's call for an algorithm whose result is edges on its input points:
// `f(points)` for one without parameters, `f(points, values)` for one with. `f` sees the
// points sorted (edges_in_lexicographic_order), so its index ties are coordinate ties.
template <class F>
Reconstruct edges_on_input(F f) {
  return [f](std::span<const Point> points, const Parameter_values& values) {
    return Reconstruction{edges_in_lexicographic_order(points, [&](std::span<const Point> sorted) -> std::vector<Edge> {
                            if constexpr (std::is_invocable_v<const F&, std::span<const Point>>)
                              return f(sorted);
                            else
                              return f(sorted, values);
                          }),
                          {}};
  };
}

// One algorithm of the registry: its names, parameters, Table 1 row and sampling
// condition, and the call that runs it.
struct Algorithm {
  std::string_view name;       // as typed on the command line: "nn-crust"
  std::string_view title;      // as the survey writes it: "NN-Crust"
  std::string_view reference;  // authors and year of the paper
  std::string_view category;   // the survey's group in Table 1: "Feature Size Criteria"
  std::vector<Parameter> parameters;  // what Parameter_values may set; empty: none
  Capabilities capabilities;          // its row of Table 1
  Sampling_condition condition;       // its proven sampling condition, if any
  Reconstruct reconstruct;            // the bare call: registry.h's reconstruct() checks and merges first
  // True for a method that simplifies rather than interpolates (Optimal Transport): its
  // output vertices are a subset of the input, so the survey scores it apart ("Comparison
  // and Evaluation": "we have not included it in any of our experiments"), and so does
  // the report, by distance and topology instead of exactness.
  bool simplifies = false;
};

}  // namespace curvebench::algorithms
