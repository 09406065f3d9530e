#include "bench/runner/evaluation.h"

#include <algorithm>
#include <vector>

#include "bench/runner/point_matching.h"

namespace curvebench::bench {

Evaluation evaluate(const geometry::Polyline_view& reconstruction, bool on_input_points,
                    const geometry::Polyline_view* truth, const geometry::Polyline_view* original,
                    bool simplifies) {
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
    if (simplifies) {
      // An isolated vertex carries mass in Optimal Transport's output: it is a point of the
      // output (an edge from itself to itself), which an interpolator's unused input point is not.
      std::vector<bool> used(reconstruction.points.size(), false);
      for (const auto& [i, j] : reconstruction.edges) used[i] = used[j] = true;
      std::vector<geometry::Edge> elements(reconstruction.edges.begin(), reconstruction.edges.end());
      for (std::size_t i = 0; i < used.size(); ++i)
        if (!used[i]) elements.emplace_back(i, i);
      const geometry::Polyline_view output{reconstruction.points, elements};
      const double spacing = geometry::default_distance_spacing(*against);
      result.to_curve = geometry::one_way_curve_distance(output, *against, spacing);
      result.from_curve = geometry::one_way_curve_distance(*against, output, spacing);
    }
  }
  return result;
}

}  // namespace curvebench::bench
