// What `curvebench evaluate` reports of one reconstruction on the input points (JSON): the
// survey's criteria (evaluation.h) against a ground truth, distances measured to the
// ground truth or to the curve itself. The command line reads the points and edges from
// files, the Python module (curvebench.evaluate) takes arrays; both score through this call.
#pragma once

#include <span>
#include <string>

#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::bench {

// The report of `edges` on `points` against the ground truth `truth` (both between
// `points`; made canonical here): points, edges, truth_edges, distances_to, exact,
// hausdorff, rms, diagonal, normal_deviation ("inf" for an infinite value, null for none),
// manifold, max_degree, components, open_components, closed_components, unconnected.
// Distances are to the curve of the spec `curve` (geometry/curves/curve_spec.h) when it is
// not empty, else to the ground truth. Throws std::invalid_argument for an edge beyond the
// points, and passes on make_curve's errors.
std::string evaluation_report_json(std::span<const geometry::Point> points, std::span<const geometry::Edge> edges,
                                   std::span<const geometry::Edge> truth, const std::string& curve);

}  // namespace curvebench::bench
