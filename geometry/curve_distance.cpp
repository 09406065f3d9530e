#include "geometry/curve_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <CGAL/bounding_box.h>

#include "geometry/nearest_segment_index.h"

namespace curvebench::geometry {
namespace {

// An edge far longer than the spacing (a reconstruction much larger than the original)
// is sampled coarser rather than without end.
constexpr double max_pieces_per_edge = 4096;

// Over the samples of `from` mapped onto `to`: the largest distance and the
// length-weighted sum of squared distances, with the total weight.
struct One_way {
  double largest = 0, weighted_squares = 0, weight = 0;
};

One_way map_onto(const Polyline_view& from, const Nearest_segment_index& to, double spacing) {
  One_way result;
  const auto squared_distance = [&](const Point& p) { return to.nearest(p)->squared_distance; };
  for (const auto& [i, j] : from.edges) {
    const Point &a = from.points[i], &b = from.points[j];
    result.largest = std::max({result.largest, squared_distance(a), squared_distance(b)});
    const double length = std::hypot(b.x() - a.x(), b.y() - a.y());  // no overflow on the way
    const double pieces = std::clamp(std::ceil(length / spacing), 1.0, max_pieces_per_edge);
    for (double k = 0; k < pieces; ++k) {
      const double t = (k + 0.5) / pieces;
      const double d2 = squared_distance(Point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y())));
      result.largest = std::max(result.largest, d2);
      result.weighted_squares += d2 * (length / pieces);
    }
    result.weight += length;
  }
  result.largest = std::sqrt(result.largest);
  return result;
}

}  // namespace

double bounding_box_diagonal(const Polyline_view& polyline) {
  if (polyline.points.empty()) return 0;
  const auto box = CGAL::bounding_box(polyline.points.begin(), polyline.points.end());
  return std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
}

double default_distance_spacing(const Polyline_view& original) {
  const double diagonal = bounding_box_diagonal(original);
  return diagonal > 0 && std::isfinite(diagonal) ? 1e-3 * diagonal : 1;
}

Curve_distance curve_distance(const Polyline_view& original, const Polyline_view& reconstruction, double spacing) {
  if (original.edges.empty() && reconstruction.edges.empty()) return {};
  if (original.edges.empty() || reconstruction.edges.empty())
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  const Nearest_segment_index original_index(original.points, original.edges);
  const Nearest_segment_index reconstruction_index(reconstruction.points, reconstruction.edges);
  const One_way forward = map_onto(original, reconstruction_index, spacing);
  const One_way backward = map_onto(reconstruction, original_index, spacing);
  const double weight = forward.weight + backward.weight;
  // Zero total length: every edge is a point, and the sampled end points say all.
  const double rms = weight > 0 ? std::sqrt((forward.weighted_squares + backward.weighted_squares) / weight)
                                : std::max(forward.largest, backward.largest);
  return {std::max(forward.largest, backward.largest), rms};
}

double normal_deviation_degrees(const Polyline_view& original, const Polyline_view& reconstruction) {
  if (original.edges.empty()) return std::numeric_limits<double>::quiet_NaN();
  const Nearest_segment_index index(original.points, original.edges);
  double sum = 0;
  std::size_t count = 0;
  for (const auto& [i, j] : reconstruction.edges) {
    const Point &a = reconstruction.points[i], &b = reconstruction.points[j];
    if (a == b) continue;
    const auto nearest = index.nearest(CGAL::midpoint(a, b));
    const auto& [oi, oj] = original.edges[nearest->edge];
    const Point &c = original.points[oi], &d = original.points[oj];
    if (c == d) continue;
    // The angle between the two lines: of |cos| between their directions.
    const double dot = (b.x() - a.x()) * (d.x() - c.x()) + (b.y() - a.y()) * (d.y() - c.y());
    const double cross = (b.x() - a.x()) * (d.y() - c.y()) - (b.y() - a.y()) * (d.x() - c.x());
    sum += std::atan2(std::abs(cross), std::abs(dot)) * 180 / std::numbers::pi;
    ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : 0;
}

}  // namespace curvebench::geometry
