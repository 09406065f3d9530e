#include "algorithms/outlier_filter.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/k_nearest_neighbor_graph.h"
#include "graphs/proximity_predicates.h"

namespace curvebench::algorithms {

std::vector<std::size_t> inlier_indices(std::span<const Point> points, const Outlier_filter_options& options) {
  if (!(options.factor >= 1) || options.neighbors == 0 || options.neighbors > 1024)
    throw std::invalid_argument("outlier filter: need 1 <= neighbors <= 1024 and factor >= 1");
  const std::size_t n = points.size(), k = options.neighbors;
  std::vector<std::size_t> kept(n);
  for (std::size_t i = 0; i < n; ++i) kept[i] = i;
  if (n <= k) return kept;

  const graphs::Delaunay_triangulation dt(points);  // checks distinct and finite
  const auto nearest = graphs::k_nearest_neighbors(dt, k);
  // r(p) as the segment from p to its k-th nearest neighbour.
  const auto far_end = [&](graphs::Vertex p) -> const Point& { return dt.point(nearest[p].back()); };
  std::vector<graphs::Vertex> by_r(n);
  for (graphs::Vertex p = 0; p < n; ++p) by_r[p] = p;
  const auto median = by_r.begin() + static_cast<std::ptrdiff_t>((n - 1) / 2);
  std::nth_element(by_r.begin(), median, by_r.end(), [&](graphs::Vertex a, graphs::Vertex b) {
    const CGAL::Sign sign = graphs::compare_lengths(dt.point(a), far_end(a), dt.point(b), far_end(b));
    return sign == CGAL::POSITIVE || (sign == CGAL::ZERO && a < b);  // POSITIVE: r(a) < r(b)
  });
  const Point &c = dt.point(*median), &d = far_end(*median);

  kept.clear();
  for (graphs::Vertex p = 0; p < n; ++p) {
    const Point &a = dt.point(p), &b = far_end(p);
    const CGAL::Sign excess = geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
      const NT f = NT(options.factor);  // a double, so an exact input like the coordinates
      return geometry::squared_length(geometry::difference<NT>(b, a)) -
             f * f * geometry::squared_length(geometry::difference<NT>(d, c));
    });
    if (excess != CGAL::POSITIVE) kept.push_back(p);
  }
  return kept;
}

Algorithm with_outlier_filter(const Algorithm& algorithm) {
  static const Parameter neighbors{.name = "outlier_neighbors", .type = Parameter_type::integer,
                                   .default_value = static_cast<double>(Outlier_filter_options{}.neighbors),
                                   .minimum = 1, .maximum = 256,
                                   .meaning = "outlier filter: k, the neighbour whose distance measures density"};
  static const Parameter factor{.name = "outlier_factor", .default_value = Outlier_filter_options{}.factor,
                                .minimum = 1, .maximum = 1e6,
                                .meaning = "outlier filter: drop p if its k-th neighbour distance exceeds this "
                                           "times the median one over all points"};
  Algorithm filtered = algorithm;
  filtered.parameters.push_back(neighbors);
  filtered.parameters.push_back(factor);
  filtered.capabilities.outliers = Support::yes;
  filtered.condition = {.statement = "none"};  // a dropped sample can break the base's guarantee
  filtered.reconstruct = [base = algorithm.reconstruct](std::span<const Point> points, const Parameter_values& values) {
    const auto kept_indices = inlier_indices(
        points, {.neighbors = static_cast<std::size_t>(values[neighbors]), .factor = values[factor]});
    std::vector<Point> kept;
    kept.reserve(kept_indices.size());
    for (const std::size_t i : kept_indices) kept.push_back(points[i]);
    Reconstruction result = base(kept, values);
    if (result.points.empty()) result.points = std::move(kept);
    return result;
  };
  return filtered;
}

}  // namespace curvebench::algorithms
