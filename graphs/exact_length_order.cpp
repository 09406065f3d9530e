#include "graphs/exact_length_order.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <tuple>
#include <utility>

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

std::vector<Edge_with_length> with_lengths(std::span<const Point> points, std::span<const Delaunay_edge> edges) {
  std::vector<Edge_with_length> result;
  result.reserve(edges.size());
  for (const Delaunay_edge& e : edges)
    result.push_back(
        {geometry::squared_distance_approximation(points[e.source], points[e.target]), e.source, e.target});
  return result;
}

namespace {

// a + b as the rounded sum and its rounding error, exactly (Knuth's TwoSum).
std::pair<double, double> two_sum(double a, double b) {
  const double sum = a + b, b_part = sum - a;
  return {sum, (a - (sum - b_part)) + (b - b_part)};
}

// |ab|^2 as an unevaluated sum hi + lo, within 2^-96 |ab|^2 of the exact value (for
// |ab|^2 in [2^-800, 2^1000]: no term underflows or overflows). The differences are exact
// as hi + lo pairs, the squares of their high parts exact as fma splits, and what is left
// is smaller than the square by 2^-52 or more and rounded once or twice.
struct Refined_length {
  double hi, lo;
  friend bool operator<(const Refined_length& a, const Refined_length& b) {
    return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
  }
};

Refined_length refined_squared_length(const Point& a, const Point& b) {
  const auto [hx, lx] = two_sum(a.x(), -b.x());
  const auto [hy, ly] = two_sum(a.y(), -b.y());
  const double px = hx * hx, py = hy * hy;
  const auto [hi, carry] = two_sum(px, py);
  const double lo = carry + std::fma(hx, hx, -px) + std::fma(hy, hy, -py) + (2 * hx * lx + lx * lx) +
                    (2 * hy * ly + ly * ly);
  const double sum = hi + lo;
  return {sum, lo - (sum - hi)};
}

}  // namespace

void sort_by_exact_length(std::span<const Point> points, std::vector<Edge_with_length>& edges) {
  const auto shorter = [&](const Edge_with_length& a, const Edge_with_length& b) {
    const CGAL::Sign s = compare_lengths(points[a.source], points[a.target], a.squared_length, points[b.source],
                                         points[b.target], b.squared_length);
    return s == CGAL::POSITIVE ||
           (s == CGAL::ZERO && std::tie(a.source, a.target) < std::tie(b.source, b.target));
  };
  std::sort(edges.begin(), edges.end(),
            [](const Edge_with_length& a, const Edge_with_length& b) { return a.squared_length < b.squared_length; });
  const auto separated = [](double shorter_key, double longer_key) {
    return shorter_key >= 0x1p-900 && std::isfinite(longer_key) &&
           longer_key - shorter_key > (shorter_key + longer_key) * 0x1p-48;
  };
  // A run the rounded keys cannot split: sorted by keys 2^48 times finer, split where
  // those separate, and only what is left in exact order. On an evenly sampled curve most
  // edges have one length to 15 digits (a run of 600,000 at 10^6 points), which the exact
  // comparator alone took as long as the triangulation to sort.
  std::vector<std::pair<Refined_length, Edge_with_length>> refined;
  const auto sort_run = [&](auto run, auto end) {
    if (!(run->squared_length >= 0x1p-800 && std::prev(end)->squared_length <= 0x1p1000))
      return std::sort(run, end, shorter);  // the fine keys could underflow or overflow
    refined.clear();
    for (auto e = run; e != end; ++e) refined.emplace_back(refined_squared_length(points[e->source], points[e->target]), *e);
    std::sort(refined.begin(), refined.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    // Within a run the high parts agree to 2^-47, so their difference is exact.
    const auto finely_separated = [](const Refined_length& a, const Refined_length& b) {
      return (b.hi - a.hi) + (b.lo - a.lo) > (a.hi + b.hi) * 0x1p-90;
    };
    auto out = run;
    for (std::size_t first = 0; first < refined.size();) {
      std::size_t last = first + 1;
      while (last < refined.size() && !finely_separated(refined[last - 1].first, refined[last].first)) ++last;
      const auto group = out;
      for (std::size_t k = first; k < last; ++k) *out++ = refined[k].second;
      if (last - first > 1) std::sort(group, out, shorter);
      first = last;
    }
  };
  for (auto run = edges.begin(); run != edges.end();) {
    auto end = std::next(run);
    while (end != edges.end() && !separated(std::prev(end)->squared_length, end->squared_length)) ++end;
    if (std::distance(run, end) > 1) sort_run(run, end);
    run = end;
  }
}

}  // namespace curvebench::graphs
