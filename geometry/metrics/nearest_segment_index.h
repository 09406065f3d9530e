// The closest point of a set of segments (a polyline, a ground truth, a reconstruction) to
// a query point: the closest-point mapping M : C -> C' of the survey's "Evaluation
// Criteria". Metric values only (output), so evaluated in double.
//
// A uniform grid over the segments' bounding box, about one cell per segment; a segment is
// listed in every cell it passes through (split into cell-sized pieces, each listed in the
// cells its box meets). A query visits rings of cells around its own until the ring's
// distance exceeds the best found, so the answer is the exact minimum over all segments
// (up to rounding), whatever the grid.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/edge.h"
#include "geometry/kernel.h"

namespace curvebench::geometry {

// The closest point on a fixed set of segments (see above). Holds its own copy of the
// segments; queries only read it.
class Nearest_segment_index {
 public:
  // Edges index `points`; an edge whose ends coincide counts as a point. Throws
  // std::invalid_argument if the segments' squared extent or total length overflows a
  // double. A query farther than that gets an infinite squared distance.
  Nearest_segment_index(std::span<const Point> points, std::span<const Edge> edges);

  // The answer to a query: which segment, and the point of it closest to the query.
  struct Nearest {
    std::size_t edge;         // index into the edges given
    double squared_distance;  // from the query to `closest`
    Point closest;            // on segment `edge`, nearest to the query (rounded)
  };
  // The closest point over all segments; std::nullopt if there is no edge.
  std::optional<Nearest> nearest(const Point& query) const;

 private:
  struct Segment {
    double ax, ay, bx, by;
  };
  std::size_t cell(std::int64_t column, std::int64_t row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
  }
  std::int64_t column_of(double x) const;
  std::int64_t row_of(double y) const;

  std::vector<Segment> segments_;
  double x0_ = 0, y0_ = 0, cell_size_ = 1;
  std::int64_t columns_ = 0, rows_ = 0;
  std::vector<std::uint32_t> cell_begin_;  // CSR: segments of cell c are items_[begin[c], begin[c+1])
  std::vector<std::uint32_t> items_;
};

}  // namespace curvebench::geometry
