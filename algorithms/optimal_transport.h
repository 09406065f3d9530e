// Optimal Transport (de Goes, Cohen-Steiner, Alliez, Desbrun 2011, "An Optimal Transport
// Approach to Robust Reconstruction and Simplification of 2D Shapes"; survey,
// "Non-manifold Reconstruction"), written here from the survey and CGAL's documentation
// of Optimal_transportation_reconstruction_2, not from CGAL's code:
//
//  - every input point is a sample of mass 1 (equal points: one sample, their count as mass);
//  - start from the Delaunay triangulation of the points, each sample on the edge to its
//    nearest neighbour;
//  - greedily remove the vertex whose removal least raises the total transport cost, the
//    samples of its edges going to the nearest edge of the filled hole;
//  - an edge transports its samples either spread uniformly along it ("regular": the
//    paper's normal plus tangential cost) or each to its nearer end ("ghost"), whichever
//    costs less; the output is the regular edges and the vertices that receive mass only
//    from ghost edges (isolated vertices).
//
// Why written here rather than wrapping CGAL (which this file did until issue 41): CGAL's
// version broke equal costs by memory address and kept random state between jobs, so runs
// differed between processes and -j settings, and its collapses slowed to 13-17 s at 10^4
// points. Here every tie goes to the smaller index of the lexicographically sorted input,
// so the output is the same for any input order, run or process; and a removal touches
// only its neighbourhood, so the run is O(n log n) for bounded degree. It is not bounded
// on smooth curves: the triangulation fans out across convex arcs, giving vertices
// hundreds of neighbours, each of whose removals simulates the fan's apex again. A hole
// of d vertices is therefore filled from the Delaunay triangulation of its ring, in
// O(d log d), and each sample's nearest edge found by a walk over it (Hole_search), not
// by an O(d^2) fill and O(d) edges per sample; still superlinear (see docs/algorithms.md).
//
// Deviations from the paper and from CGAL, each a choice of this implementation:
//  - the operation is the removal of a vertex from a Delaunay triangulation of the
//    remaining vertices (CGAL's, exact), not a half-edge collapse followed by flips: the
//    triangulation stays Delaunay, so a sample's nearest edges stay near it. Its cost is
//    simulated on the Delaunay fill of the hole, computed from exact predicates;
//  - no vertex relocation: output vertices are input points, so the output is indexed by
//    the input like every other algorithm's, and the cost comparison with CGAL in the
//    tests runs CGAL without relocation too;
//  - a ghost edge sends each sample to its nearer end (exact comparison; the smaller index
//    on a tie);
//  - the default stop is derived from the input (see Optimal_transport_options), and its
//    output also draws the gaps between regular chains: an edge of the triangulation
//    between two chain ends at most 3/2 as long as the longer chain edge at its ends,
//    shortest first. That closes a closed curve's polygon and leaves the chord of an open
//    arc undrawn. The plan and its cost are unchanged; only the drawing closes the gaps.
//
// Decisions on the triangulation (Delaunay, hole fills, hull) are exact predicates. The
// transport plan (which edge a sample goes to) and the greedy order are an optimisation
// over transport costs in double arithmetic, done in a fixed order on coordinates scaled
// by a power of two (exact), and compiled without contraction into fused multiply-adds,
// so they come out the same on every x86-64 machine.
#pragma once

#include <cstddef>
#include <span>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// When the simplification stops; the registry exposes each as a parameter of the same name.
// With neither set, it stops at the first step where every vertex that carries mass lies
// on a regular edge: no isolated vertex. (The greedy order begins at cost 0 with every
// sample at its own vertex, all isolated; each removal spreads samples onto edges.) On
// noise-free closed curves this leaves a seventh to a third of the points in regular
// chains, with gaps between the chains' ends where two chains grew towards each other
// (one or two on the suites' samplings, thousands on 10^5 points of a smooth curve): the
// default output draws the gaps (see the deviations). If that step leaves a branching
// vertex (one on three or more regular edges: a spur, or chains crossing a narrow part),
// the greedy order goes on to the first step with no isolated and no branching vertex, but
// not past twice the transport cost of the step where it would have stopped; it returns
// the first step with the fewest such defects, replaying the greedy order to it. Where
// no step leaves every vertex on an edge (coarse samplings of wiggly curves), that is the
// step with the fewest isolated vertices. Tried and dropped: stopping only where no edge
// carries samples to its ends (3 to 8 vertices left), at the first step whose output is
// closed curves (complex outlines become triangles, open arcs loops), at the first step
// without defects however costly (the same on the survey's complex and spiral outlines),
// and pruning spurs from the drawing (it leaves their ends isolated). The rule is still
// being tuned (issue 41).
struct Optimal_transport_options {
  // Stop when this many vertices remain (0: unset).
  std::size_t vertices = 0;
  // Stop before the Wasserstein distance (the square root of transport cost per unit mass)
  // would exceed this fraction of the points' bounding-box diagonal (0: unset).
  double tolerance = 0;
  // How a simulated removal finds each sample's nearest edge in the filled hole: by a walk
  // over the Delaunay triangulation of a large hole's ring (the default), or by scanning
  // every edge of the hole. Both give the same output in general position (no four points
  // of a ring on a circle, no two edges equally near a sample); the scan, O(d) per sample
  // in a hole of d vertices, is there for tests and benchmarks to compare with.
  enum class Hole_search { ring_triangulation, scan };
  // The hole search a run uses (see Hole_search).
  Hole_search hole_search = Hole_search::ring_triangulation;
};

// The output vertices (input points on a regular edge, or isolated with mass), in
// lexicographic order, and the regular edges between them, canonical. Equal input points
// are one sample of their multiplicity. Throws std::invalid_argument for a non-finite
// coordinate or a negative tolerance.
Reconstruction optimal_transport_reconstruction(std::span<const Point> points,
                                                const Optimal_transport_options& options = {});

// The total transport cost of the plan the simplification ended with, and its vertex
// count: for tests and benchmarks that compare costs at equal output size.
struct Optimal_transport_run {
  Reconstruction reconstruction;  // as optimal_transport_reconstruction returns it
  double cost = 0;              // in the input's squared units
  std::size_t vertices = 0;     // triangulation vertices left (with or without mass)
};
// As optimal_transport_reconstruction, with the cost and vertex count.
Optimal_transport_run optimal_transport_run(std::span<const Point> points, const Optimal_transport_options& options = {});

// The registry's entry "optimal-transport", with parameters vertices and tolerance; it
// simplifies (Algorithm::simplifies).
Algorithm optimal_transport_algorithm();

}  // namespace curvebench::algorithms
