#!/usr/bin/python3
"""What the Python module costs beside the C++ it calls (docs/python.md, "Speed").

    PYTHONPATH=build/python python3 bench/micro/python_speed.py [--repeat N] [--large N]

1. reconstruct on 100 points: the median wall time of curvebench.reconstruct from Python
   (numpy in, numpy out) against the median of the C++ call inside it
   (algorithms::reconstruct, timed by the binding: Reconstruction.runtime), over N calls;
   and, for a second opinion, the time the command line prints for the same call on the
   same points (`curvebench reconstruct`, median of 20 runs; $CURVEBENCH_CLI, else
   build/bench/curvebench).
2. reconstruct on 10^6 points: the same, over a few calls.
3. the `runtime` suite: a Python NN-Crust (examples/python/naive_nn_crust.py's function)
   run by curvebench.run, in the runner's worker processes, against the same file behind
   exec: (a python3 started per job): the median runtime_ms per job, and the wall time
   of each run per job.

Not a test: the figures depend on the machine and its load, which it prints.
"""
import argparse
import importlib.util
import os
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import curvebench

SOURCE = pathlib.Path(__file__).resolve().parents[2]


def load_average():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def reconstruct_overhead(points, algorithm, repeat):
    """(median wall, median C++ call, median of the per-call differences), in seconds."""
    walls, inner = [], []
    for _ in range(repeat):
        start = time.perf_counter()
        r = curvebench.reconstruct(points, algorithm)
        walls.append(time.perf_counter() - start)
        inner.append(r.runtime)
    differences = [w - c for w, c in zip(walls, inner)]
    return statistics.median(walls), statistics.median(inner), statistics.median(differences)


def command_line_milliseconds(points, algorithm, repeat):
    """The median of the times `curvebench reconstruct` prints for the call (ms), or None."""
    program = os.environ.get("CURVEBENCH_CLI", str(SOURCE / "build/bench/curvebench"))
    if not os.access(program, os.X_OK):
        return None
    with tempfile.TemporaryDirectory() as scratch:
        np.savetxt(f"{scratch}/points.xy", points, fmt="%.17g")
        times = []
        for _ in range(repeat):
            done = subprocess.run([program, "reconstruct", "-a", algorithm, "-i", f"{scratch}/points.xy", "-o",
                                   f"{scratch}/edges"], capture_output=True, text=True, check=True)
            times.append(float(re.search(r"([0-9.e+-]+) ms", done.stderr).group(1)))
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2000, help="calls on 100 points (default 2000)")
    parser.add_argument("--large", type=int, default=1_000_000, help="points of the large case (default 10^6)")
    parser.add_argument("--large-repeat", type=int, default=3, help="calls on the large case (default 3)")
    options = parser.parse_args()
    print(f"machine: {os.cpu_count()} cores, load average {load_average()}")

    small = curvebench.sample("fourier:seed=7", uniform=100).points
    for algorithm in ("nn-crust", "hnn-crust", "crust"):
        curvebench.reconstruct(small, algorithm)  # warm: first-use tables
        wall, inner, difference = reconstruct_overhead(small, algorithm, options.repeat)
        cli = command_line_milliseconds(small, algorithm, 20)
        print(f"100 points, {algorithm:9s}: Python call {1e6 * wall:8.1f} us, C++ call {1e6 * inner:8.1f} us, "
              f"overhead {1e6 * difference:5.1f} us (medians of {options.repeat})"
              + ("" if cli is None else f"; the command line's call {1e3 * cli:8.1f} us"))

    large = curvebench.sample("fourier:seed=7", uniform=options.large).points
    for algorithm in ("nn-crust", "hnn-crust"):
        wall, inner, _ = reconstruct_overhead(large, algorithm, options.large_repeat)
        cli = command_line_milliseconds(large, algorithm, options.large_repeat)
        print(f"{options.large} points, {algorithm:9s}: Python call {wall:7.3f} s, C++ call {inner:7.3f} s, "
              f"ratio {wall / inner:.4f} (medians of {options.large_repeat})"
              + ("" if cli is None else f"; the command line's call {cli / 1e3:7.3f} s, ratio {wall / (cli / 1e3):.4f}"))

    spec = importlib.util.spec_from_file_location("naive_nn_crust", SOURCE / "examples/python/naive_nn_crust.py")
    naive = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(naive)
    in_process = curvebench.algorithm(lambda points: sorted(naive.nn_crust(points)), name="naive-nn-crust-python")
    external = f"exec:/usr/bin/python3 {SOURCE}/examples/python/naive_nn_crust.py {{points}} {{edges}}"
    for name, algorithm in (("curvebench.run, Python function", in_process), ("exec: python3 per job", external)):
        start = time.perf_counter()
        frame = curvebench.run("runtime", [algorithm], jobs=1).results
        wall = time.perf_counter() - start
        assert (frame.status == "ok").all(), frame.message.tolist()
        per_job = ", ".join(f"n={n}: {ms:.1f} ms" for n, ms in zip(frame.n_points, frame.runtime_ms))
        print(f"runtime suite, {name:32s}: {per_job}; wall {wall / len(frame):.3f} s per job "
              f"(median runtime_ms {statistics.median(frame.runtime_ms):.1f})")
    print(f"load average after: {load_average()}")


if __name__ == "__main__":
    sys.exit(main())
