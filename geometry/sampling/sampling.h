// Samplers of a Curve, each returning a Sample (points, ground-truth edges, lfs, where
// each point lies on the curve). Survey, "Sampling Tools" (epsilon-sampling by a greedy
// walk), "Definitions and Notations" (epsilon-sampling, reach) and "Feature Size
// Criteria Reconstruction" (HNN-Crust's rho-sampling).
//
// lfs comes from a Local_feature_size, built once per curve and shared by every sampler.
// Near a sharp point lfs -> 0 and a walk would never pass it: the lfs-driven samplers
// place a sample on every corner and count lfs below `minimum_lfs` as `minimum_lfs`
// (Sample::floored lists where). Crossings get no sample of their own (it would be two
// coincident points); the floor bounds the sampling around them. with_crossing_samples
// adds one, shared by both branches.
//
// Measured (certify_test, EpsilonSampling.OfACircleMeasuresAboutHalfItsEpsilon): the survey's walk admits a step while the distance to the
// last sample is below epsilon lfs, so the point halfway between two samples is about
// epsilon / 2 lfs from both: on a circle its measured epsilon is 2 sin(asin(epsilon/2)/2),
// e.g. 0.252 for epsilon = 0.5. safe_epsilon_sampling walks by the definition instead and
// verifies the result: its measured epsilon is just below the target.
#pragma once

#include <cstdint>

#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sample.h"

namespace curvebench::geometry {

// 1e-3 of the bounding-box diagonal: below the lfs of every smooth curve this project
// generates at its usual sizes, above the lfs resolution of Local_feature_size.
double default_minimum_lfs(const Local_feature_size& lfs);

// The survey's walk: from a sample s_i (a corner, a component's start or its ends), the
// next sample is the last curve point s_j, going along the curve, with
// ||s_i s_j|| < epsilon max(lfs(s_j), minimum_lfs) for all points up to it (the dense lfs
// sample as candidates, the boundary refined by bisection). Throws std::invalid_argument
// unless epsilon > 0 and minimum_lfs > 0.
Sample epsilon_sampling(const Local_feature_size& lfs, double epsilon, double minimum_lfs);

// A sampling whose measured epsilon (sup over the curve of distance to the nearest sample
// / lfs) is at most epsilon, with few points: the greedy walk admits s_j while every
// curve point p between s_i and s_j (the dense lfs sample) has
// min(||p s_i||, ||p s_j||) < epsilon max(lfs(p), minimum_lfs) (1e-3 margin, and the
// Lipschitz slack of the grid step); then each interval between adjacent samples is
// searched densely (curve_search.h) and split at its worst point while that exceeds
// epsilon (1e-3 margin). Measured: within 5% below the target (certify_test).
Sample safe_epsilon_sampling(const Local_feature_size& lfs, double epsilon, double minimum_lfs);

// Connect2D's two hypotheses at once (Ohrhallinger, Mudur 2013: epsilon < 1/2 and local
// uniformity u < 1.609, u = the longer / shorter chord at a point): samples spaced by a
// size field, scale x the envelope of lfs of some slope, placed by equidistributing the
// integral of 1 / size along the arc length, so that adjacent chords differ little. The
// scale is searched (bisection, 12 steps) for the sparsest sampling whose epsilon,
// searched as safe_epsilon_sampling verifies it, is at most epsilon; the slope is halved
// while u is not below `uniformity` (both with a 1e-3 margin). Smooth curves only: throws
// std::invalid_argument for a corner, a bad bound, or no sampling that meets both.
Sample graded_epsilon_sampling(const Local_feature_size& lfs, double epsilon, double uniformity, double minimum_lfs);

// HNN-Crust's rho-sampling (Ohrhallinger, Mitchell, Wimmer 2016). The reach of a curve
// interval I is inf { lfs(p) : p in I }; the interval between adjacent samples s_i, s_{i+1}
// is rho-sampled if half its chord is below rho times its reach,
//     ||s_i s_{i+1}|| / 2 < rho reach(I),
// i.e. the disc on the chord as diameter is small against the interval's distance to the
// medial axis. (Our reading of the paper; it matches the survey's rho = epsilon / (1 -
// epsilon): a point halfway along I is within epsilon lfs of an end of I, and lfs is
// 1-Lipschitz, so an epsilon-sampling has half-chords below epsilon (reach + half-chord).)
// Greedy walk as above with this condition, reach floored at minimum_lfs.
Sample rho_sampling(const Local_feature_size& lfs, double rho, double minimum_lfs);

// A sampling whose measured rho (certify/sampling_measure.h) is at most rho: the walk at
// rho (1 - 1e-3), then each interval, its reach searched along the curve as the measure
// does, halved while its rho exceeds rho (1 - 1e-3).
Sample safe_rho_sampling(const Local_feature_size& lfs, double rho, double minimum_lfs);

// n points at equal arc-length steps: each component gets its share of n by length
// (largest remainders; at least 1 for a closed component, 2 for an open one), a closed
// one k points at lengths j L / k, an open one at j L / (k - 1), both ends included.
// Throws std::invalid_argument if n is below those minimums.
Sample uniform_sampling(const Local_feature_size& lfs, std::size_t n);

// Points at arc-length steps of at most `spacing` (equal steps on each component).
Sample uniform_sampling_with_spacing(const Local_feature_size& lfs, double spacing);

// `sample` (of lfs.curve(), straight from a sampler) with one more point at each crossing
// of the curve (Local_feature_size::sharp_points() listed for two branches), shared by both
// branches: the ground-truth convention for a sampled crossing is that the crossing point
// joins its neighbours along both branches, so it has degree 4. Without it, the branches
// pass between samples and their ground-truth edges cross. A crossing already sampled on
// a branch keeps that sample.
Sample with_crossing_samples(const Local_feature_size& lfs, Sample sample);

// n points independently uniform in arc length over the whole curve (Seeded_random).
Sample random_sampling(const Local_feature_size& lfs, std::size_t n, std::uint64_t seed);

// The points at the given parameters of each component (parameters[c], increasing along
// component c; a closed component's taken modulo its piece count), with their ground truth:
// a sampling placed by hand, as the tightness search moves samples (certify/tightness_search.h).
// Throws std::invalid_argument if there are more lists than components.
Sample sampling_at(const Local_feature_size& lfs, const std::vector<std::vector<double>>& parameters, double minimum_lfs);

}  // namespace curvebench::geometry
