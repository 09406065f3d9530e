// Laws that several reconstruction algorithms obey on any input, as RapidCheck assertions to
// call inside a property: the algorithms whose output is a subgraph of the Delaunay
// triangulation (Crawl, DISCUR, VICUR) and whose decisions are exact predicates.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <rapidcheck.h>

#include "geometry/edge.h"
#include "geometry/kernel.h"
#include "graphs/delaunay_graph.h"
#include "graphs/graph.h"
#include "tests/support/edge_sets.h"

namespace curvebench::testing {

// reconstruct(points) is paths and cycles of Delaunay edges (every degree <= 2), and the same
// edges after scaling by a power of two: exact, so every decision is the same, unless a
// coordinate underflows into the subnormals.
template <class Reconstruct>
void rc_assert_delaunay_paths_and_cycles(const Reconstruct& reconstruct, const std::vector<geometry::Point>& points) {
  const std::vector<geometry::Edge> edges = reconstruct(points);
  const std::vector<geometry::Edge> delaunay = graphs::edge_list(graphs::delaunay_graph(points));
  RC_ASSERT(std::includes(delaunay.begin(), delaunay.end(), edges.begin(), edges.end()));
  for (const std::size_t d : degrees(edges, points.size())) RC_ASSERT(d <= 2u);
  const auto scaled = scaled_by(points, *rc::gen::element(-40, -3, 5, 60));
  const auto normal = [](double x) { return std::isnormal(x) || x == 0; };
  if (std::all_of(scaled.begin(), scaled.end(), [&](const geometry::Point& p) { return normal(p.x()) && normal(p.y()); }))
    RC_ASSERT(reconstruct(scaled) == edges);
}

}  // namespace curvebench::testing
