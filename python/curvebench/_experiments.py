"""The experiments from Python: run, certify, tightness and hunt, as the command line runs
them, with their results as a pandas DataFrame and their JSON summaries as dicts."""
import contextlib
import json
import pathlib
import subprocess
import sys
import tempfile
import warnings
from typing import NamedTuple, Optional

import numpy as np

from . import _curvebench as _core
from ._algorithms import as_name

# results.csv's columns by type (bench/runner/results_table.h); the rest are text.
_FLAGS = ("exact", "manifold", "true_topology")
_COUNTS = ("job", "n_points", "components", "open_components", "closed_components", "unconnected", "output_points")
_NUMBERS = ("epsilon", "rho", "uniformity", "hausdorff", "rms", "hausdorff_to_curve", "rms_to_curve",
            "hausdorff_from_curve", "rms_from_curve", "normal_deviation", "runtime_ms", "startup_ms")


class RunResult(NamedTuple):
    """What :func:`curvebench.run` gives."""
    results: "pandas.DataFrame"  # noqa: F821  one row per job, results.csv's rows and columns
    summary: Optional["pandas.DataFrame"]  # noqa: F821  summary.csv: per suite, level and algorithm, with 95 % intervals
    counts: dict                 # jobs by status: jobs, resumed, ok, failed, invalid_output, crashed, timeout
    directory: Optional[pathlib.Path]  # the run's directory (out), or None for a temporary one


@contextlib.contextmanager
def _directory(out):
    """``out`` as a Path, or a temporary directory removed afterwards (then None is yielded second)."""
    if out is not None:
        yield pathlib.Path(out), pathlib.Path(out)
        return
    with tempfile.TemporaryDirectory(prefix="curvebench-") as scratch:
        yield pathlib.Path(scratch) / "out", None


def read_results(path):
    """results.csv as a DataFrame: flags as pandas' nullable booleans, counts as nullable
    integers, measures as floats ("inf" read as infinity), the rest as text ("" when empty)."""
    import pandas as pd

    frame = pd.read_csv(path, dtype=str, keep_default_na=False)
    for column in frame.columns:
        if column in _FLAGS:
            frame[column] = frame[column].map({"1": True, "0": False, "": pd.NA}).astype("boolean")
        elif column in _COUNTS:
            frame[column] = pd.array([None if v == "" else int(v) for v in frame[column]], dtype="Int64")
        elif column in _NUMBERS:  # parsed as Python parses them: the shortest text read back exactly
            frame[column] = np.array([float(v) if v else np.nan for v in frame[column]], dtype=np.float64)
    return frame


def _summary(directory):
    """summary.csv of a run, made by the report's own code (bench/report/make_report.py's
    write_summary) in a child interpreter, so that this one's matplotlib backend stays as it
    is; None, with a warning, if that fails (the report needs matplotlib)."""
    import pandas as pd

    summary = directory / "summary.csv"
    if not summary.exists():
        report = pathlib.Path(_core.resource_root()) / "bench" / "report"
        code = ("import pathlib, sys; sys.path.insert(0, sys.argv[1]); import make_report as m; "
                "rows = pathlib.Path(sys.argv[2]); "
                "m.write_summary(m.Run(m.read_rows(rows), m.read_simplifiers(rows.parent)), pathlib.Path(sys.argv[3]))")
        done = subprocess.run([sys.executable, "-c", code, str(report), str(directory / "results.csv"), str(summary)],
                              capture_output=True, text=True)
        if done.returncode != 0:
            last = (done.stderr.strip().splitlines() or ["no message"])[-1]
            warnings.warn(f"curvebench.run: no summary ({sys.executable} {report / 'make_report.py'}: {last})")
            return None
    return pd.read_csv(summary)


