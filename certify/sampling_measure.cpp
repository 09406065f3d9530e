#include "certify/sampling_measure.h"

#include <cmath>
#include <limits>
#include <vector>

#include "geometry/lfs/curve_search.h"
#include "geometry/lfs/nearest_point_index.h"

namespace curvebench::certify {
namespace {

using geometry::Sample_label;

constexpr double infinity = std::numeric_limits<double>::infinity();

double distance(const Point& p, const Point& q) { return std::sqrt(CGAL::squared_distance(p, q)); }

// Where an edge's interval ends: j's parameter, moved one turn on if the interval wraps.
double interval_end(const geometry::Curve_component& component, double begin, double end) {
  return component.closed() && end <= begin ? end + static_cast<double>(component.piece_count()) : end;
}

}  // namespace

Epsilon_measure measure_epsilon(const geometry::Local_feature_size& lfs, std::span<const Point> points,
                                double minimum_lfs) {
  const geometry::Nearest_point_index nearest(points);
  Epsilon_measure worst;
  const auto& components = lfs.curve().components;
  for (std::size_t c = 0; c < components.size(); ++c) {
    const auto& component = components[c];
    const geometry::Curve_maximum found =
        geometry::maximize_along(lfs, c, 0, static_cast<double>(component.piece_count()), [&](double s) {
          return geometry::relative_distance(nearest.distance(component.point(s)), lfs.at(c, s), minimum_lfs);
        });
    if (c == 0 || found.value > worst.epsilon) worst = {found.value, {c, found.parameter}};
  }
  return worst;
}

Rho_measure measure_rho(const geometry::Local_feature_size& lfs, const geometry::Sample& sample, double minimum_lfs) {
  Rho_measure worst;
  bool any = false;
  for (const Edge& edge : sample.edges) {
    const auto &from = sample.locations[edge.first], &to = sample.locations[edge.second];
    if (sample.labels[edge.first] != Sample_label::curve_point || sample.labels[edge.second] != Sample_label::curve_point ||
        from.component != to.component)
      continue;
    const auto& component = lfs.curve().components[from.component];
    double begin = from.parameter, end = to.parameter;
    if (!component.closed() && end < begin) std::swap(begin, end);
    const geometry::Curve_maximum lowest = geometry::maximize_along(
        lfs, from.component, begin, interval_end(component, begin, end),
        [&](double s) { return -std::max(lfs.at(from.component, s), minimum_lfs); });
    const double reach = -lowest.value;
    const double rho = geometry::relative_distance(distance(sample.points[edge.first], sample.points[edge.second]) / 2, reach, 0);
    if (!any || rho > worst.rho)
      worst = {rho, edge, reach, {from.component, component.closed() ? std::fmod(lowest.parameter, static_cast<double>(component.piece_count()))
                                                                     : lowest.parameter}};
    any = true;
  }
  return worst;
}

Uniformity_measure measure_uniformity(std::span<const Point> points, std::span<const Edge> edges) {
  std::vector<std::vector<double>> incident(points.size());
  for (const Edge& edge : edges) {
    const double length = distance(points[edge.first], points[edge.second]);
    incident[edge.first].push_back(length);
    incident[edge.second].push_back(length);
  }
  Uniformity_measure worst;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (incident[i].size() != 2) continue;
    const double shorter = std::min(incident[i][0], incident[i][1]), longer = std::max(incident[i][0], incident[i][1]);
    const double ratio = shorter > 0 ? longer / shorter : infinity;
    if (ratio > worst.uniformity) worst = {ratio, i};
  }
  return worst;
}

Sampling_measure measure_sampling(const geometry::Local_feature_size& lfs, const geometry::Sample& sample) {
  return {measure_epsilon(lfs, sample.points, sample.minimum_lfs), measure_rho(lfs, sample, sample.minimum_lfs),
          measure_uniformity(sample.points, sample.edges)};
}

}  // namespace curvebench::certify
