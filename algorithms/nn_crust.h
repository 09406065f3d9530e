// NN-Crust (Dey, Kumar 1999, "A simple provable algorithm for curve reconstruction";
// survey, "Feature Size Criteria Reconstruction"): connect every point p to its nearest
// neighbour q, then to its nearest point s on the far side of p, angle qps > 90 degrees;
// the union of these edges reconstructs every epsilon-sampling with epsilon < 1/3.
//
// The neighbours are those of the definition, over all points: nearest by exact squared
// distance, ties to the smaller index. The paper looks for them among p's Delaunay
// neighbours only, which is the same under its sampling condition but not for every input:
// the nearest point behind p need not be a Delaunay neighbour of p (nn_crust_test.cpp has
// one). So no triangulation is needed: two exact queries of a kd-tree per point
// (graphs/point_kd_tree.h), the second pruning boxes outside the half-plane, find both.
// Measured at 10^6 points of a smooth closed curve: under half the time of a bare CGAL
// Delaunay triangulation of the same points (docs/development.md, "Speed at 10^6 points").
// Where the tree cannot work (coordinates beyond 2^400, points packed far below their
// spread) a search outwards through CGAL's triangulation decides instead.
//
// The same search serves HNN-Crust (hnn_crust.h), whose half neighbour lies beyond the
// bisector of pq instead.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// Where p's second ("half") neighbour may lie, given its nearest neighbour q: an open
// half-plane, tested exactly.
enum class Half_plane {
  behind_p,       // NN-Crust: (s - p).(q - p) < 0, i.e. the angle qps exceeds 90 degrees
  beyond_bisector // HNN-Crust: |ps| < |qs|, the side of pq's bisector that holds p
};

// The index that stands for no neighbour.
inline constexpr std::uint32_t no_neighbor = std::numeric_limits<std::uint32_t>::max();

// The two neighbours of one point, as indices into the points.
struct Nearest_and_half_neighbor {
  std::uint32_t nearest = no_neighbor;  // none only for a lone point
  std::uint32_t half = no_neighbor;     // none if the half-plane holds no point
};

// Where the neighbours are searched. Both give the same answer, exactly.
enum class Search_structure {
  kd_tree,               // the fast one; falls back to the triangulation where it cannot
                         // work (coordinates beyond 2^400, points packed below 2^-450)
  delaunay_triangulation // the neighbours' neighbours outwards from each point
};

// For every point p (distinct points), its nearest neighbour q and its half neighbour: the
// nearest point in `half_plane`. "Nearest" is by exact squared distance, ties to the
// smaller index, over all points. Throws std::invalid_argument for equal points or a
// non-finite coordinate.
std::vector<Nearest_and_half_neighbor> nearest_and_half_neighbors(
    std::span<const Point> points, Half_plane half_plane, Search_structure structure = Search_structure::kd_tree);

// The NN-Crust edges: {p, nearest(p)} and {p, half(p)} for every p (behind_p), canonical
// (i < j, sorted, no repeats).
std::vector<Edge> nn_crust_reconstruction(std::span<const Point> points);
// The registry's entry "nn-crust", without parameters.
Algorithm nn_crust_algorithm();

}  // namespace curvebench::algorithms
