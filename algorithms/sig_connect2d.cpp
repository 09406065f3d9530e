#include "algorithms/sig_connect2d.h"

#include <array>

#include "graphs/delaunay_triangulation.h"
#include "graphs/exact_length_order.h"
#include "graphs/sphere_of_influence_delaunay_graph.h"

namespace curvebench::algorithms {
namespace {

using graphs::Delaunay_edge;
using graphs::Delaunay_triangulation;
using graphs::Edge_with_length;
using graphs::no_vertex;
using graphs::Vertex;

std::vector<Edge_with_length> shortest_first(std::span<const Point> points, const std::vector<Delaunay_edge>& edges) {
  std::vector<Edge_with_length> ranked = graphs::with_lengths(points, edges);
  graphs::sort_by_exact_length(points, ranked);
  return ranked;
}

// S1 and S2: SIGDT, thinned longest edge first while both ends keep valence >= 2. Returns
// SIGDT's edges shortest first with a flag per edge: still there.
std::vector<bool> thinned_sigdt(const Delaunay_triangulation& dt, std::vector<Edge_with_length>& ranked,
                                std::vector<std::uint32_t>& valence) {
  std::vector<Delaunay_edge> sigdt;
  for (const auto& [i, j] : graphs::edge_list(graphs::sphere_of_influence_delaunay_graph(dt)))
    sigdt.push_back({Vertex(i), Vertex(j), no_vertex, no_vertex});
  ranked = shortest_first(dt.points(), sigdt);
  for (const Edge_with_length& e : ranked) ++valence[e.source], ++valence[e.target];

  std::vector<bool> kept(ranked.size(), true);
  for (std::size_t k = ranked.size(); k-- > 0;) {
    const Edge_with_length& e = ranked[k];
    if (valence[e.source] > 2 && valence[e.target] > 2) {
      kept[k] = false;
      --valence[e.source], --valence[e.target];
    }
  }
  return kept;
}

// S3: every vertex of valence > 2 keeps its two shortest edges. Its neighbours have
// valence <= 2 (an edge survived S2 because one of its ends had), so the order of the
// vertices does not matter.
void cut_junctions(std::size_t n, const std::vector<Edge_with_length>& ranked, std::vector<bool>& kept,
                   std::vector<std::uint32_t>& valence) {
  std::vector<std::size_t> first(n + 1, 0);
  for (std::size_t k = 0; k < ranked.size(); ++k)
    if (kept[k]) ++first[ranked[k].source + 1], ++first[ranked[k].target + 1];
  for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<std::size_t> incident(first.back()), fill(first.begin(), first.end() - 1);
  for (std::size_t k = 0; k < ranked.size(); ++k)  // ascending k: each list comes out shortest first
    if (kept[k]) incident[fill[ranked[k].source]++] = k, incident[fill[ranked[k].target]++] = k;

  for (std::size_t v = 0; v < n; ++v) {
    if (valence[v] <= 2) continue;
    int seen = 0;
    for (std::size_t i = first[v]; i < first[v + 1]; ++i) {
      const std::size_t k = incident[i];
      if (!kept[k] || ++seen <= 2) continue;
      kept[k] = false;
      --valence[ranked[k].source], --valence[ranked[k].target];
    }
  }
}

// The curve as each vertex's (at most two) neighbours.
class Links {
 public:
  explicit Links(std::size_t n) : links_(n, {no_vertex, no_vertex}) {}
  bool linked(Vertex a, Vertex b) const { return links_[a][0] == b || links_[a][1] == b; }
  bool open(Vertex v) const { return links_[v][1] == no_vertex; }
  void link(Vertex a, Vertex b) { add(a, b), add(b, a); }

  std::vector<Edge> edges() const {
    std::vector<Edge> result;
    for (Vertex v = 0; v < links_.size(); ++v)
      for (const Vertex w : links_[v])
        if (w != no_vertex && v < w) result.emplace_back(v, w);
    return geometry::canonical_edges(std::move(result));
  }

 private:
  void add(Vertex a, Vertex b) { links_[a][links_[a][0] == no_vertex ? 0 : 1] = b; }
  std::vector<std::array<Vertex, 2>> links_;
};

}  // namespace

std::vector<Edge> sig_connect2d_reconstruction(std::span<const Point> points) {
  const Delaunay_triangulation dt(points);
  const std::size_t n = dt.size();
  std::vector<Edge_with_length> ranked;
  std::vector<std::uint32_t> valence(n, 0);
  std::vector<bool> kept = thinned_sigdt(dt, ranked, valence);
  cut_junctions(n, ranked, kept, valence);

  Links curve(n);
  for (std::size_t k = 0; k < ranked.size(); ++k)
    if (kept[k]) curve.link(ranked[k].source, ranked[k].target);

  // S4: join open ends (valence 0 or 1) along Delaunay edges, shortest first.
  std::vector<Delaunay_edge> between_open_ends;
  for (const Delaunay_edge& e : dt.edges())
    if (curve.open(e.source) && curve.open(e.target) && !curve.linked(e.source, e.target))
      between_open_ends.push_back(e);
  for (const Edge_with_length& e : shortest_first(dt.points(), between_open_ends))
    if (curve.open(e.source) && curve.open(e.target)) curve.link(e.source, e.target);
  return curve.edges();
}

Algorithm sig_connect2d_algorithm() {
  return {
      .name = "sig-connect2d",
      .title = "SIG-Connect2D",
      .reference = "Marin, Ohrhallinger, Wimmer 2022",
      .category = "Graph Based",
      .parameters = {},
      .capabilities = {.non_uniform = Support::yes, .manifold = Support::yes, .multiple = Support::yes,
                       .sharp = Support::yes, .time_complexity = "O(n log n)"},
      .condition = {.statement = "none for this extraction (the paper proves SIGDT contains the curve under "
                                 "its own sampling condition)"},
      .reconstruct = edges_on_input(sig_connect2d_reconstruction),
  };
}

}  // namespace curvebench::algorithms
