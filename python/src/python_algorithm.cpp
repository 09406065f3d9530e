#include "python_algorithm.h"

#include <pybind11/numpy.h>

#include <cstring>
#include <memory>

#include "algorithms/registry.h"
#include "arrays.h"
#include "bench/runner/external_algorithm.h"
#include "bench/runner/process_pool.h"
#include "errors.h"

namespace curvebench::python {
namespace py = pybind11;
namespace {

bool worker = false;

// What a Python algorithm's reconstruct call holds: the package's `invoke`, and the
// parameters by which it reads the values (their names kept here, as the registry keeps
// its own copy).
struct Python_call {
  PyObject* invoke = nullptr;  // never released: the session algorithm lives as long as the process
  std::vector<std::string> names;
  std::vector<algorithms::Parameter> parameters;  // names viewing `names`
};

// sys.stdout and sys.stderr flushed, errors ignored (the GIL held).
void flush_python_streams() {
  for (const char* stream : {"stdout", "stderr"})
    if (PyObject* file = PySys_GetObject(stream); file && file != Py_None) {
      PyObject* flushed = PyObject_CallMethod(file, "flush", nullptr);
      if (flushed) Py_DECREF(flushed);
      else PyErr_Clear();
    }
}

// The result as `invoke` returns it: (edges, points or None), both checked by it already;
// read here as any other array argument is.
algorithms::Reconstruction read_result(const py::handle& result, std::size_t point_count) {
  if (!py::isinstance<py::tuple>(result) || py::len(result) != 2)
    throw bench::Invalid_output("the algorithm's result is not (edges, points)");
  const auto pair = py::reinterpret_borrow<py::tuple>(result);
  algorithms::Reconstruction reconstruction;
  try {
    if (!pair[1].is_none()) {
      const Point_argument moved(pair[1], "points");
      reconstruction.points.assign(moved.points().begin(), moved.points().end());
      point_count = reconstruction.points.size();
    }
    reconstruction.edges = edge_argument(pair[0], point_count, "edges");
  } catch (const std::invalid_argument& error) {
    throw bench::Invalid_output(error.what());
  }
  return reconstruction;
}

algorithms::Reconstruction call(const Python_call& python, std::span<const algorithms::Point> points,
                                const algorithms::Parameter_values& values) {
  const py::gil_scoped_acquire gil;
  try {
    // A copy: the function may keep the array, and the points are the registry's.
    py::array_t<double> input({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
    if (!points.empty()) std::memcpy(input.mutable_data(), points.data(), points.size() * sizeof(algorithms::Point));
    py::dict given;
    for (const algorithms::Parameter& parameter : python.parameters) {
      const double value = values[parameter];
      if (parameter.type == algorithms::Parameter_type::integer)
        given[py::str(parameter.name.data(), parameter.name.size())] = py::int_(static_cast<long long>(value));
      else
        given[py::str(parameter.name.data(), parameter.name.size())] = py::float_(value);
    }
    const py::object result = py::reinterpret_borrow<py::object>(python.invoke)(input, given);
    if (worker) flush_python_streams();  // a worker leaves by _exit: what the function printed must be out
    return read_result(result, points.size());
  } catch (py::error_already_set& error) {
    if (worker) flush_python_streams();
    if (is_invalid_output(error)) throw bench::Invalid_output(py::str(error.value()));
    throw Python_error(std::move(error));
  }
}

// The GIL state the fork hooks took, given back after the fork (in both processes).
PyGILState_STATE fork_gil;

}  // namespace

std::string add_python_algorithm(algorithms::Algorithm algorithm, py::object invoke) {
  auto python = std::make_shared<Python_call>();
  python->invoke = invoke.release().ptr();
  for (const algorithms::Parameter& parameter : algorithm.parameters) python->names.emplace_back(parameter.name);
  python->parameters = algorithm.parameters;
  for (std::size_t k = 0; k < python->names.size(); ++k) python->parameters[k].name = python->names[k];
  algorithm.reconstruct = [python](std::span<const algorithms::Point> points, const algorithms::Parameter_values& values) {
    return call(*python, points, values);
  };
  try {
    return std::string(algorithms::add_session_algorithm(std::move(algorithm)).name);
  } catch (...) {
    // Not added: nothing calls it. Released with the GIL held (the caller's).
    Py_DECREF(python->invoke);
    python->invoke = nullptr;
    throw;
  }
}

void install_process_hooks() {
  // Ctrl-C while a run waits on its workers: KeyboardInterrupt, the workers killed.
  bench::set_interruption_check([] {
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw Python_error(py::error_already_set());
  });
  bench::set_fork_hooks({
      .before =
          [] {
            fork_gil = PyGILState_Ensure();
            flush_python_streams();  // or the child would write the parent's buffered output again
            PyOS_BeforeFork();
          },
      .after_parent =
          [] {
            PyOS_AfterFork_Parent();
            PyGILState_Release(fork_gil);
          },
      .after_child =
          [] {
            PyOS_AfterFork_Child();
            worker = true;
            PyGILState_Release(fork_gil);
          },
  });
}

bool in_worker_process() { return worker; }

}  // namespace curvebench::python
