// What kind of curve an edge list is (survey, "Evaluation & Results", "Qualitative
// Comparison": manifold, open, multiple curves): vertex degrees and connected components.
// Pure combinatorics on indices, no geometry.
#pragma once

#include <cstddef>
#include <span>

#include "geometry/edge.h"

namespace curvebench::geometry {

// The combinatorial shape of an edge list, as curve_topology counts it.
struct Curve_topology {
  bool manifold = true;              // every point has degree <= 2
  std::size_t components = 0;        // connected components with at least one edge
  std::size_t open_components = 0;  // ... that are simple paths
  std::size_t closed_components = 0; // ... that are simple cycles
  std::size_t unconnected = 0;       // points in no edge
  std::size_t max_degree = 0;        // the largest degree of a point; 0 for no edge
};

// Edges index points 0 .. point_count - 1, given canonical (geometry::canonical_edges).
// A component with a vertex of degree 3 or more is neither open nor closed.
Curve_topology curve_topology(std::size_t point_count, std::span<const Edge> edges);

}  // namespace curvebench::geometry
