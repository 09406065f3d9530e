#include "geometry/metrics/curve_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <CGAL/bounding_box.h>

#include "geometry/metrics/nearest_segment_index.h"

namespace curvebench::geometry {
namespace {

// An edge far longer than the spacing (a reconstruction much larger than the original)
// is sampled coarser rather than without end.
constexpr double max_pieces_per_edge = 4096;

// A sum of w d^2 kept as scale^2 * sum with scale = the largest d so far, so that it
// overflows only where the mean itself would (the dnrm2 technique).
struct Weighted_squares {
  double scale = 0, sum = 0;

  void add(double d, double w) {
    if (d > scale) {
      sum = sum * (scale / d) * (scale / d) + w;
      scale = d;
    } else if (d > 0) {
      sum += w * (d / scale) * (d / scale);
    }
  }
  // sum expressed at another scale >= this one.
  double sum_at(double other_scale) const { return other_scale > 0 ? sum * (scale / other_scale) * (scale / other_scale) : 0; }
};

// Over the samples of `from` mapped onto `to`: the largest distance and the
// length-weighted sum of squared distances, with the total weight.
struct One_way {
  double largest = 0, weight = 0;
  Weighted_squares squares;
};

One_way map_onto(const Polyline_view& from, const Nearest_segment_index& to, double spacing) {
  One_way result;
  const auto distance = [&](const Point& p) { return std::sqrt(to.nearest(p)->squared_distance); };
  for (const auto& [i, j] : from.edges) {
    const Point &a = from.points[i], &b = from.points[j];
    result.largest = std::max({result.largest, distance(a), distance(b)});
    const double length = std::hypot(b.x() - a.x(), b.y() - a.y());  // no overflow on the way
    const double pieces = std::clamp(std::ceil(length / spacing), 1.0, max_pieces_per_edge);
    for (double k = 0; k < pieces; ++k) {
      const double t = (k + 0.5) / pieces;
      const double d = distance(Point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y())));
      result.largest = std::max(result.largest, d);
      result.squares.add(d, length / pieces);
    }
    result.weight += length;
  }
  return result;
}

// Throws unless every distance between the two curves' points squares to a finite double.
void require_finite_extent(const Polyline_view& a, const Polyline_view& b) {
  std::vector<Point> all(a.points.begin(), a.points.end());
  all.insert(all.end(), b.points.begin(), b.points.end());
  const auto box = CGAL::bounding_box(all.begin(), all.end());
  const double width = box.xmax() - box.xmin(), height = box.ymax() - box.ymin();
  if (!std::isfinite(width * width + height * height))
    throw std::invalid_argument("curves too far apart for distances in double (their squared extent overflows)");
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
  require_finite_extent(original, reconstruction);
  const Nearest_segment_index original_index(original.points, original.edges);
  const Nearest_segment_index reconstruction_index(reconstruction.points, reconstruction.edges);
  const One_way forward = map_onto(original, reconstruction_index, spacing);
  const One_way backward = map_onto(reconstruction, original_index, spacing);
  const double hausdorff = std::max(forward.largest, backward.largest);
  const double weight = forward.weight + backward.weight;
  // Zero total length: every edge is a point, and the sampled end points say all.
  if (!(weight > 0)) return {hausdorff, hausdorff};
  const double scale = std::max(forward.squares.scale, backward.squares.scale);
  const double sum = forward.squares.sum_at(scale) + backward.squares.sum_at(scale);
  return {hausdorff, std::min(hausdorff, scale * std::sqrt(sum / weight))};  // min: rounding
}

Curve_distance one_way_curve_distance(const Polyline_view& from, const Polyline_view& to, double spacing) {
  if (from.edges.empty()) return {};
  if (to.edges.empty()) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  require_finite_extent(from, to);
  const Nearest_segment_index index(to.points, to.edges);
  const One_way mapped = map_onto(from, index, spacing);
  if (mapped.weight > 0)
    return {mapped.largest, std::min(mapped.largest, mapped.squares.scale * std::sqrt(mapped.squares.sum / mapped.weight))};
  // Points only (a simplifier that kept isolated vertices alone): each weighs the same.
  Weighted_squares squares;
  for (const auto& [i, j] : from.edges) squares.add(std::sqrt(index.nearest(from.points[i])->squared_distance), 1);
  const double rms = squares.scale * std::sqrt(squares.sum / static_cast<double>(from.edges.size()));
  return {mapped.largest, std::min(mapped.largest, rms)};
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
