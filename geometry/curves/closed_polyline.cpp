#include "geometry/curves/closed_polyline.h"

#include <algorithm>
#include <vector>

#include <CGAL/box_intersection_d.h>

namespace curvebench::geometry {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

Kernel::Segment_2 edge(std::span<const Point> points, std::size_t i) {
  return {points[i], points[(i + 1) % points.size()]};
}

std::vector<Box> edge_boxes(std::span<const Point> points) {
  std::vector<Box> boxes;
  for (std::size_t i = 0; i < points.size(); ++i) boxes.emplace_back(edge(points, i).bbox(), i);
  return boxes;
}

}  // namespace

bool closed_polyline_is_simple(std::span<const Point> points) {
  const std::size_t n = points.size();
  std::vector<Box> boxes = edge_boxes(points);
  bool simple = true;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    std::size_t i = std::min(a.info(), b.info()), j = std::max(a.info(), b.info());
    if (!simple) return;
    if (j == i + 1 || (i == 0 && j == n - 1)) {
      if (i == 0 && j == n - 1) std::swap(i, j);  // edge i ends where edge j starts
      const Point &p = points[i], &q = points[(i + 1) % n], &r = points[(j + 1) % n];
      simple = !(CGAL::collinear(p, q, r) && !CGAL::collinear_are_ordered_along_line(p, q, r));
    } else {
      simple = !CGAL::do_intersect(edge(points, i), edge(points, j));
    }
  });
  return simple;
}

bool closed_polylines_meet(std::span<const Point> a, std::span<const Point> b) {
  std::vector<Box> boxes_a = edge_boxes(a), boxes_b = edge_boxes(b);
  bool meet = false;
  CGAL::box_intersection_d(boxes_a.begin(), boxes_a.end(), boxes_b.begin(), boxes_b.end(),
                           [&](const Box& i, const Box& j) {
                             meet = meet || CGAL::do_intersect(edge(a, i.info()), edge(b, j.info()));
                           });
  return meet;
}

}  // namespace curvebench::geometry
