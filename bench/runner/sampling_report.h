// What `curvebench measure` reports of a point sampling of a known curve: its epsilon,
// rho and local uniformity (certify/sampling_measure.h), each with where it is attained.
// The command line reads the points and edges from files, the Python module
// (curvebench.measure) takes arrays; both measure through these two calls.
#pragma once

#include <string>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"
#include "geometry/lfs/local_feature_size.h"
#include "geometry/sampling/sample.h"

namespace curvebench::bench {

// `points` as a Sample of the curve of `lfs`: each point located at its nearest curve
// point, with lfs there, a curve point (no outliers); `edges` (may be empty) the ground
// truth, each turned to run forward along the curve where its points are neighbours on a
// closed component (measure_rho reads an edge as the interval from its first point forward
// to its second). Throws std::invalid_argument for an edge beyond the points, or a point
// that cannot be located (a curve without components, a point so far that its squared
// distances overflow).
geometry::Sample located_sample(const geometry::Local_feature_size& lfs, std::vector<geometry::Point> points,
                                std::vector<geometry::Edge> edges);

// The report, as `curvebench measure` prints it (JSON): curve, points, edges (`edges_name`,
// where they came from), minimum_lfs, epsilon and epsilon_at (component, parameter), rho
// and rho_edge, uniformity and uniformity_at_point; measured with sample.minimum_lfs as
// the lfs floor.
std::string measure_report_json(const geometry::Local_feature_size& lfs, const geometry::Sample& sample,
                                const std::string& edges_name);

}  // namespace curvebench::bench
