// The Delaunay triangulation of a point set, flattened to index arrays: the common
// first step of every proximity graph and of most reconstruction algorithms.
//
// Built once with CGAL (spatially sorted insertion; CGAL breaks cocircular ties by a
// symbolic perturbation, so the triangulation does not depend on the input order), then
// read through plain arrays: each finite edge with the vertices opposite it, each
// vertex's neighbours and, when asked for, the triangles. Collinear input (CGAL
// dimension 1) gives the chain of consecutive points; 0 or 1 point gives no edge.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/kernel.h"

namespace curvebench::graphs {

using geometry::Point;
// A point's index in the input span: the triangulation's name for a vertex.
using Vertex = std::uint32_t;
// No vertex: the missing apex of a hull edge, or the nearest neighbour of a lone point.
inline constexpr Vertex no_vertex = std::numeric_limits<Vertex>::max();

// A position in Delaunay_triangulation::edges().
using Edge_id = std::uint32_t;
// A position in Delaunay_triangulation::triangles().
using Triangle_id = std::uint32_t;
// No triangle: across a side on the convex hull.
inline constexpr Triangle_id no_triangle = std::numeric_limits<Triangle_id>::max();

// A finite edge of the triangulation with the apexes of the triangles on its two sides.
struct Delaunay_edge {
  // The end with the smaller index.
  Vertex source, target;  // source < target
  // The apex of the triangle left of source -> target, or no_vertex (a hull edge, collinear input).
  Vertex left, right;     // apex of the triangle left / right of source -> target, or no_vertex
};

// A finite triangle: its corners counterclockwise and, for each side i (the edge opposite
// corner i), that edge and the triangle across it.
struct Delaunay_triangle {
  std::array<Vertex, 3> corners;      // counterclockwise
  std::array<Edge_id, 3> sides;       // side i, opposite corners[i]
  std::array<Triangle_id, 3> across;  // across side i; no_triangle on the convex hull
};

// Whether a triangulation also keeps its triangles(): 2n of them at 36 bytes each, for
// the algorithms that walk triangles (Connect2D) and no one else.
enum class Keep_triangles : bool { no, yes };

// Whether all points lie on one line (exact; equal points count as collinear). CGAL
// inserts collinear points one by one into a chain it walks, quadratically (10^5 of them
// took 15 s), so triangulations check first and sort instead.
bool all_collinear(std::span<const Point> points);

// The triangulation of a span of points. It keeps the span, not a copy: the points must
// outlive it. Nothing changes after construction, so threads may share one.
class Delaunay_triangulation {
 public:
  // Throws std::invalid_argument if two points are equal (merge them first, see
  // geometry::PointSet) or a coordinate is not finite.
  explicit Delaunay_triangulation(std::span<const Point> points, Keep_triangles keep = Keep_triangles::no);

  // The input points, as given (the span, not a copy).
  std::span<const Point> points() const { return points_; }
  // The number of points, i.e. of vertices.
  std::size_t size() const { return points_.size(); }
  // Point v of the input.
  const Point& point(Vertex v) const { return points_[v]; }

  // Every finite edge once, in an order fixed by the input (not sorted: builders sort
  // what they output, and sorting 3n edges here would cost a third of the triangulation).
  std::span<const Delaunay_edge> edges() const { return edges_; }

  // The finite triangles, in an order fixed by the input, read from the same walk over
  // CGAL's faces as the edges (where looking sides up by their ends afterwards cost more
  // than the walk). Empty unless kept at construction, and for collinear input.
  std::span<const Delaunay_triangle> triangles() const { return triangles_; }

  // The Delaunay neighbours of v, in the order of their edges in edges() (not sorted).
  std::span<const Vertex> neighbors(Vertex v) const {
    return {neighbors_.data() + first_neighbor_[v], neighbors_.data() + first_neighbor_[v + 1]};
  }

  // The nearest other point, ties to the smaller index; no_vertex if there is none.
  // Exact: the nearest neighbour of a point is always one of its Delaunay neighbours.
  Vertex nearest_neighbor(Vertex v) const;

 private:
  template <class Face_base>
  void triangulate();
  void connect_collinear();
  void index_neighbors();

  std::span<const Point> points_;
  std::vector<Delaunay_edge> edges_;
  std::vector<Delaunay_triangle> triangles_;
  std::vector<std::size_t> first_neighbor_;
  std::vector<Vertex> neighbors_;
};

}  // namespace curvebench::graphs
