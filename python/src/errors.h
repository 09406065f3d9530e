// How the bindings report errors to Python. Every C++ exception becomes a Python one, with
// the library's message, which is the command line's: std::invalid_argument (a bad value,
// a bad parameter) ValueError; a name that names nothing curvebench.UnknownNameError (a
// KeyError and a ValueError); a file's geometry::ParseError ValueError; a Python
// algorithm's bad output curvebench.InvalidOutput (a ValueError); an exception raised by
// a Python algorithm itself, the same exception again.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

namespace curvebench::python {

// A name (algorithm, suite, graph kind) that names nothing: UnknownNameError in Python.
struct Unknown_name : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// An exception raised by a Python algorithm, carried through the C++ that called it. what()
// is one line, "TYPE: MESSAGE", as a job's row records it; the binding that called into
// C++ raises the original exception again, traceback and all.
struct Python_error : std::runtime_error {
  // Takes the exception the Python call raised (the GIL held).
  explicit Python_error(pybind11::error_already_set error);
  pybind11::error_already_set error;  // the original; safe to destroy without the GIL
};

// Whether `error` is a curvebench.InvalidOutput (the GIL held).
bool is_invalid_output(const pybind11::error_already_set& error);

// Registers UnknownNameError, InvalidOutput and the translations above in `module`.
void define_errors(pybind11::module_& module);

}  // namespace curvebench::python
