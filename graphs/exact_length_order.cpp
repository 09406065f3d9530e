#include "graphs/exact_length_order.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <tuple>
#include <utility>

#include "geometry/exact_sign.h"
#include "geometry/radix_sort.h"
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

// Whether every key up to shorter_key is certainly shorter than every key from longer_key
// on (see the header): the filter GathanG's corner order splits its runs by, too.
bool separated(double shorter_key, double longer_key) {
  return geometry::certain_sign_of_difference(shorter_key, longer_key) == CGAL::POSITIVE;
}

// The sort for any edge record with a rounded squared_length and end points source < target.
template <class Edge_record>
void sort_records_by_exact_length(std::span<const Point> points, std::span<Edge_record> edges) {
  const auto shorter = [&](const Edge_record& a, const Edge_record& b) {
    const CGAL::Sign s = compare_lengths(points[a.source], points[a.target], a.squared_length, points[b.source],
                                         points[b.target], b.squared_length);
    return s == CGAL::POSITIVE ||
           (s == CGAL::ZERO && std::tie(a.source, a.target) < std::tie(b.source, b.target));
  };
  geometry::radix_sort_by_key(edges, [](const Edge_record& e) { return e.squared_length; });
  // A run the rounded keys cannot split: sorted by keys 2^48 times finer, split where
  // those separate, and only what is left in exact order. On an evenly sampled curve most
  // edges have one length to 15 digits (a run of 600,000 at 10^6 points), which the exact
  // comparator alone took as long as the triangulation to sort.
  std::vector<std::pair<geometry::Refined_squared_distance, Edge_record>> refined;
  const auto sort_run = [&](auto run, auto end) {
    if (!(run->squared_length >= 0x1p-800 && std::prev(end)->squared_length <= 0x1p1000))
      return std::sort(run, end, shorter);  // the fine keys could underflow or overflow
    refined.clear();
    for (auto e = run; e != end; ++e) {
      if (end - e > 8) {  // sorted by length, the ends are scattered: start loading them early
        __builtin_prefetch(&points[e[8].source]);
        __builtin_prefetch(&points[e[8].target]);
      }
      refined.emplace_back(geometry::refined_squared_distance(points[e->source], points[e->target]), *e);
    }
    std::sort(refined.begin(), refined.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const auto finely_separated = [](const auto& shorter, const auto& longer) {
      return geometry::certain_sign_of_difference(shorter, longer) == CGAL::POSITIVE;
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

}  // namespace

void sort_by_exact_length(std::span<const Point> points, std::vector<Edge_with_length>& edges) {
  sort_records_by_exact_length(points, std::span(edges));
}

std::size_t sort_shortest_by_exact_length(std::span<const Point> points, std::vector<Edge_with_length>& edges,
                                          std::size_t begin, std::size_t count) {
  const auto by_key = [](const Edge_with_length& a, const Edge_with_length& b) {
    return a.squared_length < b.squared_length;
  };
  const auto first = edges.begin() + std::ptrdiff_t(begin);
  auto end = edges.end();
  if (count < edges.size() - begin) {
    // The count shortest keys, then every key the filter cannot put after the longest of
    // them, until it can: what is left is certainly longer than all that was taken.
    end = first + std::ptrdiff_t(count);
    std::nth_element(first, end, edges.end(), by_key);
    for (double longest = std::max_element(first, ++end, by_key)->squared_length;;) {
      const auto taken_end = std::partition(
          end, edges.end(), [&](const Edge_with_length& e) { return !separated(longest, e.squared_length); });
      if (taken_end == end) break;
      longest = std::max(longest, std::max_element(end, taken_end, by_key)->squared_length);
      end = taken_end;
    }
  }
  sort_records_by_exact_length(points, std::span(first, end));
  return std::size_t(end - edges.begin());
}

std::vector<std::uint32_t> edge_ids_by_exact_length(std::span<const Point> points, std::span<const Delaunay_edge> edges) {
  struct Record {
    double squared_length;
    Vertex source, target;
    std::uint32_t id;
  };
  std::vector<Record> records;
  records.reserve(edges.size());
  for (std::uint32_t id = 0; id < edges.size(); ++id) {
    const Delaunay_edge& e = edges[id];
    records.push_back(
        {geometry::squared_distance_approximation(points[e.source], points[e.target]), e.source, e.target, id});
  }
  sort_records_by_exact_length(points, std::span(records));
  std::vector<std::uint32_t> ids(records.size());
  for (std::size_t r = 0; r < records.size(); ++r) ids[r] = records[r].id;
  return ids;
}

}  // namespace curvebench::graphs
