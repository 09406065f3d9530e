// Inputs with a known right answer for reconstruction algorithms: random smooth closed
// curves (one to three components, random Fourier series side by side), safe-epsilon-
// sampled (geometry/sampling/sampling.h) at a requested epsilon below an algorithm's proven bound,
// with the sampling's measured epsilon (certify/sampling_measure.h) checked to be below it
// too. The ground truth is the sampler's chain, canonical (i < j, sorted).
#pragma once

#include <gtest/gtest.h>

#include <rapidcheck.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "certify/sampling_measure.h"
#include "geometry/curves/analytic_curves.h"
#include "geometry/sampling/sampling.h"
#include "tests/support/edge_sets.h"

namespace curvebench::testing {

// A curve piece moved by a vector.
class Translated_piece : public geometry::Curve_piece {
 public:
  Translated_piece(const geometry::Curve_piece& piece, geometry::Vector offset) : piece_(piece), offset_(offset) {}
  geometry::Point point(double t) const override { return piece_.point(t) + offset_; }
  geometry::Vector derivative(double t) const override { return piece_.derivative(t); }
  geometry::Vector second_derivative(double t) const override { return piece_.second_derivative(t); }

 private:
  const geometry::Curve_piece& piece_;  // kept alive by Sampled_case::source
  geometry::Vector offset_;
};

struct Sampled_case {
  std::shared_ptr<const geometry::Curve> source;  // owns the pieces the translated ones read
  geometry::Curve curve;
  geometry::Sample sample;
  std::vector<geometry::Edge> truth;  // canonical
  double requested_epsilon = 0, measured_epsilon = 0;

  friend std::ostream& operator<<(std::ostream& out, const Sampled_case& c) {
    return out << c.curve.name << " sampled at epsilon " << c.requested_epsilon << " (measured "
               << c.measured_epsilon << "), " << c.sample.size() << " points";
  }
};

// `components` random Fourier curves (seeds seed, seed + 1, ...) in a row, 1.5 apart
// beyond their bounding boxes so that the gap is wide against every curve's features.
inline Sampled_case sampled_fourier_curves(std::uint64_t seed, int components, int harmonics, double epsilon) {
  Sampled_case result;
  std::vector<geometry::Curve> parts;
  for (int c = 0; c < components; ++c)
    parts.push_back(geometry::random_fourier_curve(seed + c, {.harmonics = harmonics, .amplitude = 0.3}));
  auto source = std::make_shared<geometry::Curve>();
  double x = 0;
  std::ostringstream name;
  for (geometry::Curve& part : parts) {
    const geometry::Kernel::Iso_rectangle_2 box = part.bounding_box(1e-6);
    const geometry::Vector offset(x - box.xmin(), 0);
    x += box.xmax() - box.xmin() + 1.5;
    name << (name.tellp() > 0 ? " + " : "") << part.name;
    for (const geometry::Curve_component& component : part.components) source->components.push_back(component);
    std::vector<std::shared_ptr<const geometry::Curve_piece>> moved;
    for (std::size_t i = 0; i < part.components.front().piece_count(); ++i)
      moved.push_back(std::make_shared<Translated_piece>(source->components.back().piece(i), offset));
    result.curve.components.emplace_back(std::move(moved), true);
  }
  result.curve.name = name.str();
  result.source = std::move(source);
  const geometry::Local_feature_size lfs(result.curve);
  const double minimum_lfs = geometry::default_minimum_lfs(lfs);
  result.sample = geometry::safe_epsilon_sampling(lfs, epsilon, minimum_lfs);
  result.truth = canonical(result.sample.edges);
  result.requested_epsilon = epsilon;
  result.measured_epsilon = certify::measure_epsilon(lfs, result.sample.points, minimum_lfs).epsilon;
  return result;
}

// Random cases whose measured epsilon is below `bound`: one to `max_components` components of 2 to 8
// harmonics, requested epsilon in [bound / 4, 0.99 bound].
inline rc::Gen<Sampled_case> safely_sampled_smooth_curves(double bound, int max_components = 3) {
  return rc::gen::exec([bound, max_components] {
    const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
    const int components = *rc::gen::inRange(1, max_components + 1);
    const int harmonics = *rc::gen::inRange(2, 9);
    const double epsilon = bound * (0.25 + 0.74 * *rc::gen::inRange(0, 1001) / 1000.0);
    Sampled_case result = sampled_fourier_curves(seed, components, harmonics, epsilon);
    RC_ASSERT(result.measured_epsilon < bound);
    return result;
  });
}

}  // namespace curvebench::testing
