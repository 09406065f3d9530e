#include "bench/runner/evaluation.h"

#include <algorithm>

#include "bench/runner/point_matching.h"

namespace curvebench::bench {

Evaluation evaluate(const geometry::Polyline_view& reconstruction, bool on_input_points,
                    const geometry::Polyline_view* truth, const geometry::Polyline_view* original) {
  Evaluation result;
  result.topology = geometry::curve_topology(reconstruction.points.size(), reconstruction.edges);
  if (truth && on_input_points) result.exact = std::ranges::equal(reconstruction.edges, truth->edges);
  if (truth && !on_input_points) {
    const auto match = match_to_input(reconstruction.points, truth->points);
    std::vector<geometry::Edge> renamed;
    if (match)
      for (const auto& [i, j] : reconstruction.edges) renamed.emplace_back((*match)[i], (*match)[j]);
    result.exact = match && std::ranges::equal(geometry::canonical_edges(std::move(renamed)), truth->edges);
  }
  if (const geometry::Polyline_view* against = original ? original : truth) {
    const auto distance =
        geometry::curve_distance(*against, reconstruction, geometry::default_distance_spacing(*against));
    result.hausdorff = distance.hausdorff, result.rms = distance.rms;
    result.diagonal = geometry::bounding_box_diagonal(*against);
    result.normal_deviation = geometry::normal_deviation_degrees(*against, reconstruction);
  }
  return result;
}

}  // namespace curvebench::bench
