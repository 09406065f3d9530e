// A Python function as a curvebench algorithm, and what lets it run in the runner's forked
// worker processes.
//
// The function is added to the registry as a session algorithm
// (algorithms/registry.h's add_session_algorithm), so every verb finds it by name, as it
// finds a built-in one. Its reconstruct call takes the GIL, hands the distinct points to
// Python as a fresh (n, 2) float64 array, calls the package's `invoke` (which calls the
// function and checks its result: curvebench/_algorithms.py) and reads back the edges, and
// the points for one that moves points. A Python exception in the function is carried as
// Python_error; a result that is not edges between its points is bench::Invalid_output,
// as it is for an exec: program.
//
// The runner forks a worker process per job (bench/runner/process_pool.h). A fork copies
// only the thread that forks, so the child's interpreter must be left consistent, as
// os.fork() leaves it: the fork hooks take the GIL and run PyOS_BeforeFork before each fork
// (so no other Python thread is inside the interpreter, or holds the import lock, when the
// memory is copied), then PyOS_AfterFork_Parent, or in the child PyOS_AfterFork_Child, and
// give the GIL back. The calls that run jobs release the GIL while the C++ runs, so the
// parent's other Python threads go on meanwhile.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "algorithms/algorithm.h"

namespace curvebench::python {

// Adds `algorithm` (its reconstruct is set here) as a session algorithm whose call is
// invoke(points, parameters) -> (edges, points or None), `invoke` a Python callable kept
// for the life of the process. Returns the name it was added under. Throws
// std::invalid_argument for a bad or taken name (registry.h).
std::string add_python_algorithm(algorithms::Algorithm algorithm, pybind11::object invoke);

// Makes every fork of the runner's worker processes safe for the interpreter (see above),
// and lets Ctrl-C stop a run that waits on its workers: the runner's interruption check
// raises KeyboardInterrupt (PyErr_CheckSignals) and the running workers are killed.
void install_process_hooks();

// Whether this process is a worker forked by the runner.
bool in_worker_process();

}  // namespace curvebench::python
