// Range search on a Delaunay triangulation: breadth-first from a vertex through the
// vertices that lie inside a region.
//
// Why this finds every point of a disk D: take a site x in D and walk the segment from x
// to the centre c of D. Every site y whose Voronoi cell the segment crosses, at z, has
// |zy| <= |zx|, hence |cy| <= |cz| + |zx| = |cx|: y is in D too, and consecutive cells
// along the segment are Delaunay neighbours. So the sites in D form a connected subgraph
// that contains the site nearest c. Callers start from that site: p itself for a disk
// centred at point p, and p for the midpoint of a Gabriel edge pq.
#pragma once

#include <vector>

#include "graphs/delaunay_triangulation.h"

namespace curvebench::graphs {

// A reusable search on one triangulation: each query resets its marks by a new stamp, not
// by clearing them. Keeps a reference to the triangulation; one object per thread.
class Delaunay_region_search {
 public:
  // `dt` must outlive the search, which holds one mark per vertex.
  explicit Delaunay_region_search(const Delaunay_triangulation& dt) : dt_(dt), mark_(dt.size(), 0) {}

  // Calls visit(v) for each vertex v != start reached from `start` through vertices with
  // inside(v), stopping early when visit returns true. Returns whether it stopped early.
  template <class Inside, class Visit>
  bool find_if(Vertex start, Inside inside, Visit visit) {
    if (++stamp_ == 0) {  // stamps wrapped around: forget every old mark
      std::fill(mark_.begin(), mark_.end(), 0);
      stamp_ = 1;
    }
    queue_.assign(1, start);
    mark_[start] = stamp_;
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      for (const Vertex w : dt_.neighbors(queue_[head])) {
        if (mark_[w] == stamp_) continue;
        mark_[w] = stamp_;
        if (!inside(w)) continue;
        if (visit(w)) return true;
        queue_.push_back(w);
      }
    }
    return false;
  }

 private:
  const Delaunay_triangulation& dt_;
  std::vector<unsigned> mark_;
  unsigned stamp_ = 0;
  std::vector<Vertex> queue_;
};

}  // namespace curvebench::graphs
