// libFuzzer target for the benchmark's metrics (geometry/metrics/curve_distance.h,
// nearest_segment_index.h, curve_topology.h) on degenerate edge chains: coincident,
// collinear and one-ulp-apart points, zero-length edges, scales from 2^-1000 to 1e300
// (degenerate_point_program.h). Laws: the nearest segment is the closest of all (brute
// force), H_D is symmetric and bounds RMS_D, the topology counts add up, and only an
// extent that overflows a double is refused (std::invalid_argument).
//
// Input: one byte, the number of points k of the first curve (mod 33); then one point
// program whose first k points are the first curve's vertices and the rest the second's;
// each curve is the chain of its vertices, closed if it has three or more.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fuzz/degenerate_point_program.h"
#include "fuzz/fuzz_target.h"
#include "geometry/metrics/curve_distance.h"
#include "geometry/metrics/curve_topology.h"
#include "geometry/metrics/nearest_segment_index.h"
#include "geometry/io/point_io.h"

namespace curvebench::fuzz {
namespace {

using geometry::Edge;
using geometry::Point;

std::vector<Edge> chain(std::size_t first, std::size_t count) {
  std::vector<Edge> edges;
  for (std::size_t i = 0; i + 1 < count; ++i) edges.emplace_back(first + i, first + i + 1);
  if (count >= 3) edges.emplace_back(first, first + count - 1);
  return edges;
}

// True if the points' extent (their bounding box's squared diagonal, which the metrics
// check) or a squared difference overflows: then refusing is right. The box's diagonal can
// overflow while every pair of points squares to a finite distance (a campaign found
// points at 1e154 spread along both axes), and the metrics refuse those too.
bool overflows(const std::vector<Point>& points) {
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for (const Point& a : points) {
    xmin = std::min(xmin, a.x()), xmax = std::max(xmax, a.x()), ymin = std::min(ymin, a.y()), ymax = std::max(ymax, a.y());
    for (const Point& b : points) {
      const double dx = a.x() - b.x(), dy = a.y() - b.y();
      if (!std::isfinite(dx * dx + dy * dy)) return true;
    }
  }
  const double width = xmax - xmin, height = ymax - ymin;
  return !points.empty() && !std::isfinite(width * width + height * height);
}

void check_metrics(const std::vector<Point>& points, std::size_t split) {
  const std::vector<Edge> a = chain(0, split), b = chain(split, points.size() - split);
  const auto context = [&] {
    std::ostringstream out;
    out << "first curve: points 0.." << split << " of\n";
    geometry::write_points(out, points);
    return out.str();
  };
  const geometry::Polyline_view first{points, a}, second{points, b};
  geometry::Curve_distance forward, backward;
  try {
    const double spacing = geometry::default_distance_spacing(first);
    forward = geometry::curve_distance(first, second, spacing);
    backward = geometry::curve_distance(second, first, spacing);
    if (!b.empty()) {
      // The oracle: the exact distance to every segment (Epeck), rounded once. The index
      // works in double, so it may be off by a few ulps of the largest coordinate (not of
      // the distance, which may be far smaller near an end point), and by the square root
      // of a few subnormals where the squared distance underflows.
      double largest = 0;
      for (const Point& p : points) largest = std::max({largest, std::abs(p.x()), std::abs(p.y())});
      const double slack = 16 * largest * std::numeric_limits<double>::epsilon() +
                           std::sqrt(64 * std::numeric_limits<double>::denorm_min());
      using Exact = geometry::Exact_kernel;
      const auto exact = [](const Point& p) { return Exact::Point_2(p.x(), p.y()); };
      const geometry::Nearest_segment_index index(points, b);
      for (const Point& q : points) {
        Exact::FT best = -1;
        for (const auto& [i, j] : b) {
          const Exact::FT d = points[i] == points[j]
                                  ? CGAL::squared_distance(exact(q), exact(points[i]))
                                  : CGAL::squared_distance(exact(q), Exact::Segment_2(exact(points[i]), exact(points[j])));
          if (best < 0 || d < best) best = d;
        }
        const double oracle = std::sqrt(CGAL::to_double(best)), found = std::sqrt(index.nearest(q)->squared_distance);
        FUZZ_CHECK(found == oracle || std::abs(found - oracle) <= 1e-9 * oracle + slack,  // equal: both infinite
                   "the nearest segment is the closest of all (to a few ulps of the coordinates)", context());
      }
    }
  } catch (const std::invalid_argument&) {
    FUZZ_CHECK(overflows(points), "only an overflowing extent is refused", context());
    return;
  }
  FUZZ_CHECK(forward.hausdorff == backward.hausdorff, "H_D is symmetric", context());
  FUZZ_CHECK(!(forward.rms > forward.hausdorff * (1 + 1e-9)), "RMS_D <= H_D", context());
  FUZZ_CHECK(!std::isnan(forward.hausdorff) || overflows(points), "H_D is a number", context());

  std::vector<Edge> both = a;
  both.insert(both.end(), b.begin(), b.end());
  both.erase(std::remove_if(both.begin(), both.end(), [](const Edge& e) { return e.first == e.second; }), both.end());
  both = geometry::canonical_edges(std::move(both));
  const geometry::Curve_topology t = geometry::curve_topology(points.size(), both);
  FUZZ_CHECK(t.open_components + t.closed_components <= t.components && t.components <= both.size(),
             "open and closed components are components", context());
  FUZZ_CHECK(t.unconnected <= points.size() && t.manifold == (t.max_degree <= 2), "degrees add up", context());
}

}  // namespace
}  // namespace curvebench::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvebench;
  fuzz::Fuzz_input input(data, size);
  const std::size_t split = input.byte() % 33;
  const std::vector<geometry::Point> points = fuzz::decode_degenerate_points(input, 64);
  fuzz::check_metrics(points, std::min(split, points.size()));
  return 0;
}
