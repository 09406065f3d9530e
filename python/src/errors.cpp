#include "errors.h"

#include "bench/runner/external_algorithm.h"
#include "geometry/io/parse_error.h"

namespace curvebench::python {
namespace py = pybind11;
namespace {

// "TYPE: MESSAGE" of a Python exception (the GIL held).
std::string one_line(const py::error_already_set& error) {
  std::string text = py::str(error.type().attr("__name__"));
  const std::string message = py::str(error.value());
  if (!message.empty()) text += ": " + message;
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

// Kept for the life of the process (a static py::object would be released after the
// interpreter is gone): made by define_errors.
PyObject* unknown_name = nullptr;
PyObject* invalid_output = nullptr;

}  // namespace

Python_error::Python_error(py::error_already_set raised) : std::runtime_error(one_line(raised)), error(std::move(raised)) {}

bool is_invalid_output(const py::error_already_set& error) { return invalid_output && error.matches(invalid_output); }

void define_errors(py::module_& module) {
  // ValueError first, so that str() is the message alone (KeyError's would quote it).
  unknown_name = PyErr_NewExceptionWithDoc(
      "curvebench.UnknownNameError",
      "A name that names nothing curvebench knows: an algorithm, a suite, a graph kind. A ValueError and a KeyError.",
      py::make_tuple(py::handle(PyExc_ValueError), py::handle(PyExc_KeyError)).ptr(), nullptr);
  invalid_output = PyErr_NewExceptionWithDoc(
      "curvebench.InvalidOutput",
      "A Python algorithm returned something that is not edges between its points: a wrong type or shape, an index "
      "out of range, a self-loop. A ValueError.",
      PyExc_ValueError, nullptr);
  if (!unknown_name || !invalid_output) throw py::error_already_set();
  module.add_object("UnknownNameError", py::handle(unknown_name));
  module.add_object("InvalidOutput", py::handle(invalid_output));
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (Python_error& error) {
      error.error.restore();
    } catch (const Unknown_name& error) {
      PyErr_SetString(unknown_name, error.what());
    } catch (const bench::Invalid_output& error) {
      PyErr_SetString(invalid_output, error.what());
    } catch (const geometry::ParseError& error) {
      PyErr_SetString(PyExc_ValueError, error.what());
    }
  });
}

}  // namespace curvebench::python
