#include "geometry/lfs/medial_axis.h"

#include <optional>

#include <CGAL/Delaunay_triangulation_2.h>

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

std::vector<Point> voronoi_vertices(std::span<const Point> sample, std::span<const Point> exact_points) {
  // Duplicates merge silently, which is what a Voronoi diagram wants.
  const CGAL::Delaunay_triangulation_2<Kernel> delaunay(sample.begin(), sample.end());
  std::vector<Point> points(exact_points.begin(), exact_points.end());
  points.reserve(points.size() + delaunay.number_of_faces());
  for (const auto face : delaunay.finite_face_handles())
    if (const auto center = circumcenter(face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point()))
      points.push_back(*center);
  return points;
}

}  // namespace

Medial_axis::Medial_axis(std::span<const Point> curve_sample, std::span<const Point> exact_points)
    : Medial_axis(voronoi_vertices(curve_sample, exact_points)) {}

Medial_axis::Medial_axis(std::vector<Point> points) : points_(std::move(points)), index_(points_) {}

}  // namespace curvebench::geometry
