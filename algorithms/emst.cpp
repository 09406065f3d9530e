#include "algorithms/emst.h"

#include "graphs/euclidean_minimum_spanning_tree.h"

namespace curvebench::algorithms {

std::vector<Edge> emst_reconstruction(std::span<const Point> points) {
  return graphs::edge_list(graphs::euclidean_minimum_spanning_tree(points));
}

Algorithm emst_algorithm() {
  return {
      .name = "emst",
      .title = "EMST-based",
      .reference = "de Figueiredo, Gomes 1994",
      .category = "Graph Based",
      .parameters = {},
      .capabilities = {.manifold = Support::yes, .open = Support::only, .guarantee = true,
                       .time_complexity = "O(n log n)"},
      // Proven for open curves sampled densely in an empty tubular neighbourhood; the
      // survey gives no epsilon for it.
      .condition = {.statement = "dense uniform sampling of an open curve"},
      .reconstruct = edges_on_input(emst_reconstruction),
  };
}

}  // namespace curvebench::algorithms
