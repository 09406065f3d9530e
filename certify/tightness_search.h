// How tight is a sampling-condition theorem (survey, "Guarantees as Sampling Conditions")?
// The certifier shows no failure below the proven bound b; this searches from the other
// side, adversarially, for a failing case whose measured epsilon (or rho) is as small as it
// can find: a smooth closed curve and a sampling of it that the algorithm does not
// reconstruct exactly. Together they bracket the true breakdown: no failure below b was
// seen, and one at f was built; f / b says how much room the proof leaves.
//
// The search, per curve (random Fourier curves of 1 to 8 harmonics and varied amplitude and
// decay, and star polygons with rounded corners; side-by-side Fourier curves too for an
// algorithm that reconstructs several):
//   1. the sparsest level: the theorem's safe sampler (epsilon=, rho=) at b x 1, 1.4, 2,
//      2.8, ... until the algorithm fails, then bisection between the last level that
//      passed and the first that failed (the failure need not be monotone in the level;
//      the search only needs a failing case);
//   2. densify: a sample is added in the middle of the interval where the measured value is
//      attained, kept while the case still fails (it lowers the measure wherever the
//      failure does not need that gap);
//   3. move samples: hill climbing on the sample positions (each move shifts one sample
//      along the curve by a random share of its interval, preferring the samples at the
//      worst interval and at the wrong edges), kept when the case still fails and its
//      measure does not grow.
// A case has three samples or more on every component (closed: a polygon to reconstruct).
// The measure is exact for the sample (certify/sampling_measure.h, true lfs, no floor);
// the algorithm runs in this process (built-in algorithms only; a crash would end the
// search, which `curvebench hunt` and the fuzz targets exist to find).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/algorithm.h"
#include "certify/theorems.h"
#include "geometry/sampling/sample.h"

namespace curvebench::certify {

// What search_tightness searches, and for how long.
struct Tightness_options {
  Measure measure = Measure::epsilon;  // the theorem on epsilon or the one on rho
  double seconds = 60;      // search time (a curve under way is finished)
  std::uint64_t seed = 0;   // of the curves and the moves
  std::size_t max_curves = 0;  // stop after this many curves; 0: search for `seconds`
  std::size_t moves = 60;      // step 3's tries per failing curve
};

// A case the search built: a curve and a sampling of it, with the algorithm's output.
struct Tightness_case {
  std::string curve;               // the curve spec (geometry/curves/curve_spec.h)
  geometry::Sample sample = {};    // on the curve, with its ground truth
  double measured = 0;             // its epsilon (rho)
  double level = 0;                // the sampler level that step 1 found
  std::vector<geometry::Edge> reconstruction = {};  // the algorithm's edges (not the ground truth)
  std::string error = {};          // or the algorithm's error, if it threw
  // Samples added in step 2.
  std::size_t added = 0, moved = 0;  // samples added in step 2, moves kept in step 3
};

// What search_tightness found.
struct Tightness_result {
  Theorem theorem;  // the theorem searched
  std::optional<Tightness_case> best = {};  // the failing case of smallest measure
  // Curves searched.
  std::size_t curves = 0, failing_curves = 0, evaluations = 0;  // samplings measured in all
  // The largest measure of a sampler level that met the hypotheses and passed: where no
  // failure is found, the search saw none up to here.
  double largest_passed = 0;
  double seconds = 0;  // the search's running time
  // \var failing_curves
  // Curves on which some sampler level failed.
};

// Throws std::invalid_argument if `algorithm` has no bound on options.measure.
Tightness_result search_tightness(const algorithms::Algorithm& algorithm, const Tightness_options& options);

// Whether `algorithm` reconstructs `sample` exactly (its own points, its ground truth), and
// its edges or error: what the search and its tests decide a case by.
struct Reconstruction_check {
  bool exact = false;                  // the edges are the ground truth's, on the sample's own points
  std::vector<geometry::Edge> edges;   // the algorithm's edges, canonical; empty if it threw
  std::string error;                   // what it threw, if it did
};
// Runs `algorithm` on sample.points through algorithms::reconstruct. An exception it
// throws is caught and returned in `error`, so this does not throw.
Reconstruction_check check_reconstruction(const algorithms::Algorithm& algorithm, const geometry::Sample& sample);

}  // namespace curvebench::certify
