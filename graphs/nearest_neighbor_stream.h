// One point's other points, nearest first, one at a time: for algorithms that grow a
// neighbourhood until it satisfies a test (FitConnect's fitted neighbourhoods), so that
// no bound on k has to be guessed up front.
//
// A best-first search over the Delaunay graph from the centre. It is exact because the
// (k+1)-th nearest point is always a Delaunay neighbour of the centre or of one of the k
// nearer ones (walk the segment from the centre to it: every Voronoi cell crossed belongs
// to a point no farther from the centre). Distances are compared exactly; points at the
// same distance come out in index order, so the stream is the same on every machine.
#pragma once

#include <vector>

#include "graphs/delaunay_triangulation.h"

namespace curvebench::graphs {

// The other points of one centre, nearest first, produced on demand. Keeps a pointer to
// the triangulation.
class Nearest_neighbor_stream {
 public:
  // `dt` must outlive the stream.
  Nearest_neighbor_stream(const Delaunay_triangulation& dt, Vertex center);

  // Starts again from another centre, keeping the storage: for one stream per point in
  // turn (Lenz's probes), which would otherwise allocate three vectors each.
  void restart(Vertex center);

  // The next nearest point, or no_vertex once every other point has been given.
  Vertex next();

 private:
  void reach(Vertex v);
  bool farther(Vertex a, Vertex b) const;  // the heap order: a after b

  const Delaunay_triangulation* dt_;
  Vertex center_;
  std::vector<Vertex> frontier_;  // a heap, nearest on top
  std::vector<Vertex> seen_;      // every vertex ever reached (small: about 6 per point given)
  std::vector<Vertex> ready_;     // a group of equidistant points, the next one last
};

}  // namespace curvebench::graphs
