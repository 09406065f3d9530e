#include "graphs/nearest_neighbor_stream.h"

#include <algorithm>
#include <functional>

#include "graphs/proximity_predicates.h"

namespace curvebench::graphs {

Nearest_neighbor_stream::Nearest_neighbor_stream(const Delaunay_triangulation& dt, Vertex center) : dt_(&dt) {
  restart(center);
}

void Nearest_neighbor_stream::restart(Vertex center) {
  center_ = center;
  frontier_.clear();
  seen_.assign(1, center);
  ready_.clear();
  for (const Vertex w : dt_->neighbors(center)) reach(w);
}

bool Nearest_neighbor_stream::farther(Vertex a, Vertex b) const {
  return compare_distances(dt_->point(center_), dt_->point(a), dt_->point(b)) == CGAL::NEGATIVE;
}

void Nearest_neighbor_stream::reach(Vertex v) {
  if (std::find(seen_.begin(), seen_.end(), v) != seen_.end()) return;
  seen_.push_back(v);
  frontier_.push_back(v);
  std::push_heap(frontier_.begin(), frontier_.end(), [this](Vertex a, Vertex b) { return farther(a, b); });
}

Vertex Nearest_neighbor_stream::next() {
  const auto heap_order = [this](Vertex a, Vertex b) { return farther(a, b); };
  if (ready_.empty()) {
    // Take every point at the nearest remaining distance, and what they reach at that same
    // distance, before giving any of them: a tie may hide a smaller index one step further.
    while (!frontier_.empty() &&
           (ready_.empty() || compare_distances(dt_->point(center_), dt_->point(frontier_.front()),
                                                dt_->point(ready_.front())) == CGAL::ZERO)) {
      std::pop_heap(frontier_.begin(), frontier_.end(), heap_order);
      const Vertex v = frontier_.back();
      frontier_.pop_back();
      ready_.push_back(v);
      for (const Vertex w : dt_->neighbors(v)) reach(w);
    }
    std::sort(ready_.begin(), ready_.end(), std::greater<>());
  }
  if (ready_.empty()) return no_vertex;
  const Vertex v = ready_.back();
  ready_.pop_back();
  return v;
}

}  // namespace curvebench::graphs
