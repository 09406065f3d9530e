// Loading the command line's input point files, with the duplicate policy applied and
// reported where a person sees it.
#pragma once

#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "geometry/edge.h"
#include "geometry/point_set.h"

namespace curvebench::cli {

// Reads a point file in any supported format and merges exact duplicates into their
// first occurrence, printing one line per merged point to stderr
// ("FILE:LINE: duplicate of the point on line L, merged"). Throws geometry::ParseError.
geometry::PointSet load_point_set(const std::filesystem::path& path);

// Edges between kept points, renumbered to the input file's points (first occurrences),
// as sorted (i < j) pairs: what every command writes, so users can index their own file.
std::vector<geometry::Edge> to_input_indices(const geometry::PointSet& points, std::span<const geometry::Edge> edges);

// The picture of a graph on points, titled "WHAT of INPUT: n points, m edges".
void write_graph_picture(const std::filesystem::path& svg, std::span<const geometry::Point> points,
                         std::span<const geometry::Edge> edges, std::string_view what,
                         const std::filesystem::path& input);

}  // namespace curvebench::cli
