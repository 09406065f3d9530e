// The one graph type every proximity-graph builder and reconstruction returns.
//
// Vertex i is point i of the input; each edge carries its squared length as
// `edge_weight_t` (a double, for reporting and drawing: decisions never read it).
// The edge list is a vector (the last template argument) because builders only ever
// add edges, and a vector costs a third of the default std::list at 10^6 points.
#pragma once

#include <span>
#include <vector>

#include <boost/graph/adjacency_list.hpp>

#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::graphs {

using geometry::Edge;
using geometry::Point;

// An undirected Boost adjacency list: vertex i is point i, and each edge's edge_weight_t
// its squared length rounded to double.
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                    boost::property<boost::edge_weight_t, double>, boost::no_property,
                                    boost::vecS>;

// A graph on `points` with the given edges, each stored once as (min, max) in sorted order,
// so that equal edge sets give identical graphs.
Graph make_graph(std::span<const Point> points, const std::vector<Edge>& edges);

// The edges of `graph` as sorted (i < j) pairs.
std::vector<Edge> edge_list(const Graph& graph);

}  // namespace curvebench::graphs
