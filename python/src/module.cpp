// curvebench._curvebench: the compiled half of the Python module `curvebench`
// (docs/python.md). Thin bindings over the libraries' own calls; the package around it
// (curvebench/__init__.py) gives them their Pythonic names, defaults and documents.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "errors.h"
#include "python_algorithm.h"

PYBIND11_MODULE(_curvebench, m) {
  m.doc() = "curvebench's compiled bindings; use the package `curvebench`.";
  curvebench::python::define_errors(m);
  curvebench::python::define_algorithms(m);
  curvebench::python::define_graphs(m);
  curvebench::python::define_curves(m);
  curvebench::python::define_experiments(m);
  curvebench::python::install_process_hooks();
}
