// What `curvebench sample` draws from a curve: one sampler (epsilon, rho, uniform or random
// points), optionally a sample at every crossing, then the perturbations (uniform noise,
// noise in lfs, outliers), each from its own stream of one seed. The command line and the
// Python module (curvebench.sample) both draw through sample_curve, so that the same
// request gives the same points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sample.h"

namespace curvebench::bench {

// One sampling of a curve and its perturbations, as `curvebench sample`'s options say it.
struct Sampling_request {
  // The sampler: exactly one of the next four is set.
  std::optional<double> epsilon = {};      // the survey's greedy walk at epsilon
  std::optional<double> rho = {};          // HNN-Crust's rho-sampling at rho
  std::optional<std::size_t> uniform = {};  // n points at equal arc-length steps
  std::optional<std::size_t> random = {};   // n points independently uniform in arc length (seed)
  bool safe = false;              // with epsilon or rho: the measured value stays below it
  bool crossing_samples = false;  // a sample on every crossing, shared by both branches
  std::optional<double> minimum_lfs = {};    // the lfs floor; default geometry::default_minimum_lfs
  std::optional<double> uniform_noise = {};  // noise of extent this x the bounding-box diagonal (seed + 1)
  std::optional<double> lfs_noise = {};      // noise along the normal, uniform in [-this, this] x lfs (seed + 2)
  std::optional<double> outliers = {};       // this percent of outliers in the bounding box (seed + 3)
  std::uint64_t seed = 0;                    // of every random choice
};

// The sample `request` asks for, on the curve of `lfs`. Throws std::invalid_argument unless
// exactly one sampler is set, and passes on the samplers' own errors (a bad epsilon, too
// few points, ...).
geometry::Sample sample_curve(const geometry::Local_feature_size& lfs, const Sampling_request& request);

}  // namespace curvebench::bench
