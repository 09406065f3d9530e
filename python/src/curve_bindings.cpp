// sample(), measure() and evaluate(): curves, their samplings and the benchmark's metrics.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "arrays.h"
#include "bench/runner/curve_sampling.h"
#include "bench/runner/evaluation_report.h"
#include "bench/runner/sampling_report.h"
#include "bindings.h"
#include "geometry/curves/curve_spec.h"
#include "geometry/sampling/sampling.h"

namespace curvebench::python {
namespace py = pybind11;
namespace {

py::dict sample(const std::string& curve, const bench::Sampling_request& request) {
  geometry::Sample s;
  {
    const py::gil_scoped_release released;
    const geometry::Local_feature_size lfs(geometry::make_curve(curve));
    s = bench::sample_curve(lfs, request);
  }
  const std::size_t n = s.size();
  py::array_t<double> lfs(static_cast<py::ssize_t>(n)), parameter(static_cast<py::ssize_t>(n));
  py::array_t<std::int64_t> component(static_cast<py::ssize_t>(n));
  py::array_t<bool> outlier(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    lfs.mutable_at(i) = s.lfs[i];
    parameter.mutable_at(i) = s.locations[i].parameter;
    const bool on_curve = s.locations[i].component != geometry::Curve_location::no_component;
    component.mutable_at(i) = on_curve ? static_cast<std::int64_t>(s.locations[i].component) : -1;
    outlier.mutable_at(i) = s.labels[i] == geometry::Sample_label::outlier;
  }
  py::dict out;
  out["points"] = point_array(std::move(s.points));
  out["edges"] = edge_array(std::move(s.edges));
  out["lfs"] = lfs;
  out["outlier"] = outlier;
  out["component"] = component;
  out["parameter"] = parameter;
  out["minimum_lfs"] = s.minimum_lfs;
  out["floored"] = py::array_t<std::int64_t>(py::cast(std::vector<std::int64_t>(s.floored.begin(), s.floored.end())));
  return out;
}

std::string measure(const std::string& curve, const py::handle& given_points, const py::handle& given_edges,
                    std::optional<double> minimum_lfs) {
  const Point_argument input(given_points, "points");
  std::vector<geometry::Edge> edges;
  if (!given_edges.is_none()) edges = edge_argument(given_edges, input.points().size(), "edges");
  const py::gil_scoped_release released;
  const geometry::Local_feature_size lfs(geometry::make_curve(curve));
  geometry::Sample s = bench::located_sample(lfs, {input.points().begin(), input.points().end()}, std::move(edges));
  s.minimum_lfs = minimum_lfs.value_or(geometry::default_minimum_lfs(lfs));
  return bench::measure_report_json(lfs, s, given_edges.is_none() ? "" : "edges");
}

std::string evaluate(const py::handle& given_points, const py::handle& given_edges, const py::handle& given_truth,
                     const std::string& curve) {
  const Point_argument input(given_points, "points");
  const std::vector<geometry::Edge> edges = edge_argument(given_edges, input.points().size(), "edges");
  const std::vector<geometry::Edge> truth = edge_argument(given_truth, input.points().size(), "truth");
  const py::gil_scoped_release released;
  return bench::evaluation_report_json(input.points(), edges, truth, curve);
}

}  // namespace

void define_curves(py::module_& m) {
  py::class_<bench::Sampling_request>(m, "SamplingRequest", "bench::Sampling_request: what `curvebench sample` draws.")
      .def(py::init<>())
      .def_readwrite("epsilon", &bench::Sampling_request::epsilon)
      .def_readwrite("rho", &bench::Sampling_request::rho)
      .def_readwrite("uniform", &bench::Sampling_request::uniform)
      .def_readwrite("random", &bench::Sampling_request::random)
      .def_readwrite("safe", &bench::Sampling_request::safe)
      .def_readwrite("crossing_samples", &bench::Sampling_request::crossing_samples)
      .def_readwrite("minimum_lfs", &bench::Sampling_request::minimum_lfs)
      .def_readwrite("uniform_noise", &bench::Sampling_request::uniform_noise)
      .def_readwrite("lfs_noise", &bench::Sampling_request::lfs_noise)
      .def_readwrite("outliers", &bench::Sampling_request::outliers)
      .def_readwrite("seed", &bench::Sampling_request::seed);
  m.def("sample", &sample, py::arg("curve"), py::arg("request"),
        "sample(curve, request): the sample's arrays, as a dict; the GIL released.");
  m.def("measure", &measure, py::arg("curve"), py::arg("points"), py::arg("edges"), py::arg("minimum_lfs"),
        "measure(curve, points, edges, minimum_lfs): `curvebench measure`'s JSON.");
  m.def("evaluate", &evaluate, py::arg("points"), py::arg("edges"), py::arg("truth"), py::arg("curve"),
        "evaluate(points, edges, truth, curve): `curvebench evaluate`'s JSON.");
}

}  // namespace curvebench::python
