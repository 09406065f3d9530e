#include "bench/runner/curve_sampling.h"

#include <stdexcept>

#include "geometry/sampling/sampling.h"
#include "geometry/sampling/sampling_noise.h"

namespace curvebench::bench {
namespace {

geometry::Sample drawn(const geometry::Local_feature_size& lfs, const Sampling_request& r) {
  if (r.epsilon.has_value() + r.rho.has_value() + r.uniform.has_value() + r.random.has_value() != 1)
    throw std::invalid_argument("sample: exactly one sampler: epsilon, rho, uniform or random");
  const double floor = r.minimum_lfs.value_or(geometry::default_minimum_lfs(lfs));
  if (r.epsilon) return (r.safe ? geometry::safe_epsilon_sampling : geometry::epsilon_sampling)(lfs, *r.epsilon, floor);
  if (r.rho) return (r.safe ? geometry::safe_rho_sampling : geometry::rho_sampling)(lfs, *r.rho, floor);
  if (r.uniform) return geometry::uniform_sampling(lfs, *r.uniform);
  return geometry::random_sampling(lfs, *r.random, r.seed);
}

}  // namespace

geometry::Sample sample_curve(const geometry::Local_feature_size& lfs, const Sampling_request& r) {
  geometry::Sample sample = drawn(lfs, r);
  if (r.crossing_samples) sample = geometry::with_crossing_samples(lfs, std::move(sample));
  // Independent streams for the noise and the outliers, all derived from the one seed.
  if (r.uniform_noise) sample = geometry::with_uniform_noise(std::move(sample), *r.uniform_noise, r.seed + 1);
  if (r.lfs_noise) sample = geometry::with_lfs_noise(lfs, std::move(sample), *r.lfs_noise, r.seed + 2);
  if (r.outliers) sample = geometry::with_outliers(std::move(sample), *r.outliers, r.seed + 3);
  return sample;
}

}  // namespace curvebench::bench
