// An outlier pre-filter for any algorithm (survey, "Outliers": erroneous points far from
// the curve "should not be considered in the reconstruction, and must thus be classified
// and excluded beforehand"). Density-based and scale-free: with r(p) the distance from p
// to its k-th nearest neighbour, p is an outlier iff r(p) > factor * R, R the median of r
// over all points (lower median). While outliers are fewer than the samples, R is a
// curve's spacing, and an outlier's r is about its distance to the curve or to the next
// outlier.
//
// Why global: the survey's outliers are uniform in the bounding box, so most lie inside
// the shape, far from every sample, with other outliers as all their nearest neighbours.
// Any reference taken from a point's own neighbourhood then sees a sparse cloud of equal
// density and keeps it (we tried the median r of the 4k nearest neighbours: 19 of 40
// outliers of a circle survived). The price: a sampling that is sparser than factor * R
// somewhere loses those samples, so strongly non-uniform samplings need a larger factor.
//
// Every comparison is exact: r values are ordered by compare_lengths, and
// r(p)^2 > factor^2 R^2 is the sign of a polynomial in the input coordinates and the
// factor (geometry/exact_sign.h). Outliers nearer a curve than factor * R are noise to it.
//
// In the registry, "NAME+outlier-filter" is algorithm NAME run on the points the filter
// keeps, with the filter's two parameters added (registry.h).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The filter's two parameters (outlier_neighbors and outlier_factor in the registry).
struct Outlier_filter_options {
  std::size_t neighbors = 4;  // k
  double factor = 3;          // p is an outlier iff r(p) > factor * R
};

// Indices of the points kept, increasing. Points must be distinct and finite (throws
// std::invalid_argument otherwise); with at most k points nothing is dropped.
std::vector<std::size_t> inlier_indices(std::span<const Point> points, const Outlier_filter_options& options = {});

// `algorithm` behind the filter: named NAME+outlier-filter, its parameters plus
// "outlier_neighbors" and "outlier_factor"; the result's points are the points kept (or
// the algorithm's own output points) and the edges index them.
Algorithm with_outlier_filter(const Algorithm& algorithm);

}  // namespace curvebench::algorithms
