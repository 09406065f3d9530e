// A ground truth given as points and edges (edge_io.h) as a Curve, so that the bundled
// and user-made ground truths can be sampled, measured and drawn like any other curve
// (survey, "Definitions and Notations": a curve is a set of closed or open components).
#pragma once

#include <string>

#include "geometry/curves/curve.h"
#include "geometry/io/edge_io.h"

namespace curvebench::geometry {

// Each chain of edges becomes a component of Line_segments: open chains run from their
// end of lower point index, cycles (closed components) from their lowest point index
// towards its lower-indexed neighbour. Points on no edge are ignored; edges between
// coincident points are dropped (path_builder.h). Throws std::invalid_argument for a point
// of degree > 2, an edge listed twice, an edge from a point to itself, or an index
// outside the points.
Curve polyline_curve(const GroundTruth& truth, std::string name = "polyline");

}  // namespace curvebench::geometry
