#include "bench/runner/point_matching.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <limits>

namespace curvebench::bench {
namespace {

using Kernel = geometry::Kernel;
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel>;
using Triangulation =
    CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vertex_base>>;

}  // namespace

std::optional<std::vector<std::size_t>> match_to_input(std::span<const geometry::Point> output,
                                                       std::span<const geometry::Point> input) {
  if (output.size() > input.size()) return std::nullopt;
  if (output.empty()) return std::vector<std::size_t>{};
  std::vector<std::pair<geometry::Point, std::size_t>> indexed;
  for (std::size_t i = 0; i < input.size(); ++i) indexed.emplace_back(input[i], i);
  const Triangulation triangulation(indexed.begin(), indexed.end());
  if (triangulation.number_of_vertices() < input.size()) return std::nullopt;  // duplicates: nothing is unambiguous

  // The nearest other input point is a Delaunay neighbour (or, in dimension < 2, an
  // adjacent vertex all the same).
  std::vector<double> nearest_other(input.size(), std::numeric_limits<double>::infinity());
  for (auto e = triangulation.finite_edges_begin(); e != triangulation.finite_edges_end(); ++e) {
    const auto a = e->first->vertex(Triangulation::cw(e->second)), b = e->first->vertex(Triangulation::ccw(e->second));
    const double d = CGAL::squared_distance(a->point(), b->point());
    nearest_other[a->info()] = std::min(nearest_other[a->info()], d);
    nearest_other[b->info()] = std::min(nearest_other[b->info()], d);
  }
  std::vector<std::size_t> match(output.size());
  std::vector<bool> taken(input.size(), false);
  for (std::size_t k = 0; k < output.size(); ++k) {
    const auto v = triangulation.nearest_vertex(output[k]);
    const std::size_t i = v->info();
    // |q - p| < |p - p'| / 2, squared: 4 |q - p|^2 < |p - p'|^2.
    if (taken[i] || !(4 * CGAL::squared_distance(output[k], v->point()) < nearest_other[i])) return std::nullopt;
    taken[i] = true;
    match[k] = i;
  }
  return match;
}

}  // namespace curvebench::bench
