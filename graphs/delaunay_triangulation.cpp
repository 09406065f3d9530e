#include "graphs/delaunay_triangulation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {
namespace {

using Kernel = geometry::Kernel;
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<Vertex, Kernel>;
template <class Face_base>
using Cgal_delaunay_with = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vertex_base, Face_base>>;
// Faces that carry their number in triangles(), for the triangulations that keep them
// only: the number takes a face from 56 to 64 bytes, which cost the triangulation 2 %.
using Numbered_faces = CGAL::Triangulation_face_base_with_info_2<Triangle_id, Kernel>;
using Plain_faces = CGAL::Triangulation_face_base_2<Kernel>;

[[noreturn]] void throw_duplicate(std::span<const Point> points) {
  std::vector<Vertex> order(points.size());
  std::iota(order.begin(), order.end(), Vertex{0});
  std::sort(order.begin(), order.end(), [&](Vertex a, Vertex b) {
    return std::tie(points[a], a) < std::tie(points[b], b);
  });
  const auto equal = std::adjacent_find(order.begin(), order.end(),
                                        [&](Vertex a, Vertex b) { return points[a] == points[b]; });
  throw std::invalid_argument("Delaunay triangulation: points " + std::to_string(*equal) + " and " +
                              std::to_string(*std::next(equal)) +
                              " are equal; merge duplicates first (geometry::PointSet)");
}

}  // namespace

bool all_collinear(std::span<const Point> points) {
  if (points.empty()) return true;
  const auto second = std::find_if(points.begin(), points.end(), [&](const Point& p) { return p != points.front(); });
  if (second == points.end()) return true;
  return std::all_of(points.begin(), points.end(), [&](const Point& p) {
    return CGAL::orientation(points.front(), *second, p) == CGAL::COLLINEAR;
  });
}

Delaunay_triangulation::Delaunay_triangulation(std::span<const Point> points, Keep_triangles keep) : points_(points) {
  if (points.size() >= no_vertex) throw std::invalid_argument("Delaunay triangulation: too many points");
  for (const Point& p : points)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw std::invalid_argument("Delaunay triangulation: a coordinate is not finite");
  if (all_collinear(points)) {
    connect_collinear();  // a sort; CGAL's insertion is quadratic there
  } else if (keep == Keep_triangles::yes) {
    triangulate<Numbered_faces>();
  } else {
    triangulate<Plain_faces>();
  }
  index_neighbors();
}

template <class Face_base>
void Delaunay_triangulation::triangulate() {
  constexpr bool with_triangles = std::is_same_v<Face_base, Numbered_faces>;
  using Cgal_delaunay = Cgal_delaunay_with<Face_base>;
  std::vector<std::pair<Point, Vertex>> indexed;
  indexed.reserve(points_.size());
  for (Vertex i = 0; i < points_.size(); ++i) indexed.emplace_back(points_[i], i);

  // Sort the (point, index) pairs themselves along a Hilbert curve, then insert with the
  // previous vertex as the locate hint: what CGAL's range insert does, but moving the
  // pairs instead of sorting indices into them, which misses the cache at 10^6 points.
  CGAL::spatial_sort(indexed.begin(), indexed.end(),
                     CGAL::Spatial_sort_traits_adapter_2<Kernel, CGAL::First_of_pair_property_map<std::pair<Point, Vertex>>>());
  Cgal_delaunay dt;
  typename Cgal_delaunay::Face_handle hint;
  for (const auto& [point, index] : indexed) {
    const auto v = dt.insert(point, hint);
    v->info() = index;
    hint = v->face();
  }
  if (dt.number_of_vertices() != points_.size()) throw_duplicate(points_);

  edges_.reserve(3 * points_.size());
  if constexpr (with_triangles) {
    if (dt.number_of_faces() >= no_triangle) throw std::invalid_argument("Delaunay triangulation: too many triangles");
    triangles_.resize(dt.number_of_faces());
    Triangle_id next = 0;
    for (const auto face : dt.finite_face_handles()) face->info() = next++;
  }
  // Faces list their vertices counterclockwise, so an interior edge appears as (a, b) in
  // one face and (b, a) in the other: taking it from the face where a < b visits it once.
  // Walking faces is cheaper than CGAL's edge iterator, and indices (unlike face
  // addresses) make the choice the same on every run.
  for (const auto face : dt.finite_face_handles()) {
    const Vertex corner[3] = {face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()};
    if constexpr (with_triangles) triangles_[face->info()].corners = {corner[0], corner[1], corner[2]};
    for (int i = 0; i < 3; ++i) {
      const auto neighbor = face->neighbor(i);
      const bool on_hull = dt.is_infinite(neighbor);
      if constexpr (with_triangles) triangles_[face->info()].across[i] = on_hull ? no_triangle : neighbor->info();
      // source -> target runs clockwise in `face`, which therefore lies on its right.
      const Vertex source = corner[Cgal_delaunay::cw(i)], target = corner[Cgal_delaunay::ccw(i)];
      if (source > target && !on_hull) continue;  // the other face has it; skip the apex lookup
      const int back = on_hull ? 0 : neighbor->index(face);  // this side's number in `neighbor`
      Delaunay_edge e{source, target, on_hull ? no_vertex : neighbor->vertex(back)->info(), corner[i]};
      if (source > target) {
        std::swap(e.source, e.target);
        std::swap(e.left, e.right);
      }
      if constexpr (with_triangles) {  // the side's edge, in both triangles that have it
        const auto id = Edge_id(edges_.size());
        triangles_[face->info()].sides[i] = id;
        if (!on_hull) triangles_[neighbor->info()].sides[back] = id;
      }
      edges_.push_back(e);
    }
  }
}

void Delaunay_triangulation::connect_collinear() {
  // Lexicographic order is the order along the line, whatever its direction.
  std::vector<Vertex> order(points_.size());
  std::iota(order.begin(), order.end(), Vertex{0});
  std::sort(order.begin(), order.end(), [&](Vertex a, Vertex b) { return points_[a] < points_[b]; });
  if (std::adjacent_find(order.begin(), order.end(), [&](Vertex a, Vertex b) { return points_[a] == points_[b]; }) !=
      order.end())
    throw_duplicate(points_);
  for (std::size_t k = 1; k < order.size(); ++k)
    edges_.push_back({std::min(order[k - 1], order[k]), std::max(order[k - 1], order[k]), no_vertex, no_vertex});
}

void Delaunay_triangulation::index_neighbors() {
  first_neighbor_.assign(points_.size() + 1, 0);
  for (const auto& e : edges_) {
    ++first_neighbor_[e.source + 1];
    ++first_neighbor_[e.target + 1];
  }
  std::partial_sum(first_neighbor_.begin(), first_neighbor_.end(), first_neighbor_.begin());
  neighbors_.resize(first_neighbor_.back());
  std::vector<std::size_t> next(first_neighbor_.begin(), first_neighbor_.end() - 1);
  for (const auto& e : edges_) {
    neighbors_[next[e.source]++] = e.target;
    neighbors_[next[e.target]++] = e.source;
  }
}

Vertex Delaunay_triangulation::nearest_neighbor(Vertex v) const {
  Vertex nearest = no_vertex;
  for (const Vertex w : neighbors(v))
    if (nearest == no_vertex || closer(point(v), point(w), w, point(nearest), nearest)) nearest = w;
  return nearest;
}

}  // namespace curvebench::graphs
