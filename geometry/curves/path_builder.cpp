#include "geometry/curves/path_builder.h"

#include <CGAL/bounding_box.h>

#include "geometry/curves/cubic_bezier.h"

namespace curvebench::geometry {

void Path_builder::move_to(const Point& p) {
  end_subpath(false);
  start_ = current_ = p;
}

void Path_builder::line_to(const Point& p) {
  segments_.push_back({current_, p});
  current_ = p;
}

void Path_builder::quadratic_to(const Point& control, const Point& p) {
  const auto cubic = elevate_quadratic_bezier(current_, control, p);
  cubic_to(cubic[1], cubic[2], p);
}

void Path_builder::cubic_to(const Point& control1, const Point& control2, const Point& p) {
  segments_.push_back({current_, control1, control2, p});
  current_ = p;
}

void Path_builder::close() {
  if (!segments_.empty()) {
    std::vector<Point> points;
    for (const auto& segment : segments_) points.insert(points.end(), segment.begin(), segment.end());
    const auto box = CGAL::bounding_box(points.begin(), points.end());
    const Vector gap = start_ - current_;
    if (gap * gap > CGAL::square(close_gap) * CGAL::squared_distance(box.min(), box.max())) {
      line_to(start_);
    } else {
      auto& last = segments_.back();
      if (last.size() == 4) last[2] = last[2] + gap;
      last.back() = start_;
    }
  }
  end_subpath(true);
  current_ = start_;
}

std::vector<Curve_component> Path_builder::finish() {
  end_subpath(false);
  return std::exchange(components_, {});
}

void Path_builder::end_subpath(bool closed) {
  std::vector<std::shared_ptr<const Curve_piece>> pieces;
  for (const auto& s : segments_) {
    if (s.size() == 4)
      append_cubic_bezier(pieces, {s[0], s[1], s[2], s[3]});
    else if (s[0] != s[1])
      pieces.push_back(std::make_shared<Line_segment>(s[0], s[1]));
  }
  segments_.clear();
  if (!pieces.empty()) components_.emplace_back(std::move(pieces), closed);
}

}  // namespace curvebench::geometry
