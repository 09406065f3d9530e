// The functions of the compiled module curvebench._curvebench, a group per file. The
// package (curvebench/__init__.py) gives them their Pythonic signatures and documents them.
#pragma once

#include <pybind11/pybind11.h>

namespace curvebench::python {

// algorithms(), reconstruct(), the registration of Python algorithms, algorithm files.
void define_algorithms(pybind11::module_& module);
// graph() and graph_kinds().
void define_graphs(pybind11::module_& module);
// sample(), measure(), evaluate().
void define_curves(pybind11::module_& module);
// run(), certify(), tightness(), hunt(), suites() and the resource root.
void define_experiments(pybind11::module_& module);

}  // namespace curvebench::python
