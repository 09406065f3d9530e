#include "geometry/sampling/sampling_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <CGAL/bounding_box.h>

#include "geometry/bounding_box_diagonal.h"
#include "geometry/sampling/seeded_random.h"

namespace curvebench::geometry {
namespace {

void check_level(const char* name, double level) {
  if (!(level >= 0 && std::isfinite(level)))
    throw std::invalid_argument(std::string(name) + ": the noise level must be non-negative and finite");
}

std::vector<Point> curve_points(const Sample& sample) {
  std::vector<Point> points;
  for (std::size_t i = 0; i < sample.size(); ++i)
    if (sample.labels[i] == Sample_label::curve_point) points.push_back(sample.points[i]);
  return points;
}

// Moves every curve point by displacement(i), in order: the random draws follow the points.
template <class Displacement>
void displace(Sample& sample, Displacement displacement) {
  for (std::size_t i = 0; i < sample.size(); ++i)
    if (sample.labels[i] == Sample_label::curve_point) sample.points[i] = sample.points[i] + displacement(i);
}

}  // namespace

Sample with_uniform_noise(Sample sample, double delta, std::uint64_t seed) {
  check_level("uniform noise", delta);
  const std::vector<Point> points = curve_points(sample);
  if (points.empty()) return sample;
  const double diagonal = bounding_box_diagonal(points);
  Seeded_random random(seed);
  displace(sample, [&](std::size_t) {
    const double sigma = random.uniform(0, delta * diagonal);
    return sigma * random.direction();
  });
  return sample;
}

Sample with_lfs_noise(const Local_feature_size& lfs, Sample sample, double delta, std::uint64_t seed) {
  check_level("lfs noise", delta);
  Seeded_random random(seed);
  displace(sample, [&](std::size_t i) {
    const Curve_location& at = sample.locations[i];
    const double scale = std::min(sample.lfs[i], lfs.bounding_box_diagonal());
    return random.uniform(-delta, delta) * scale * lfs.curve().components[at.component].unit_normal(at.parameter);
  });
  return sample;
}

Sample with_outliers(Sample sample, double percent, std::uint64_t seed) {
  check_level("outliers", percent);
  const std::size_t curve_count = curve_points(sample).size();
  const auto count = static_cast<std::size_t>(std::llround(percent / 100 * static_cast<double>(curve_count)));
  if (sample.points.empty() || count == 0) return sample;
  const auto box = CGAL::bounding_box(sample.points.begin(), sample.points.end());
  Seeded_random random(seed);
  for (std::size_t k = 0; k < count; ++k) {
    const double x = random.uniform(box.xmin(), box.xmax());
    sample.points.emplace_back(x, random.uniform(box.ymin(), box.ymax()));
    sample.lfs.push_back(std::numeric_limits<double>::quiet_NaN());
    sample.locations.emplace_back();
    sample.labels.push_back(Sample_label::outlier);
  }
  return sample;
}

}  // namespace curvebench::geometry
