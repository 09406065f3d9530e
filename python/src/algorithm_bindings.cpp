// algorithms(), reconstruct() and what makes a Python function an algorithm.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "algorithms/registry.h"
#include "arrays.h"
#include "bench/runner/algorithm_file.h"
#include "bench/runner/external_algorithm.h"
#include "bindings.h"
#include "errors.h"
#include "python_algorithm.h"

namespace curvebench::python {
namespace py = pybind11;
namespace {

const char* word(algorithms::Support support) {
  switch (support) {
    case algorithms::Support::yes: return "yes";
    case algorithms::Support::only: return "only";
    default: return "no";
  }
}

algorithms::Support support(const std::string& text, const std::string& key) {
  if (text == "yes") return algorithms::Support::yes;
  if (text == "no") return algorithms::Support::no;
  if (text == "only") return algorithms::Support::only;
  throw std::invalid_argument("capabilities: " + key + " is yes, no or only, not '" + text + "'");
}

py::object optional_number(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::object(py::none());
}

// One algorithm as algorithms() lists it.
py::dict describe(const algorithms::Algorithm& a, const char* kind) {
  py::list parameters;
  for (const algorithms::Parameter& p : a.parameters) {
    py::dict parameter;
    parameter["name"] = std::string(p.name);
    parameter["type"] = p.type == algorithms::Parameter_type::integer ? "integer" : "real";
    parameter["default"] = p.default_value;
    parameter["minimum"] = p.minimum;
    parameter["maximum"] = p.maximum;
    parameter["meaning"] = std::string(p.meaning);
    parameters.append(parameter);
  }
  const algorithms::Capabilities& c = a.capabilities;
  py::dict capabilities;
  capabilities["non_uniform"] = word(c.non_uniform);
  capabilities["noise"] = word(c.noise);
  capabilities["outliers"] = word(c.outliers);
  capabilities["manifold"] = word(c.manifold);
  capabilities["open"] = word(c.open);
  capabilities["multiple"] = word(c.multiple);
  capabilities["sharp"] = word(c.sharp);
  capabilities["guarantee"] = c.guarantee;
  capabilities["time_complexity"] = std::string(c.time_complexity);
  const algorithms::Sampling_condition& s = a.condition;
  py::dict condition;
  condition["statement"] = std::string(s.statement);
  condition["epsilon_below"] = optional_number(s.epsilon_below);
  condition["rho_below"] = optional_number(s.rho_below);
  condition["corner_angle_above"] = optional_number(s.corner_angle_above);
  condition["uniformity_below"] = optional_number(s.uniformity_below);
  condition["covers_open_curves"] = s.covers_open_curves;
  py::dict entry;
  entry["name"] = std::string(a.name);
  entry["title"] = std::string(a.title);
  entry["reference"] = std::string(a.reference);
  entry["category"] = std::string(a.category);
  entry["kind"] = kind;
  entry["parameters"] = parameters;
  entry["capabilities"] = capabilities;
  entry["condition"] = condition;
  return entry;
}

// Every algorithm a name can pick: the registry's, those of algorithm files, this
// session's Python ones.
py::list list_algorithms() {
  py::list all;
  for (const algorithms::Algorithm& a : algorithms::registry()) all.append(describe(a, "built-in"));
  for (const algorithms::Algorithm* a : bench::find_algorithms({}))
    if (bench::external_declaration(*a)) all.append(describe(*a, "external"));
  for (const algorithms::Algorithm* a : algorithms::session_algorithms()) all.append(describe(*a, "python"));
  return all;
}

// A reconstruction as reconstruct() returns it.
struct Reconstruction_result {
  py::array_t<std::int64_t> edges;
  py::array_t<double> points;
  double runtime = 0;  // seconds
  bool moved = false;  // the points are the algorithm's own, not the input
  std::string algorithm;
};

py::object reconstruct(const py::handle& given_points, const std::string& name, const py::dict& given_values) {
  const Point_argument input(given_points, "points");
  const algorithms::Algorithm* algorithm = bench::find_any_algorithm(name);
  if (!algorithm) throw Unknown_name("unknown algorithm '" + name + "' (see `curvebench list`)");
  algorithms::Parameter_values values;
  for (const auto& [key, value] : given_values) {
    const std::string parameter = py::str(key);
    if (!PyNumber_Check(value.ptr()) || PyComplex_Check(value.ptr()))
      throw std::invalid_argument(std::string(algorithm->name) + ": parameter " + parameter + " is a number, not " +
                                  std::string(py::repr(value)));
    values.set(parameter, value.cast<double>());
  }
  algorithms::Reconstruction result;
  std::chrono::duration<double> elapsed{};
  {
    const py::gil_scoped_release released;
    const auto start = std::chrono::steady_clock::now();
    result = algorithms::reconstruct(*algorithm, input.points(), values);
    elapsed = std::chrono::steady_clock::now() - start;
  }
  Reconstruction_result out;
  out.moved = !result.points.empty();
  out.points = out.moved ? point_array(std::move(result.points)) : py::array_t<double>(input.array());
  out.edges = edge_array(std::move(result.edges));
  out.runtime = elapsed.count();
  out.algorithm = algorithm->name;
  return py::cast(std::move(out));
}

// The registry's description of a Python algorithm from the package's keyword arguments.
std::string add_algorithm(const std::string& name, py::object invoke, const std::string& title,
                          const std::vector<py::dict>& parameters, const py::dict& condition,
                          const std::map<std::string, py::object>& capabilities) {
  algorithms::Algorithm a;
  a.name = name;
  a.title = title;
  a.reference = "a Python function";
  a.category = "Python";
  std::vector<std::string> texts;  // the registry copies them; these live until it has
  texts.reserve(2 * parameters.size() + 1);
  for (const py::dict& p : parameters) {
    algorithms::Parameter parameter;
    parameter.name = texts.emplace_back(py::str(p["name"]));
    parameter.type = py::str(p["type"]).cast<std::string>() == "integer" ? algorithms::Parameter_type::integer
                                                                         : algorithms::Parameter_type::real;
    parameter.default_value = p["default"].cast<double>();
    parameter.minimum = p["minimum"].cast<double>();
    parameter.maximum = p["maximum"].cast<double>();
    parameter.meaning = texts.emplace_back(py::str(p["meaning"]));
    a.parameters.push_back(parameter);
  }
  const auto bound = [&condition](const char* key) -> std::optional<double> {
    if (!condition.contains(key) || condition[key].is_none()) return std::nullopt;
    return condition[key].cast<double>();
  };
  const std::string statement = condition.contains("statement") ? py::str(condition["statement"]) : py::str("none");
  a.condition = {.statement = statement,
                 .epsilon_below = bound("epsilon_below"),
                 .rho_below = bound("rho_below"),
                 .corner_angle_above = std::nullopt,
                 .uniformity_below = bound("uniformity_below"),
                 .covers_open_curves = condition.contains("covers_open_curves") && condition["covers_open_curves"].cast<bool>()};
  algorithms::Capabilities& c = a.capabilities;
  const std::pair<const char*, algorithms::Support*> rows[] = {
      {"non_uniform", &c.non_uniform}, {"noise", &c.noise}, {"outliers", &c.outliers}, {"manifold", &c.manifold},
      {"open", &c.open},               {"multiple", &c.multiple}, {"sharp", &c.sharp}};
  for (const auto& [key, value] : capabilities) {
    const auto row = std::ranges::find_if(rows, [&key](const auto& r) { return key == r.first; });
    if (row != std::end(rows)) *row->second = support(py::str(value), key);
    else if (key == "guarantee") c.guarantee = value.cast<bool>();
    else throw std::invalid_argument("capabilities: no '" + key + "' (non_uniform, noise, outliers, manifold, open, multiple, sharp, guarantee)");
  }
  c.guarantee = c.guarantee || a.condition.epsilon_below || a.condition.rho_below;
  return add_python_algorithm(std::move(a), std::move(invoke));
}

}  // namespace

void define_algorithms(py::module_& m) {
  py::class_<Reconstruction_result>(m, "Reconstruction", "The result of reconstruct().")
      .def_readonly("edges", &Reconstruction_result::edges, "(m, 2) int64: edges (i < j, sorted) between `points`")
      .def_readonly("points", &Reconstruction_result::points,
                    "(n, 2) float64: the input points for an interpolating algorithm, else the algorithm's own")
      .def_readonly("runtime", &Reconstruction_result::runtime, "seconds the algorithm took (the C++ call)")
      .def_readonly("moved", &Reconstruction_result::moved, "whether `points` are the algorithm's own, not the input")
      .def_readonly("algorithm", &Reconstruction_result::algorithm, "the algorithm's name")
      .def("__iter__", [](const Reconstruction_result& r) { return py::iter(py::make_tuple(r.edges, r.points)); })
      .def("__repr__", [](const Reconstruction_result& r) {
        return "<Reconstruction " + r.algorithm + ": " + std::to_string(r.edges.shape(0)) + " edges on " +
               std::to_string(r.points.shape(0)) + " points, " + std::to_string(r.runtime * 1e3) + " ms>";
      });
  m.def("algorithms", &list_algorithms, "Every algorithm a name can pick, as dicts.");
  m.def("reconstruct", &reconstruct, py::arg("points"), py::arg("algorithm"), py::arg("parameters"),
        "reconstruct(points, algorithm, parameters): the registry's reconstruct(), the GIL released.");
  m.def("add_algorithm", &add_algorithm, py::arg("name"), py::arg("invoke"), py::arg("title"), py::arg("parameters"),
        py::arg("condition"), py::arg("capabilities"),
        "Adds a Python algorithm under `name`; invoke(points, parameters) -> (edges, points or None).");
  m.def("algorithm_exists",
        [](const std::string& name) {
          return !name.starts_with(bench::external_prefix) && bench::find_any_algorithm(name) != nullptr;
        },
        py::arg("name"), "Whether `name` names a registered, declared or session algorithm (exec: names are not looked up).");
  m.def("load_algorithm_file", [](const std::string& file) {
        std::vector<std::string> names;
        for (const algorithms::Algorithm* a : bench::load_algorithm_file(file)) names.emplace_back(a->name);
        return names;
      },
      py::arg("file"), "Declares the algorithms of a JSON algorithm file; their names.");
  m.def("in_worker_process", &in_worker_process, "Whether this process is a worker the runner forked.");
}

}  // namespace curvebench::python
