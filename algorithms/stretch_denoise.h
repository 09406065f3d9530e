// StretchDenoise (Ohrhallinger, Wimmer 2018, "StretchDenoise: Parametric Curve
// Reconstruction with Guarantees by Separating Connectivity from Residual Uncertainty of
// Samples", Pacific Graphics; survey, "Noisy Points Fitting" and "Robustness to Noise"):
// pass 1 recovers a manifold connectivity of the noisy points; pass 2 moves every vertex
// of that polygon along its estimated normal, at most its noise cut-off, so that the
// turning angles become small in the least-squares sense while the polygon stays
// balanced between the samples (inside/outside), iterated to convergence.
//
// Pass 1 is FitConnect's connectivity pass (algorithms/fit_connect.h), as in the authors'
// program: it thins a noisy band to a chain of representative points, with exact
// decisions; pass 2 only computes output coordinates (in double). Output: the
// representative points, moved, with FitConnect's edges between them; every other input
// point is dropped, as in the authors' program. Pass 2 per chain (a path or a cycle),
// in coordinates translated and scaled by a power of two so that 1e-300 and 1e300 inputs
// neither underflow nor overflow:
//   - a window of `window` chain neighbours on each side gets a least-squares quadratic
//     in the frame of its principal axis; its normal at the vertex is the direction of
//     movement, its largest residual the vertex's noise estimate;
//   - the cut-off of vertex i is min(cutoff_scale * the largest estimate in its window,
//     max_cutoff * its local spacing (the mean length of its input edges));
//   - displacements t along the normals minimise
//       sum_i theta_i^2 + balance * sum_i (mean of t over i +- balance_window / s_i)^2
//                       + fidelity * sum_i (t_i / s_i)^2,   |t_i| <= cutoff_i,
//     theta_i the signed turning angle at i, by Levenberg-Marquardt (exact derivatives of
//     the angles, a step accepted only if it lowers the energy) whose normal equations are
//     a symmetric banded matrix (cyclic for a closed chain, factored by our own banded
//     Cholesky with a dense tail, O(n) per step); bounds by the authors' active-set rule:
//     a variable that would leave its bound is fixed there and the rest solved again.
//
// Deviations from the authors' code (stefango74/stretchdenoise, Reconstruct2D.cpp,
// ConstrainedLS.cpp), and why:
//  - Connectivity: the same pass as theirs, with FitConnect's deviations (fit_connect.h).
//    Chains of fewer than three points do not move.
//  - Normals and noise extents: they take the normal and the largest residual of a fitted
//    circle (Chernov's hyper fit); we fit a quadratic over a fixed window of chain
//    neighbours (no fit needs a growing neighbourhood once the chain is known).
//  - Balance: they impose one linear equality per run of vertices a line fits through
//    (sum of signed sample-to-edge distances = 0), solved densely by Lagrange
//    multipliers with explicit inverses (Eigen, O(k^3) per run). Each sample here is a
//    vertex, so its signed distance to the moved polygon is about -t_i, and we ask the
//    windowed mean of t to vanish as a weighted least-squares term: the same balance,
//    local everywhere instead of per run, and the system stays banded (no Eigen; it is
//    not installed here, and a dense solve would be O(n^3)).
//  - Angles: they linearise an angle proxy (sagitta / baseline) once per run and solve
//    once; we minimise the true turning angles by iterated Levenberg-Marquardt with exact
//    derivatives, over the whole chain at once (no runs, no sharp-vertex splitting).
//  - A small fidelity term (their code has none) makes the problem strictly convex in
//    directions the angles do not see (moving a straight run or a circle rigidly), so the
//    result does not depend on the solver's path.
//  - Parameters: the authors call the method parameter-free (noise extents estimated or
//    from a sensor model); ours are exposed, with the defaults below.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// StretchDenoise's settings; the registry exposes each as a parameter of the same name.
struct Stretch_denoise_options {
  int window = 3;             // chain neighbours on each side in a normal / noise fit
  double cutoff_scale = 1.0;  // cut-off = this * estimated noise extent ...
  double max_cutoff = 1.0;    // ... but at most this * local spacing
  double balance = 3.0;       // weight of the local balance (mean displacement 0)
  int balance_window = 1;     // chain neighbours on each side in that mean
  double fidelity = 0.1;      // weight of the pull towards the input point
  int iterations = 50;        // Levenberg-Marquardt steps at most, per chain
  int max_neighbors = 1024;   // the connectivity pass's largest neighbourhood
};

// The output of stretch_denoise, with what each output point was allowed and where it came
// from.
struct Stretch_denoise_result {
  Reconstruction reconstruction;  // the representative points, denoised, and FitConnect's edges
  std::vector<double> cutoff;     // per output point: how far it was allowed to move
  std::vector<std::size_t> source;  // per output point: the input point it represents
};

// Exact duplicates are merged first. Throws std::invalid_argument on a non-finite
// coordinate.
Stretch_denoise_result stretch_denoise(std::span<const Point> points, const Stretch_denoise_options& options = {});
// stretch_denoise(points, options).reconstruction.
Reconstruction stretch_denoise_reconstruction(std::span<const Point> points,
                                              const Stretch_denoise_options& options = {});
// The registry's entry "stretch-denoise", with the parameters of Stretch_denoise_options.
Algorithm stretch_denoise_algorithm();

}  // namespace curvebench::algorithms
