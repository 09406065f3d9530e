#include "geometry/metrics/nearest_segment_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace curvebench::geometry {
namespace {

struct Closest {
  double squared_distance, x, y;
};

Closest closest_on_segment(double qx, double qy, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((qx - ax) * dx + (qy - ay) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double x = ax + t * dx, y = ay + t * dy;
  return {(qx - x) * (qx - x) + (qy - y) * (qy - y), x, y};
}

}  // namespace

Nearest_segment_index::Nearest_segment_index(std::span<const Point> points, std::span<const Edge> edges) {
  if (edges.empty()) return;
  segments_.reserve(edges.size());
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin, total_length = 0;
  for (const auto& [i, j] : edges) {
    const Point &a = points[i], &b = points[j];
    segments_.push_back({a.x(), a.y(), b.x(), b.y()});
    xmin = std::min({xmin, a.x(), b.x()}), xmax = std::max({xmax, a.x(), b.x()});
    ymin = std::min({ymin, a.y(), b.y()}), ymax = std::max({ymax, a.y(), b.y()});
    total_length += std::hypot(b.x() - a.x(), b.y() - a.y());
  }
  const double m = static_cast<double>(segments_.size()), width = xmax - xmin, height = ymax - ymin;
  if (!std::isfinite(width * width + height * height) || !std::isfinite(total_length))
    throw std::invalid_argument("segments too far apart for distances in double (their squared extent overflows)");
  // About one cell per segment, and cells no smaller than the mean segment, so that the
  // pieces listed stay O(number of segments) even when many segments are long. At most
  // 2m + 1 cells a side: the last column and row take whatever lies beyond.
  cell_size_ = std::max({std::sqrt(width * height / m), total_length / m, std::max(width, height) / m});
  if (!(cell_size_ > 0)) cell_size_ = 1;  // every segment is one point
  x0_ = xmin, y0_ = ymin;
  const double most = 2 * m + 1;
  columns_ = static_cast<std::int64_t>(std::min(std::floor(width / cell_size_) + 1, most));
  rows_ = static_cast<std::int64_t>(std::min(std::floor(height / cell_size_) + 1, most));

  // Two passes over the same pieces: count per cell, then fill (CSR). A segment is listed
  // once per cell: its consecutive pieces meet the same cells, so `last` remembers it.
  const std::size_t cells = static_cast<std::size_t>(columns_ * rows_);
  cell_begin_.assign(cells + 1, 0);
  std::vector<std::uint32_t> last(cells, std::numeric_limits<std::uint32_t>::max());
  const auto for_each_cell = [&](auto&& visit) {
    for (std::uint32_t s = 0; s < segments_.size(); ++s) {
      const Segment& g = segments_[s];
      const double length = std::hypot(g.bx - g.ax, g.by - g.ay);
      // A piece's box meets every cell the piece passes through, whatever its length; short
      // pieces keep a long diagonal segment out of the cells its box alone would meet.
      const auto pieces = static_cast<std::int64_t>(std::min(std::ceil(length / cell_size_), 2 * most)) + 1;
      for (std::int64_t k = 0; k < pieces; ++k) {
        const double t0 = static_cast<double>(k) / pieces, t1 = static_cast<double>(k + 1) / pieces;
        const double x_a = g.ax + t0 * (g.bx - g.ax), x_b = g.ax + t1 * (g.bx - g.ax);
        const double y_a = g.ay + t0 * (g.by - g.ay), y_b = g.ay + t1 * (g.by - g.ay);
        for (std::int64_t row = row_of(std::min(y_a, y_b)); row <= row_of(std::max(y_a, y_b)); ++row)
          for (std::int64_t column = column_of(std::min(x_a, x_b)); column <= column_of(std::max(x_a, x_b)); ++column)
            if (const std::size_t c = cell(column, row); last[c] != s) {
              last[c] = s;
              visit(c, s);
            }
      }
    }
  };
  for_each_cell([&](std::size_t c, std::uint32_t) { ++cell_begin_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) cell_begin_[c + 1] += cell_begin_[c];
  items_.resize(cell_begin_.back());
  std::vector<std::uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  std::fill(last.begin(), last.end(), std::numeric_limits<std::uint32_t>::max());
  for_each_cell([&](std::size_t c, std::uint32_t s) { items_[fill[c]++] = s; });
}

namespace {

// floor(offset / cell) clamped to [0, count - 1], also for offsets that overflow or are NaN
// (a query far outside the grid).
std::int64_t clamped_cell(double offset, double cell, std::int64_t count) {
  const double k = std::floor(offset / cell);
  if (!(k >= 0)) return 0;
  return k >= static_cast<double>(count - 1) ? count - 1 : static_cast<std::int64_t>(k);
}

}  // namespace

std::int64_t Nearest_segment_index::column_of(double x) const { return clamped_cell(x - x0_, cell_size_, columns_); }
std::int64_t Nearest_segment_index::row_of(double y) const { return clamped_cell(y - y0_, cell_size_, rows_); }

std::optional<Nearest_segment_index::Nearest> Nearest_segment_index::nearest(const Point& query) const {
  if (segments_.empty()) return std::nullopt;
  const double qx = query.x(), qy = query.y();
  Nearest best{0, std::numeric_limits<double>::infinity(), query};
  const auto visit = [&](std::int64_t column, std::int64_t row) {
    if (column < 0 || row < 0 || column >= columns_ || row >= rows_) return;
    const std::size_t c = cell(column, row);
    for (std::uint32_t k = cell_begin_[c]; k < cell_begin_[c + 1]; ++k) {
      const Segment& g = segments_[items_[k]];
      if (const Closest here = closest_on_segment(qx, qy, g.ax, g.ay, g.bx, g.by); here.squared_distance < best.squared_distance)
        best = {items_[k], here.squared_distance, Point(here.x, here.y)};
    }
  };
  const std::int64_t cx = column_of(qx), cy = row_of(qy);
  for (std::int64_t r = 0;; ++r) {
    if (r == 0) {
      visit(cx, cy);
    } else {
      for (std::int64_t column = cx - r; column <= cx + r; ++column) visit(column, cy - r), visit(column, cy + r);
      for (std::int64_t row = cy - r + 1; row < cy + r; ++row) visit(cx - r, row), visit(cx + r, row);
    }
    // A lower bound on the distance to any cell outside the block of rings 0..r: the
    // distance to the nearest side of the block that does not yet reach the grid's edge.
    double bound = std::numeric_limits<double>::infinity();
    if (cx - r > 0) bound = std::min(bound, std::max(0.0, qx - (x0_ + static_cast<double>(cx - r) * cell_size_)));
    if (cx + r < columns_ - 1) bound = std::min(bound, std::max(0.0, x0_ + static_cast<double>(cx + r + 1) * cell_size_ - qx));
    if (cy - r > 0) bound = std::min(bound, std::max(0.0, qy - (y0_ + static_cast<double>(cy - r) * cell_size_)));
    if (cy + r < rows_ - 1) bound = std::min(bound, std::max(0.0, y0_ + static_cast<double>(cy + r + 1) * cell_size_ - qy));
    if (bound == std::numeric_limits<double>::infinity() || best.squared_distance <= bound * bound) return best;
  }
}

}  // namespace curvebench::geometry
