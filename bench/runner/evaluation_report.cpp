#include "bench/runner/evaluation_report.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/runner/bench_input.h"
#include "bench/runner/evaluation.h"
#include "geometry/curves/curve_spec.h"

namespace curvebench::bench {
namespace {

std::vector<geometry::Edge> checked(std::span<const geometry::Edge> edges, std::size_t points) {
  std::vector<geometry::Edge> canonical = geometry::canonical_edges({edges.begin(), edges.end()});
  for (const auto& [i, j] : canonical)
    if (j >= points)
      throw std::invalid_argument("edge " + std::to_string(i) + " " + std::to_string(j) + " names a point beyond the " +
                                  std::to_string(points) + " points");
  return canonical;
}

nlohmann::json optional(const std::optional<double>& value) {
  return value ? (std::isfinite(*value) ? nlohmann::json(*value) : nlohmann::json("inf")) : nlohmann::json();
}

}  // namespace

std::string evaluation_report_json(std::span<const geometry::Point> points, std::span<const geometry::Edge> edges,
                                   std::span<const geometry::Edge> truth, const std::string& curve) {
  const std::vector<geometry::Edge> found = checked(edges, points.size()), expected = checked(truth, points.size());
  std::optional<Polyline> original;
  if (!curve.empty()) original = dense_polyline(geometry::Local_feature_size(geometry::make_curve(curve)));
  const geometry::Polyline_view truth_view{points, expected};
  const std::optional<geometry::Polyline_view> curve_view = original ? std::optional(original->view()) : std::nullopt;
  const Evaluation e = evaluate({points, found}, true, &truth_view, curve_view ? &*curve_view : nullptr);
  const nlohmann::json report = {
      {"points", points.size()},
      {"edges", found.size()},
      {"truth_edges", expected.size()},
      {"distances_to", original ? "curve " + curve : std::string("ground truth")},
      {"exact", *e.exact},
      {"hausdorff", optional(e.hausdorff)},
      {"rms", optional(e.rms)},
      {"diagonal", optional(e.diagonal)},
      {"normal_deviation", optional(e.normal_deviation)},
      {"manifold", e.topology.manifold},
      {"max_degree", e.topology.max_degree},
      {"components", e.topology.components},
      {"open_components", e.topology.open_components},
      {"closed_components", e.topology.closed_components},
      {"unconnected", e.topology.unconnected},
  };
  return report.dump(2);
}

}  // namespace curvebench::bench