def run(suite, algorithms=None, out=None, *, jobs=0, timeout=60.0, pictures=None, resume=False, shard=None,
        report=False, progress=False):
    """See curvebench.run."""
    names = [as_name(a) for a in ([] if algorithms is None else
                                  [algorithms] if isinstance(algorithms, str) or callable(algorithms) else algorithms)]
    if report and out is None:
        raise ValueError("report=True writes report.html into out: name a directory")
    if pictures is None:
        pictures = "some" if out is not None else "none"
    with _directory(out) as (directory, kept):
        counts = _core.run(str(suite), names, directory, _count(jobs, "jobs"), _seconds(timeout, "timeout", zero=True),
                           str(pictures), bool(resume), "" if shard is None else str(shard), bool(report),
                           bool(progress))
        results = read_results(directory / "results.csv")
        summary = _summary(directory)
    return RunResult(results, summary, counts, kept)


def _count(value, what):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
        raise ValueError(f"{what} is a whole number >= 0, not {value!r}")
    return int(value)


def _seconds(value, what, zero=False):
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) or \
            not (value >= 0 if zero else value > 0) or not np.isfinite(value):
        raise ValueError(f"{what} is a number of seconds {'>= 0' if zero else '> 0'}, not {value!r}")
    return float(value)


def _read_points(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # an empty file is no points
        return np.loadtxt(path, ndmin=2, comments="#").reshape(-1, 2).astype(np.float64)


def _read_edges(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return np.loadtxt(path, ndmin=2, dtype=np.int64, comments="#").reshape(-1, 2)


def certify(algorithm, *, curves="fourier", count=100, rho=False, epsilon=None, below_bound=None, seed=0, out=None,
            jobs=0, timeout=60.0, resume=False, shard=None, progress=False):
    """See curvebench.certify."""
    if epsilon is not None and below_bound is not None:
        raise ValueError("epsilon and below_bound: give one, not both")
    with _directory(out) as (directory, kept):
        summary = json.loads(_core.certify(as_name(algorithm), str(curves), _count(count, "count"), bool(rho),
                                           None if epsilon is None else float(epsilon),
                                           None if below_bound is None else float(below_bound), _count(seed, "seed"),
                                           directory, _count(jobs, "jobs"), _seconds(timeout, "timeout", zero=True),
                                           bool(resume), "" if shard is None else str(shard), bool(progress)))
        for case in summary["counterexamples"]:
            case_directory = pathlib.Path(case["path"])
            case["sample"] = {"points": _read_points(case_directory / "points.xy"),
                              "truth": _read_edges(case_directory / "truth.edges")}
            if kept is None:
                case["path"] = case["replay"] = None
        if kept is None:
            summary["results"] = None
    return summary


def tightness(algorithms, *, rho=False, seconds=60.0, curves=0, moves=60, seed=0, out=None):
    """See curvebench.tightness."""
    single = isinstance(algorithms, str) or callable(algorithms)
    records = []
    with _directory(out) as (directory, kept):
        for given in ([algorithms] if single else algorithms):
            name = as_name(given)
            record = json.loads(_core.tightness(name, bool(rho), _seconds(seconds, "seconds"), _count(curves, "curves"),
                                                _count(moves, "moves"), _count(seed, "seed"),
                                                directory / (name + ("-rho" if rho else ""))))
            if "directory" in record:
                case = pathlib.Path(record["directory"])
                record["sample"] = {"points": _read_points(case / "points.xy"), "truth": _read_edges(case / "truth.edges"),
                                    "reconstruction": _read_edges(case / "reconstruction.edges")}
                if kept is None:
                    record["directory"] = None
            records.append(record)
    return records[0] if single else records


def hunt(algorithm, *, seconds=60.0, seed=0, out=None, timeout=10.0, max_findings=1, stop_after=0):
    """See curvebench.hunt."""
    summary = json.loads(_core.hunt(as_name(algorithm), _seconds(seconds, "seconds", zero=True), _count(seed, "seed"),
                                    "" if out is None else str(out),
                                    _seconds(timeout, "timeout"), _count(max_findings, "max_findings"),
                                    _count(stop_after, "stop_after")))
    for finding in summary["findings"]:
        finding["points"] = np.asarray(finding["points"], dtype=np.float64).reshape(-1, 2)
    return summary
