#include "graphs/alpha_shape_boundary.h"

#include <cmath>
#include <stdexcept>

#include "geometry/exact_sign.h"

namespace curvebench::graphs {
namespace {

using geometry::cross, geometry::difference, geometry::exact_sign, geometry::squared_length;

// Squared circumradius of (a, b, c) <= alpha, for a proper triangle: with u = b - a,
// v = c - a, R^2 = |u|^2 |v|^2 |u - v|^2 / (4 (u x v)^2).
bool triangle_in_complex(const Point& a, const Point& b, const Point& c, double alpha) {
  return exact_sign([&]<class NT>(std::type_identity<NT>) {
           const auto u = difference<NT>(b, a), v = difference<NT>(c, a);
           const NT area2 = cross(u, v);
           return NT(4) * NT(alpha) * area2 * area2 -
                  squared_length(u) * squared_length(v) * squared_length(difference<NT>(c, b));
         }) != CGAL::NEGATIVE;
}

}  // namespace

Graph alpha_shape_boundary(const Delaunay_triangulation& dt, double alpha) {
  if (!std::isfinite(alpha) || alpha < 0)
    throw std::invalid_argument("alpha-shape: alpha must be a finite number >= 0");
  std::vector<Edge> edges;
  for (const Delaunay_edge& e : dt.edges()) {
    const Point &p = dt.point(e.source), &q = dt.point(e.target);
    int triangles = 0;
    bool attached = false;  // a point strictly inside the diametral circle of pq
    for (const Vertex apex : {e.left, e.right}) {
      if (apex == no_vertex) continue;
      triangles += triangle_in_complex(p, q, dt.point(apex), alpha);
      attached = attached || CGAL::side_of_bounded_circle(p, q, dt.point(apex)) == CGAL::ON_BOUNDED_SIDE;
    }
    const bool singular = triangles == 0 && !attached && exact_sign([&]<class NT>(std::type_identity<NT>) {
                            return NT(4) * NT(alpha) - squared_length(difference<NT>(q, p));
                          }) != CGAL::NEGATIVE;
    if (triangles == 1 || singular) edges.emplace_back(e.source, e.target);
  }
  return make_graph(dt.points(), edges);
}

Graph alpha_shape_boundary(std::span<const Point> points, double alpha) {
  return alpha_shape_boundary(Delaunay_triangulation(points), alpha);
}

}  // namespace curvebench::graphs
