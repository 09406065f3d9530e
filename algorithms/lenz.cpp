#include "algorithms/lenz.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <unordered_set>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"
#include "graphs/exact_length_order.h"
#include "graphs/nearest_neighbor_stream.h"

namespace curvebench::algorithms {
namespace {

using graphs::no_vertex;
using graphs::Vertex;

// True if q lies in the probe at the end p of edge op: the closed cone of half-angle
// acos(c) about the direction p - o (c = cos_alpha > 0), apex p excluded.
bool in_probe(const Point& o, const Point& p, const Point& q, double cos_alpha) {
  using geometry::difference, geometry::dot, geometry::exact_sign, geometry::squared_length;
  if (exact_sign([&]<class NT>(std::type_identity<NT>) { return dot(difference<NT>(p, o), difference<NT>(q, p)); }) !=
      CGAL::POSITIVE)
    return false;
  return exact_sign([&]<class NT>(std::type_identity<NT>) {
           const auto d = difference<NT>(p, o), v = difference<NT>(q, p);
           const NT along = dot(d, v), c = NT(cos_alpha);
           return along * along - c * c * squared_length(d) * squared_length(v);
         }) != CGAL::NEGATIVE;
}

class Tracer {
 public:
  Tracer(const graphs::Delaunay_triangulation& dt, std::size_t k, double cos_alpha)
      : dt_(dt), k_(k), cos_alpha_(cos_alpha), degree_(dt.size(), 0) {
    keys_.reserve(dt.size());
  }

  bool used(Vertex v) const { return degree_[v] > 0; }
  std::size_t degree(Vertex v) const { return degree_[v]; }

  // Adds edge ab; false if it was there already.
  bool add(Vertex a, Vertex b) {
    const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
    if (!keys_.insert(key).second) return false;
    ++degree_[a], ++degree_[b];
    edges_.emplace_back(a, b);
    return true;
  }

  // Adds seed ab and traces on beyond b, then beyond a; false if the probe found nothing
  // at either end.
  bool trace_seed(Vertex a, Vertex b) {
    const std::size_t before = edges_.size();
    add(a, b);
    trace(a, b);
    trace(b, a);
    return edges_.size() > before + 1;
  }

  // Traces on beyond p, the last edge being op, until the probe is empty or the next edge
  // exists. Every step adds an edge of the kNN graph, so this ends.
  void trace(Vertex o, Vertex p) {
    for (;;) {
      const Vertex q = probe(o, p);
      if (q == no_vertex || !add(p, q)) return;
      o = p;
      p = q;
    }
  }

  // The edges but the `dropped` seeds.
  std::vector<Edge> edges(const std::vector<Edge>& dropped) && {
    std::vector<Edge> edges = geometry::canonical_edges(std::move(edges_));
    std::erase_if(edges, [&](const Edge& e) { return std::binary_search(dropped.begin(), dropped.end(), e); });
    return edges;
  }

 private:
  // The nearest of p's k nearest points inside the probe, or no_vertex. They come one at a
  // time, as the probe asks: it usually takes the first or the second, and ranking all k
  // of every point first was a fifth of the run at 10^6 points.
  Vertex probe(Vertex o, Vertex p) {
    if (nearest_) {
      nearest_->restart(p);
    } else {
      nearest_.emplace(dt_, p);
    }
    for (std::size_t rank = 0; rank < k_; ++rank) {
      const Vertex q = nearest_->next();
      if (q == no_vertex) break;
      if (in_probe(dt_.point(o), dt_.point(p), dt_.point(q), cos_alpha_)) return q;
    }
    return no_vertex;
  }

  const graphs::Delaunay_triangulation& dt_;
  std::size_t k_;
  std::optional<graphs::Nearest_neighbor_stream> nearest_;  // made at the first probe, then restarted
  double cos_alpha_;
  std::vector<std::size_t> degree_;
  std::unordered_set<std::uint64_t> keys_;
  std::vector<Edge> edges_;
};

}  // namespace

std::vector<Edge> lenz_reconstruction(std::span<const Point> points, double alpha_degrees, std::size_t k) {
  if (!(alpha_degrees > 0 && alpha_degrees < 90)) throw std::invalid_argument("lenz: alpha must lie in (0, 90)");
  if (k < 1) throw std::invalid_argument("lenz: k must be at least 1");
  const graphs::Delaunay_triangulation dt(points);  // checks distinct, finite points
  Tracer tracer(dt, k, std::cos(alpha_degrees * std::numbers::pi / 180));

  // The nearest-neighbour pairs, each once, shortest first.
  std::vector<Vertex> nearest(dt.size());
  for (Vertex v = 0; v < dt.size(); ++v) nearest[v] = dt.nearest_neighbor(v);
  std::vector<graphs::Delaunay_edge> pairs;
  for (Vertex v = 0; v < dt.size(); ++v) {
    const Vertex w = nearest[v];
    if (w != no_vertex && (v < w || nearest[w] != v)) pairs.push_back({std::min(v, w), std::max(v, w), no_vertex, no_vertex});
  }
  std::vector<graphs::Edge_with_length> seeds = graphs::with_lengths(points, pairs);
  graphs::sort_by_exact_length(points, seeds);

  std::vector<Edge> lone_seeds;  // seeds that no trace extended
  for (const graphs::Edge_with_length& seed : seeds) {
    const Vertex a = seed.source, b = seed.target;
    if (tracer.used(a) || tracer.used(b)) continue;
    if (!tracer.trace_seed(a, b)) lone_seeds.emplace_back(a, b);
  }
  // A lone seed between two points that traces passed through later joins two branches
  // where they come close (the short sides around a crossing): drop it.
  std::vector<Edge> dropped;
  for (const auto& [a, b] : lone_seeds)
    if (tracer.degree(Vertex(a)) > 1 && tracer.degree(Vertex(b)) > 1) dropped.emplace_back(a, b);
  std::sort(dropped.begin(), dropped.end());
  return std::move(tracer).edges(dropped);
}

Algorithm lenz_algorithm() {
  static const Parameter alpha{.name = "alpha", .default_value = 40, .minimum = 1, .maximum = 89,
                               .meaning = "half-angle (degrees) of the probe cone about the last edge; a turn "
                                          "wider than alpha ends the trace (a sharp corner)"};
  // k = 1 is the function's, not the registry's: the single nearest point is often behind.
  static const Parameter k{.name = "k", .type = Parameter_type::integer, .default_value = 8, .minimum = 2,
                           .maximum = 64, .meaning = "the probe sees each end's k nearest points"};
  return {
      .name = "lenz",
      .title = "Lenz",
      .reference = "Lenz 2006",
      .category = "Feature Size Criteria",
      .parameters = {alpha, k},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::no, .open = Support::yes,
                       .multiple = Support::no, .sharp = Support::yes, .guarantee = true,
                       .time_complexity = "O(n log n)"},
      // The survey's table; the paper claims this without proof, so no bound is registered.
      .condition = {.statement = "epsilon < 0.48 (no proof)"},
      .reconstruct = edges_on_input([](std::span<const Point> points, const Parameter_values& values) {
        return lenz_reconstruction(points, values[alpha], static_cast<std::size_t>(values[k]));
      }),
  };
}

}  // namespace curvebench::algorithms
