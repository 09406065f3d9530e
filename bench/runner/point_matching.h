// The tolerance of "exact reconstruction" for an algorithm that moves points (denoising,
// FitConnect, StretchDenoise): its output point q stands for the input point p nearest to
// q when q is unambiguously p's, i.e. closer to p than half the distance from p to any
// other input point (so no other input point can be as close to q). A reconstruction is
// exact when every output point stands for a different input point and the edges, so
// renamed, are the ground truth's.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "geometry/kernel.h"

namespace curvebench::bench {

// match[k] = the input point output point k stands for; std::nullopt unless every output
// point stands for one, each for a different one.
std::optional<std::vector<std::size_t>> match_to_input(std::span<const geometry::Point> output,
                                                       std::span<const geometry::Point> input);

}  // namespace curvebench::bench
