#include "geometry/curves/curve_crossings.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <CGAL/box_intersection_d.h>

namespace curvebench::geometry {
namespace {

struct Chord {
  std::size_t component, index;  // index-th chord of the component
  double s0, s1;
  Point p0, p1;
};

std::vector<Chord> chords(const Curve& curve, std::span<const std::vector<double>> chord_parameters) {
  std::vector<Chord> all;
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const Curve_component& component = curve.components[c];
    const std::vector<double>& s = chord_parameters[c];
    const std::size_t count = component.closed() ? s.size() : s.size() - 1;
    for (std::size_t i = 0; i < count && s.size() > 1; ++i) {
      const double s1 = i + 1 < s.size() ? s[i + 1] : s[0] + static_cast<double>(component.piece_count());
      all.push_back({c, i, s[i], s1, component.point(s[i]), component.point(s1)});
    }
  }
  return all;
}

bool adjacent(const Chord& a, const Chord& b, std::size_t chord_count, bool closed) {
  if (a.component != b.component) return false;
  const std::size_t low = std::min(a.index, b.index), high = std::max(a.index, b.index);
  return high - low <= 1 || (closed && low == 0 && high + 1 == chord_count);
}

// Newton's method on c_a(s) - c_b(u) = 0 from where the two chords cross.
Curve_crossing refine(const Curve& curve, const Chord& a, const Chord& b) {
  const Curve_component &ca = curve.components[a.component], &cb = curve.components[b.component];
  const Vector da = a.p1 - a.p0, db = b.p1 - b.p0, offset = b.p0 - a.p0;
  const double denominator = da.x() * db.y() - da.y() * db.x();
  double ta = 0.5, tb = 0.5;  // overlapping chords: their middles
  if (denominator != 0) {
    ta = std::clamp((offset.x() * db.y() - offset.y() * db.x()) / denominator, 0.0, 1.0);
    tb = std::clamp((offset.x() * da.y() - offset.y() * da.x()) / denominator, 0.0, 1.0);
  }
  double s = a.s0 + ta * (a.s1 - a.s0), u = b.s0 + tb * (b.s1 - b.s0);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Vector f = ca.point(s) - cb.point(u), js = ca.derivative(s), ju = -cb.derivative(u);
    const double det = js.x() * ju.y() - js.y() * ju.x();
    if (det == 0) break;  // tangential: keep the chord estimate
    const double step_s = (f.x() * ju.y() - f.y() * ju.x()) / det, step_u = (js.x() * f.y() - js.y() * f.x()) / det;
    const double next_s = std::clamp(s - step_s, a.s0, a.s1), next_u = std::clamp(u - step_u, b.s0, b.s1);
    if (next_s == s && next_u == u) break;
    s = next_s, u = next_u;
  }
  const Point p = CGAL::midpoint(ca.point(s), cb.point(u));
  const auto wrap = [](const Curve_component& c, double t) {
    return c.closed() ? std::fmod(t, static_cast<double>(c.piece_count())) : t;
  };
  return {p, {a.component, wrap(ca, s)}, {b.component, wrap(cb, u)}};
}

bool same_crossing(const Curve_crossing& x, const Curve_crossing& y, double tolerance) {
  const auto close = [&](const Curve_location& l, const Curve_location& m) {
    return l.component == m.component && std::abs(l.parameter - m.parameter) <= tolerance;
  };
  return (close(x.first, y.first) && close(x.second, y.second)) || (close(x.first, y.second) && close(x.second, y.first));
}

}  // namespace

std::vector<Curve_crossing> curve_crossings(const Curve& curve, std::span<const std::vector<double>> chord_parameters) {
  const std::vector<Chord> all = chords(curve, chord_parameters);
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;
  std::vector<Box> boxes;
  boxes.reserve(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto box = Kernel::Segment_2(all[i].p0, all[i].p1).bbox();
    double low[2] = {box.xmin(), box.ymin()}, high[2] = {box.xmax(), box.ymax()};
    boxes.emplace_back(low, high, i);
  }
  std::vector<std::size_t> chord_count(curve.components.size(), 0);
  for (const Chord& chord : all) ++chord_count[chord.component];

  std::vector<Curve_crossing> found;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const Chord &a = all[std::min(x.info(), y.info())], &b = all[std::max(x.info(), y.info())];
    if (adjacent(a, b, chord_count[a.component], curve.components[a.component].closed())) return;
    if (!CGAL::do_intersect(Kernel::Segment_2(a.p0, a.p1), Kernel::Segment_2(b.p0, b.p1))) return;
    found.push_back(refine(curve, a, b));
  });
  // Box intersection reports pairs in an order of its own, and a crossing at a chord vertex
  // is found by several chord pairs: sort, then keep one of each, for a deterministic result.
  std::sort(found.begin(), found.end(), [](const Curve_crossing& x, const Curve_crossing& y) {
    return std::tie(x.first.component, x.first.parameter, x.second.component, x.second.parameter) <
           std::tie(y.first.component, y.first.parameter, y.second.component, y.second.parameter);
  });
  std::vector<Curve_crossing> distinct;
  for (const Curve_crossing& crossing : found) {
    const double tolerance = 1e-9 * static_cast<double>(curve.components[crossing.first.component].piece_count() +
                                                        curve.components[crossing.second.component].piece_count());
    if (std::none_of(distinct.begin(), distinct.end(),
                     [&](const Curve_crossing& kept) { return same_crossing(kept, crossing, tolerance); }))
      distinct.push_back(crossing);
  }
  return distinct;
}

}  // namespace curvebench::geometry
