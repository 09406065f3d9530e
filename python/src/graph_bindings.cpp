// graph(): every proximity graph that `curvebench graph` builds.
#include <pybind11/stl.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "arrays.h"
#include "bindings.h"
#include "errors.h"
#include "graphs/proximity_graph.h"

namespace curvebench::python {
namespace py = pybind11;
namespace {

std::string kind_list() {
  std::string list;
  for (const graphs::Proximity_graph& g : graphs::proximity_graphs()) list += (list.empty() ? "" : ", ") + std::string(g.name);
  return list;
}

double real(const py::handle& value, const char* name) {
  if (!PyNumber_Check(value.ptr()) || PyComplex_Check(value.ptr()))
    throw std::invalid_argument(std::string("graph: ") + name + " is a number, not " + std::string(py::repr(value)));
  return value.cast<double>();
}

py::array_t<std::int64_t> graph(const py::handle& given_points, const std::string& kind, const py::dict& given) {
  const Point_argument input(given_points, "points");
  const graphs::Proximity_graph* graph = graphs::find_proximity_graph(kind);
  if (!graph) throw Unknown_name("unknown graph kind '" + kind + "' (" + kind_list() + ")");
  graphs::Proximity_graph_parameters parameters;
  for (const auto& [key, value] : given) {
    const std::string name = py::str(key);
    if (name == "beta") {
      parameters.beta = real(value, "beta");
    } else if (name == "alpha") {
      if (!value.is_none()) parameters.alpha = real(value, "alpha");
    } else if (name == "k") {
      const double k = real(value, "k");
      if (!(k >= 0 && k == std::floor(k) && k < 1e9))
        throw std::invalid_argument("graph: k is a whole number >= 0, not " + std::string(py::repr(value)));
      parameters.k = static_cast<std::size_t>(k);
    } else {
      throw std::invalid_argument("graph: no parameter '" + name + "' (beta, k, alpha)");
    }
  }
  std::vector<geometry::Edge> edges;
  {
    const py::gil_scoped_release released;
    edges = graphs::build_graph(*graph, input.points(), parameters);
  }
  return edge_array(std::move(edges));
}

}  // namespace

void define_graphs(py::module_& m) {
  m.def("graph", &graph, py::arg("points"), py::arg("kind"), py::arg("parameters"),
        "graph(points, kind, parameters): graphs::build_graph, the GIL released.");
  m.def("graph_kinds", [] {
        py::list kinds;
        for (const graphs::Proximity_graph& g : graphs::proximity_graphs())
          kinds.append(py::make_tuple(std::string(g.name), std::string(g.description)));
        return kinds;
      },
      "(name, description) of every proximity graph.");
}

}  // namespace curvebench::python
