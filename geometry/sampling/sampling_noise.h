// Perturbations of a Sample, as in the survey's "Robustness to Noise" and "Outliers":
// they move the curve points (or add outlier points) and keep the ground truth, the lfs
// and the curve location of each point as they were. Seeded (Seeded_random): the same
// seed gives the same bits on every machine (given the same curve points).
#pragma once

#include <cstdint>

#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sample.h"

namespace curvebench::geometry {

// Uniform noise: each curve point s moves to s + sigma v, sigma uniform in
// [0, delta * diagonal] with `diagonal` that of the bounding box of the curve points, v a
// unit vector of uniformly random direction. Throws std::invalid_argument unless delta >= 0.
Sample with_uniform_noise(Sample sample, double delta, std::uint64_t seed);

// Noise in lfs: each curve point s moves along the curve's unit normal n at its location
// to s + sigma n, sigma uniform in [-delta, +delta] * lfs(s) (an infinite lfs counts as
// the curve's bounding-box diagonal). Throws std::invalid_argument unless delta >= 0.
Sample with_lfs_noise(const Local_feature_size& lfs, Sample sample, double delta, std::uint64_t seed);

// Outliers: round(percent / 100 * curve points) extra points, uniform in the bounding box
// of the sample's points, labelled Sample_label::outlier and in no edge. Throws
// std::invalid_argument unless percent >= 0.
Sample with_outliers(Sample sample, double percent, std::uint64_t seed);

}  // namespace curvebench::geometry
