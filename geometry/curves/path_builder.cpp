#include "geometry/curves/path_builder.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <CGAL/bounding_box.h>

#include "geometry/curves/cubic_bezier.h"

namespace curvebench::geometry {
namespace {

using Segment = std::vector<Point>;  // the ends of a line, or a cubic's four control points

bool is_cubic(const Segment& s) { return s.size() == 4; }
bool has_length(const Segment& s) { return std::any_of(s.begin() + 1, s.end(), [&](const Point& p) { return p != s[0]; }); }
double norm(const Vector& v) { return std::sqrt(v * v); }

// The control point that sets the segment's tangent at its start: the first one apart
// from the start (B'(0) is 3 (c1 - p0), or along c2 - p0 if c1 is on p0). At its end: the
// last one apart from the end.
std::size_t start_handle(const Segment& s) {
  std::size_t k = 1;
  while (k + 1 < s.size() && s[k] == s[0]) ++k;
  return k;
}
std::size_t end_handle(const Segment& s) {
  std::size_t k = s.size() - 2;
  while (k > 0 && s[k] == s.back()) --k;
  return k;
}
// Whether that control point may move: an inner control point of a cubic.
bool movable(const Segment& s, std::size_t k) { return is_cubic(s) && k != 0 && k != 3; }

// Makes every join of the subpath whose tangent turns by less than `corner_angle` (but
// does turn) exactly G1 (path_builder.h). The directions are all chosen on the segments as
// drawn, then the handles are moved, so that the order of the joins does not matter.
void smooth_near_smooth_joins(std::vector<Segment>& segments, bool closed, double corner_angle) {
  const std::size_t n = segments.size();
  if (!(corner_angle > 0) || n == 0) return;
  std::vector<std::optional<Vector>> start_direction(n), end_direction(n);
  for (std::size_t j = 0; j < (closed ? n : n - 1); ++j) {  // join j: the end of segment j
    const std::size_t next = (j + 1) % n;
    const Segment &in = segments[j], &out = segments[next];
    const std::size_t k_in = end_handle(in), k_out = start_handle(out);
    const Vector a = in.back() - in[k_in], b = out[k_out] - out[0];
    const double turn = std::atan2(std::abs(CGAL::determinant(a, b)), a * b);
    const bool move_in = movable(in, k_in), move_out = movable(out, k_out);
    if (!(turn > 0 && turn < corner_angle) || !(move_in || move_out)) continue;
    Vector u = move_in && move_out ? a / norm(a) + b / norm(b) : move_in ? b : a;
    u = u / norm(u);
    if (move_in) end_direction[j] = u;
    if (move_out) start_direction[next] = u;
  }
  for (std::size_t i = 0; i < n; ++i) {
    Segment& s = segments[i];
    if (!is_cubic(s)) continue;
    const std::size_t ks = start_handle(s), ke = end_handle(s);
    if (ks == ke && start_direction[i] && end_direction[i]) {
      // One control point sets both tangents: it goes where the two lines cross, p0 + t us
      // = p3 - t' ue, if that is near (a nearly flat cubic's lines cross far away).
      const Vector us = *start_direction[i], ue = *end_direction[i], chord = s[3] - s[0];
      const double det = CGAL::determinant(us, ue);
      if (det == 0) continue;
      const Point crossing = s[0] + CGAL::determinant(chord, ue) / det * us;
      const double budget = corner_angle * (norm(s[ks] - s[0]) + norm(s[3] - s[ks]));
      if (norm(crossing - s[ks]) <= budget) s[ks] = crossing;
      continue;
    }
    if (start_direction[i]) s[ks] = s[0] + norm(s[ks] - s[0]) * *start_direction[i];
    if (end_direction[i]) s[ke] = s[3] - norm(s[3] - s[ke]) * *end_direction[i];
  }
}

}  // namespace

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
  std::erase_if(segments_, [](const Segment& s) { return !has_length(s); });
  smooth_near_smooth_joins(segments_, closed, corner_angle_);
  std::vector<std::shared_ptr<const Curve_piece>> pieces;
  for (const auto& s : segments_) {
    if (is_cubic(s))
      append_cubic_bezier(pieces, {s[0], s[1], s[2], s[3]});
    else
      pieces.push_back(std::make_shared<Line_segment>(s[0], s[1]));
  }
  segments_.clear();
  if (!pieces.empty()) components_.emplace_back(std::move(pieces), closed);
}

}  // namespace curvebench::geometry
