#include "graphs/alpha_shape_boundary.h"

#include <cmath>
#include <stdexcept>

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "geometry/exact_sign.h"
#include "graphs/delaunay_triangulation.h"

namespace curvebench::graphs {
namespace {

using Kernel = geometry::Kernel;
using Exact_alpha = CGAL::Tag_true;
using Vertex_base = CGAL::Alpha_shape_vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<Vertex, Kernel>,
                                                    Exact_alpha>;
using Face_base = CGAL::Alpha_shape_face_base_2<Kernel, CGAL::Triangulation_face_base_2<Kernel>, Exact_alpha>;
using Tds = CGAL::Triangulation_data_structure_2<Vertex_base, Face_base>;
using Alpha_shape = CGAL::Alpha_shape_2<CGAL::Delaunay_triangulation_2<Kernel, Tds>, Exact_alpha>;

// On a line the alpha-complex is the chain of consecutive points no farther apart than
// the eraser's diameter 2 sqrt(alpha); CGAL's Alpha_shape_2 only handles dimension 2.
std::vector<Edge> collinear_boundary(const Delaunay_triangulation& chain, double alpha) {
  std::vector<Edge> edges;
  for (const Delaunay_edge& e : chain.edges()) {
    const auto fits = geometry::exact_sign([&]<class NT>(std::type_identity<NT>) {
      return NT(4) * NT(alpha) -
             geometry::squared_length(geometry::difference<NT>(chain.point(e.target), chain.point(e.source)));
    });
    if (fits != CGAL::NEGATIVE) edges.emplace_back(e.source, e.target);
  }
  return edges;
}

}  // namespace

Graph alpha_shape_boundary(std::span<const Point> points, double alpha) {
  if (!std::isfinite(alpha) || alpha < 0)
    throw std::invalid_argument("alpha-shape: alpha must be a finite number >= 0");
  std::vector<std::pair<Point, Vertex>> indexed;
  indexed.reserve(points.size());
  for (Vertex i = 0; i < points.size(); ++i) indexed.emplace_back(points[i], i);

  Alpha_shape shape(indexed.begin(), indexed.end(), alpha, Alpha_shape::GENERAL);
  if (shape.number_of_vertices() != points.size() || shape.dimension() < 2) {
    const Delaunay_triangulation chain(points);  // reports duplicates; collinear otherwise
    return make_graph(points, collinear_boundary(chain, alpha));
  }
  std::vector<Edge> edges;
  for (auto e = shape.alpha_shape_edges_begin(); e != shape.alpha_shape_edges_end(); ++e) {
    const auto& [face, i] = *e;
    edges.emplace_back(face->vertex(Alpha_shape::cw(i))->info(), face->vertex(Alpha_shape::ccw(i))->info());
  }
  return make_graph(points, edges);
}

}  // namespace curvebench::graphs
