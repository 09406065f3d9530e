#include "geometry/lfs/medial_axis.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace curvebench::geometry {
namespace {

// The circumcenter of a Delaunay triangle, unless it is too flat for double arithmetic:
// then its center is as good as at infinity, on no medial axis that lfs would see.
std::optional<Point> circumcenter(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x() - a.x(), by = b.y() - a.y(), cx = c.x() - a.x(), cy = c.y() - a.y();
  const double denominator = 2 * (bx * cy - by * cx);
  if (denominator == 0) return std::nullopt;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return Point(a.x() + (cy * b2 - by * c2) / denominator, a.y() + (bx * c2 - cx * b2) / denominator);
}

// Points per chord length along a Voronoi edge between non-neighbours (the error of a
// subdivided segment is about (step / 2)^2 / (2 lfs): 5e-4 of lfs at a gap's ends), and a
// cap per edge.
constexpr double edge_points_per_chord = 32;
constexpr double max_edge_points = 512;

using Delaunay = CGAL::Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel>>>;

std::vector<Point> medial_points(std::span<const Point> sample, std::span<const Sample_chain> chains,
                                 std::span<const Point> exact_points) {
  // Each point's chain position, to tell neighbours along a component.
  struct Position {
    std::size_t chain, index;
  };
  std::vector<Position> position;
  position.reserve(sample.size());
  for (std::size_t c = 0; c < chains.size(); ++c)
    for (std::size_t i = 0; i < chains[c].size; ++i) position.push_back({c, i});
  if (position.size() != sample.size()) throw std::invalid_argument("medial axis: the chains do not add up to the sample");
  const auto neighbours = [&](std::size_t a, std::size_t b) {
    const Position p = position[a], q = position[b];
    if (p.chain != q.chain) return false;
    const std::size_t d = p.index > q.index ? p.index - q.index : q.index - p.index;
    return d == 1 || (chains[p.chain].closed && d + 1 == chains[p.chain].size);
  };

  std::vector<std::pair<Point, std::size_t>> indexed;
  indexed.reserve(sample.size());
  for (std::size_t i = 0; i < sample.size(); ++i) indexed.emplace_back(sample[i], i);
  // Duplicates merge silently (the first one's index stays), which is what a Voronoi
  // diagram wants.
  const Delaunay delaunay(indexed.begin(), indexed.end());
  std::vector<Point> points(exact_points.begin(), exact_points.end());
  points.reserve(points.size() + delaunay.number_of_faces());
  for (const auto face : delaunay.finite_face_handles())
    if (const auto center = circumcenter(face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point()))
      points.push_back(*center);
  if (delaunay.dimension() < 2) return points;

  // The Voronoi edges dual to Delaunay edges between non-neighbours that run nearer to
  // both generators than every vertex does (its points are equidistant from the two):
  // only those can lower lfs much, and they are few (a gap between an open curve's ends;
  // elsewhere vertices are dense along the medial axis), while subdividing every such edge
  // made the estimate 2.4x slower.
  const Nearest_point_index vertices(points);
  std::vector<Point> along;
  for (const auto& [face, i] : delaunay.finite_edges()) {
    const auto a = face->vertex(Delaunay::cw(i)), b = face->vertex(Delaunay::ccw(i));
    if (neighbours(a->info(), b->info())) continue;
    const Point& p = a->point();
    const Point& q = b->point();
    const double chord = std::sqrt(CGAL::squared_distance(p, q)), step = chord / edge_points_per_chord;
    // The Voronoi edge dual to pq: between its faces' circumcenters, or from the finite
    // face's circumcenter away from that face for a hull edge (clipped a chord past pq).
    const auto twin = face->neighbor(i);
    const bool ray = delaunay.is_infinite(face) || delaunay.is_infinite(twin);
    const auto finite = delaunay.is_infinite(face) ? twin : face;
    const auto start = circumcenter(finite->vertex(0)->point(), finite->vertex(1)->point(), finite->vertex(2)->point());
    if (!start || !(step > 0)) continue;
    Point end;
    if (ray) {
      const Point& inner = finite->vertex(finite == face ? i : twin->index(face))->point();
      const Point middle = CGAL::midpoint(p, q);
      // The unit normal of pq on the side away from the finite face's third vertex.
      const double sense = CGAL::orientation(p, q, inner) == CGAL::LEFT_TURN ? -1 : 1;
      const Kernel::Vector_2 normal = Kernel::Vector_2(p.y() - q.y(), q.x() - p.x()) * (sense / chord);
      end = *start + std::max(0.0, normal * (middle - *start) + chord) * normal;
    } else {
      const auto other = circumcenter(twin->vertex(0)->point(), twin->vertex(1)->point(), twin->vertex(2)->point());
      if (!other) continue;
      end = *other;
    }
    const Kernel::Segment_2 edge(*start, end);
    const double nearest = std::sqrt(std::min(CGAL::squared_distance(p, edge), CGAL::squared_distance(q, edge)));
    if (!(nearest < (1 - 1e-4) * std::min(vertices.distance(p), vertices.distance(q)))) continue;
    const double length = std::sqrt(edge.squared_length());
    const auto pieces = static_cast<std::size_t>(std::min(std::ceil(length / step), max_edge_points));
    for (std::size_t k = 1; k < pieces; ++k) along.push_back(*start + (end - *start) * (double(k) / double(pieces)));
    if (ray) along.push_back(end);  // a finite edge ends at a circumcenter, already a vertex
  }
  points.insert(points.end(), along.begin(), along.end());
  return points;
}

}  // namespace

Medial_axis::Medial_axis(std::span<const Point> curve_sample, std::span<const Sample_chain> chains,
                         std::span<const Point> exact_points)
    : Medial_axis(medial_points(curve_sample, chains, exact_points)) {}

Medial_axis::Medial_axis(std::vector<Point> points) : points_(std::move(points)), index_(points_) {}

}  // namespace curvebench::geometry
