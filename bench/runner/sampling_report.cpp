#include "bench/runner/sampling_report.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "bench/runner/results_table.h"
#include "certify/sampling_measure.h"
#include "geometry/lfs/curve_projection.h"

namespace curvebench::bench {
namespace {

// Edge files are canonical (i < j), but an edge stands for the interval from its first
// point forward along the curve to its second (measure_rho reads it so): turn each edge of
// a closed component whose points are neighbours the other way round along it, so that its
// interval holds no other sample. Without this, `measure` took a closing edge (first, last)
// as the whole loop but one gap and over-estimated rho (1.10 for a sampling of rho 0.98).
void orient_along_the_curve(const geometry::Local_feature_size& lfs, geometry::Sample& sample) {
  const auto& components = lfs.curve().components;
  std::vector<std::vector<std::pair<double, std::size_t>>> along(components.size());
  for (std::size_t i = 0; i < sample.size(); ++i) along[sample.locations[i].component].emplace_back(sample.locations[i].parameter, i);
  std::vector<std::size_t> position(sample.size());
  for (auto& points : along) {
    std::sort(points.begin(), points.end());
    for (std::size_t k = 0; k < points.size(); ++k) position[points[k].second] = k;
  }
  for (auto& [i, j] : sample.edges) {
    const std::size_t c = sample.locations[i].component;
    if (c != sample.locations[j].component || !components[c].closed()) continue;
    const std::size_t count = along[c].size();
    if ((position[i] + 1) % count != position[j] && (position[j] + 1) % count == position[i]) std::swap(i, j);
  }
}

nlohmann::json location(const geometry::Curve_location& where) {
  return {{"component", where.component}, {"parameter", where.parameter}};
}

}  // namespace

geometry::Sample located_sample(const geometry::Local_feature_size& lfs, std::vector<geometry::Point> points,
                                std::vector<geometry::Edge> edges) {
  geometry::Sample sample;
  sample.points = std::move(points);
  sample.edges = std::move(edges);
  for (const auto& [i, j] : sample.edges)
    if (i >= sample.size() || j >= sample.size())
      throw std::invalid_argument("edge " + std::to_string(i) + " " + std::to_string(j) + " names a point beyond the " +
                                  std::to_string(sample.size()) + " points");
  for (std::size_t i = 0; i < sample.size(); ++i) {
    const geometry::Point& p = sample.points[i];
    const auto where = geometry::nearest_curve_location(lfs, p);
    // None for a curve without components, or a point so far (beyond about 1e154) that
    // every squared distance overflows.
    if (where.component == geometry::Curve_location::no_component)
      throw std::invalid_argument("point " + std::to_string(i) + " (" + format_number(p.x()) + ", " +
                                  format_number(p.y()) + ") cannot be located on the curve");
    sample.locations.push_back(where);
    sample.lfs.push_back(lfs.at(where.component, where.parameter));
    sample.labels.push_back(geometry::Sample_label::curve_point);
  }
  orient_along_the_curve(lfs, sample);
  return sample;
}

std::string measure_report_json(const geometry::Local_feature_size& lfs, const geometry::Sample& sample,
                                const std::string& edges_name) {
  const certify::Sampling_measure m = certify::measure_sampling(lfs, sample);
  const nlohmann::json report = {
      {"curve", lfs.curve().name},
      {"points", sample.size()},
      {"edges", edges_name},
      {"minimum_lfs", sample.minimum_lfs},
      {"epsilon", m.epsilon.epsilon},
      {"epsilon_at", location(m.epsilon.where)},
      {"rho", m.rho.rho},
      {"rho_edge", {m.rho.edge.first, m.rho.edge.second}},
      {"uniformity", m.uniformity.uniformity},
      {"uniformity_at_point", m.uniformity.point},
  };
  return report.dump(2);
}

}  // namespace curvebench::bench
