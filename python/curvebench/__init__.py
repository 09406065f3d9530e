"""curvebench from Python: planar curve reconstruction on exact geometry.

Point sets are (n, 2) float64 numpy arrays, edge sets (m, 2) int64 arrays of indices into
them. Every function calls the library the ``curvebench`` command line calls, with the
same results and the same error messages; the C++ runs with the GIL released.

    >>> import curvebench
    >>> s = curvebench.sample("circle:r=1", epsilon=0.3, safe=True)
    >>> r = curvebench.reconstruct(s.points, "nn-crust")
    >>> curvebench.evaluate(s.points, r.edges, s.edges)["exact"]
    True

A Python function ``f(points) -> edges`` (or ``-> (edges, points)``) stands wherever an
algorithm's name does: reconstruct, run, certify, tightness and hunt. The runner calls it
in its forked worker processes, so a crash, a hang or an exception costs that job only. docs/python.md has the whole story.
"""
import json as _json
import math as _math
import numbers as _numbers
import os as _os

from . import _algorithms, _experiments, _paths, _plot
from . import _curvebench as _core
from ._algorithms import Algorithm, algorithm
from ._curvebench import InvalidOutput, Reconstruction, UnknownNameError
from ._experiments import RunResult

__version__ = _paths.version
__all__ = [
    "Algorithm", "InvalidOutput", "Reconstruction", "RunResult", "Sample", "UnknownNameError",
    "algorithm", "algorithms", "certify", "evaluate", "graph", "graph_kinds", "hunt", "load_algorithm_file",
    "measure", "plot", "reconstruct", "run", "sample", "suites", "tightness",
]


def _choose_resource_root():
    """The bundled data and report scripts: share/curvebench beside an installed package,
    else what the module was built against."""
    installed = _os.path.normpath(_os.path.join(_os.path.dirname(_os.path.abspath(__file__)),
                                                _paths.installed_resources))
    _core.set_resource_root(installed if _os.path.isdir(_os.path.join(installed, "data"))
                            else _paths.built_resources)


_choose_resource_root()


def algorithms():
    """Every algorithm a name can pick, as a list of dicts.

    Each has ``name``, ``title``, ``reference``, ``category``, ``kind`` ("built-in",
    "external" for one of an algorithm file, "python" for one of this session),
    ``parameters`` (each: ``name``, ``type`` "real" or "integer", ``default``, ``minimum``,
    ``maximum``, ``meaning``), ``capabilities`` (the survey's Table 1 row: ``non_uniform``,
    ``noise``, ``outliers``, ``manifold``, ``open``, ``multiple``, ``sharp`` as "yes", "no"
    or "only", ``guarantee``, ``time_complexity``), ``condition`` (the proven sampling
    condition: ``statement``, ``epsilon_below``, ``rho_below``, ``corner_angle_above``,
    ``uniformity_below``, ``covers_open_curves``).

    >>> [a["name"] for a in curvebench.algorithms()][:3]
    ['alpha-shape', 'beta-skeleton', 'emst']
    """
    return _core.algorithms()


def reconstruct(points, algorithm="hnn-crust", **parameters):
    """Reconstructs a curve from ``points`` with one algorithm: ``curvebench reconstruct``.

    ``points``: any (n, 2) array-like of real numbers, read in place when it is a
    C-contiguous float64 array. ``algorithm``: a name (``curvebench.algorithms()``,
    ``NAME+outlier-filter``, ``exec:COMMAND``, a name from an algorithm file) or a Python
    function (see :func:`algorithm`). ``parameters``: the algorithm's, by name, each
    range-checked.

    Exact duplicates are merged into their first occurrence, which alone gets edges. Returns a
    :class:`Reconstruction`: ``edges`` (m, 2) int64, sorted, i < j; ``points``, the input
    points (the array given, when it needed no conversion) for an interpolating algorithm,
    else the algorithm's own points (``moved``); ``runtime`` in seconds. Raises ValueError
    for NaN, infinity or a wrong shape or type, and for a bad parameter;
    UnknownNameError (a KeyError) for an unknown algorithm.

    >>> r = curvebench.reconstruct(points, "beta-skeleton", beta=1.7)
    >>> edges, points = r
    """
    if not isinstance(algorithm, str):
        algorithm = _algorithms.as_name(algorithm)
    return _core.reconstruct(points, algorithm, parameters)


def graph(points, kind, **parameters):
    """A proximity graph of ``points``, as ``curvebench graph KIND`` builds it: its edges, (m, 2) int64.

    ``kind``: one of :func:`graph_kinds` (delaunay, emst, rng, gabriel, beta-lune,
    beta-circle, sig, sigdt, knn, alpha). ``parameters``: ``beta`` (beta-lune and
    beta-circle, default 1.5), ``k`` (knn, default 2), ``alpha`` (alpha, the squared radius;
    default the smallest alpha whose alpha-complex contains the EMST). Exact duplicates are
    merged into their first occurrence, which alone gets edges.

    >>> curvebench.graph(points, "gabriel")
    """
    return _core.graph(points, kind, parameters)


def graph_kinds():
    """(name, description) of every proximity graph :func:`graph` builds."""
    return _core.graph_kinds()


def suites():
    """(name, description) of every benchmark suite :func:`run` runs."""
    return _core.suites()


def load_algorithm_file(path):
    """Declares the external algorithms of a JSON algorithm file (``--algorithm-file``,
    docs/own-algorithm.md), so that every function finds them by name; returns their names."""
    return _core.load_algorithm_file(_os.fspath(path))


class Sample:
    """A sampling of a curve with its ground truth, as :func:`sample` draws it.

    ``points`` (n, 2) float64, each component's points in order along it, outliers last;
    ``edges`` (m, 2) int64, the ground truth; ``lfs`` (n,) the local feature size at the
    curve point each sample was drawn from (NaN for an outlier); ``labels`` (n,) "curve" or
    "outlier"; ``outlier`` (n,) bool; ``component`` (n,) int64 and ``parameter`` (n,)
    float64, where on the curve each point was drawn (-1 and NaN for an outlier);
    ``minimum_lfs``, the lfs floor the sampler used; ``floored``, the points where lfs was
    below it; ``curve``, the spec."""

    __slots__ = ("curve", "points", "edges", "lfs", "labels", "outlier", "component", "parameter", "minimum_lfs",
                 "floored")

    def __init__(self, curve, arrays):
        import numpy as np

        self.curve = curve
        for key, value in arrays.items():
            setattr(self, key, value)
        self.labels = np.where(self.outlier, "outlier", "curve")

    def __len__(self):
        return len(self.points)

    def __repr__(self):
        return f"<Sample of {self.curve}: {len(self.points)} points, {len(self.edges)} edges>"


def sample(curve, epsilon=None, rho=None, uniform=None, random=None, *, safe=False, crossing_samples=False,
           minimum_lfs=None, uniform_noise=None, lfs_noise=None, outliers=None, seed=0):
    """Samples a curve, as ``curvebench sample`` does: a :class:`Sample` (points, ground truth, lfs, labels).

    ``curve``: a curve spec (``circle:r=1``, ``ellipse:a=2,b=1``, ``fourier:seed=7``,
    ``svg:FILE``, ``glyph:g``, ...). Exactly one sampler: ``epsilon`` (the survey's greedy
    walk; ``safe=True`` guarantees the measured epsilon stays below it), ``rho``
    (HNN-Crust's rho-sampling; ``safe`` likewise), ``uniform`` (n points at equal arc-length
    steps) or ``random`` (n points uniform in arc length). Then optionally a sample on every
    crossing (``crossing_samples``), ``uniform_noise`` (extent x bounding-box diagonal),
    ``lfs_noise`` (along the normal, x lfs), ``outliers`` (percent), each drawn from its own
    stream of ``seed``. ``minimum_lfs``: the lfs floor near sharp points (default 1e-3 of the
    bounding-box diagonal).

    >>> s = curvebench.sample("fourier:seed=3", epsilon=0.3, safe=True, lfs_noise=0.1, seed=1)
    """
    request = _core.SamplingRequest()
    for key, value in (("epsilon", epsilon), ("rho", rho), ("minimum_lfs", minimum_lfs),
                       ("uniform_noise", uniform_noise), ("lfs_noise", lfs_noise), ("outliers", outliers)):
        if value is not None:
            setattr(request, key, _real(value, key))
    for key, value in (("uniform", uniform), ("random", random)):
        if value is not None:
            setattr(request, key, _whole(value, key))
    request.safe, request.crossing_samples, request.seed = bool(safe), bool(crossing_samples), _whole(seed, "seed")
    return Sample(curve, _core.sample(str(curve), request))


def measure(curve, points, edges=None, *, minimum_lfs=None):
    """Measures a sampling of a known curve, as ``curvebench measure`` does: a dict.

    ``epsilon`` (sup over the curve of the distance to the nearest point / lfs) and
    ``epsilon_at`` (``component``, ``parameter``: where it is attained); ``rho`` (HNN-Crust's,
    over the ground-truth ``edges``) and ``rho_edge``; ``uniformity`` (the longer / shorter
    ground-truth edge at a point) and ``uniformity_at_point``; ``minimum_lfs``, the lfs floor
    (default 1e-3 of the bounding-box diagonal; 0 measures the true ratios). Without edges,
    rho is 0 and uniformity 1. An infinite measure is ``inf``.

    >>> curvebench.measure("circle:r=1", s.points, s.edges)["epsilon"]
    """
    report = _json.loads(_core.measure(str(curve), points, edges,
                                       None if minimum_lfs is None else _real(minimum_lfs, "minimum_lfs", zero=True)))
    for key in ("epsilon", "rho", "uniformity"):  # JSON has no infinity: null stands for it
        if report[key] is None:
            report[key] = float("inf")
    return report


def evaluate(points, edges, truth, curve=None):
    """Scores a reconstruction on ``points`` against the ground truth, as ``curvebench evaluate`` does: a dict.

    ``exact`` (the edge set is the truth's), ``hausdorff`` and ``rms`` (to the truth, or to
    ``curve``, a curve spec, when given), ``diagonal`` (of the original's bounding box: divide
    by it for results.csv's units), ``normal_deviation`` (degrees), ``manifold``,
    ``max_degree``, ``components``, ``open_components``, ``closed_components``,
    ``unconnected``, and the counts ``points``, ``edges``, ``truth_edges``. An infinite
    distance is ``inf``, one that cannot be measured None.
    """
    report = _json.loads(_core.evaluate(points, edges, truth, "" if curve is None else str(curve)))
    for key, value in report.items():
        if value == "inf":
            report[key] = float("inf")
    return report


def run(suite, algorithms=None, out=None, *, jobs=0, timeout=60.0, pictures=None, resume=False, shard=None,
        report=False, progress=False):
    """Runs a benchmark suite, as ``curvebench run SUITE`` does: a :class:`RunResult`.

    ``algorithms``: names or Python functions (all registered and declared ones when None),
    each run on every input of the suite (:func:`suites`), each job in a worker process of
    its own under ``timeout`` seconds. ``out``: the run's directory (results.csv,
    results.json, pictures, with ``report=True`` report.html); None runs in a temporary
    directory, removed afterwards. ``pictures``: some, all, failures or none (default: some
    with ``out``, none without). ``jobs``: worker processes (0: one per core); ``shard``:
    "K/N"; ``resume``: continue an interrupted run in ``out``.

    Returns ``results`` (a pandas DataFrame: results.csv's rows and columns), ``summary``
    (summary.csv, made by the report's code: per suite, level and algorithm the exact and
    true-topology shares with their Wilson 95 % intervals, RMS and Hausdorff means with their
    Student-t 95 % intervals, mean runtime; None, with a warning, where that code cannot run),
    ``counts`` (jobs by status) and ``directory``.

    >>> r = curvebench.run("sampling", ["nn-crust", my_function])
    >>> r.results.groupby("algorithm").exact.mean()
    """
    return _experiments.run(suite, algorithms, out, jobs=jobs, timeout=timeout, pictures=pictures, resume=resume,
                            shard=shard, report=report, progress=progress)


def certify(algorithm, *, curves="fourier", count=100, rho=False, epsilon=None, below_bound=None, seed=0, out=None,
            jobs=0, timeout=60.0, resume=False, shard=None, progress=False):
    """Checks an algorithm's sampling-condition theorem, as ``curvebench certify --json`` does: its summary, a dict.

    The algorithm (a name, or a Python function made with :func:`algorithm` with a claimed
    ``epsilon_below`` or ``rho_below``) runs on ``count`` generated ``curves`` (fourier,
    multi, nested, rounded, open, mixed, svg, glyphs) sampled at ``epsilon`` (or, with
    ``rho=True``, that rho), else at ``below_bound`` (default 0.95) of its bound. The dict has
    algorithm, bound, measure, requested_level, curves, seed, cases, passed, failures,
    inconclusive, hypothesis_violations and counterexamples: the first five failures,
    shrunk, each with its input (the input name that makes it again), points (their count),
    the measured value, ``sample`` (``points`` and ``truth``, the ground-truth edges, as
    arrays) and, with ``out``, the path of its directory and replay.sh. ``out`` is written
    anew unless ``resume``, as the command does.
    """
    return _experiments.certify(algorithm, curves=curves, count=count, rho=rho, epsilon=epsilon,
                                below_bound=below_bound, seed=seed, out=out, jobs=jobs, timeout=timeout,
                                resume=resume, shard=shard, progress=progress)


def tightness(algorithms, *, rho=False, seconds=60.0, curves=0, moves=60, seed=0, out=None):
    """Searches for the failing sampling of smallest measured epsilon (rho), as ``curvebench tightness --json``.

    One algorithm gives one record (a dict), a list of them a list. A record has algorithm,
    bound, largest_passed, curves, failing_curves, evaluations and seconds; with a failing case
    also measure, smallest_failure, ratio (to the bound), curve, points (their count), level,
    samples_added, moves_kept, error, the case itself as ``sample`` (``points``, ``truth`` and
    the algorithm's ``reconstruction``, as arrays) and, with ``out``, its directory. ``curves`` stops after that many curves (0: search for
    ``seconds``). The algorithm runs in this process.
    """
    return _experiments.tightness(algorithms, rho=rho, seconds=seconds, curves=curves, moves=moves, seed=seed,
                                  out=out)


def hunt(algorithm, *, seconds=60.0, seed=0, out=None, timeout=10.0, max_findings=1, stop_after=0):
    """Searches an algorithm for defects, as ``curvebench hunt --json`` does: its summary, a dict.

    Crashes, hangs, invalid output, runs that differ, broken laws (order, scale, mirror) and
    inexact results under the algorithm's own sampling condition, each shrunk. The dict has
    algorithm, seed, cases, seconds and findings, each with kind, message, points (the shrunk
    input, an array), shrink_steps and replay (with ``out``: each finding written to
    out/KIND-N/). ``timeout``: seconds per run before it counts as a hang; ``stop_after``:
    stop after that many findings (0: search for ``seconds``).
    """
    return _experiments.hunt(algorithm, seconds=seconds, seed=seed, out=out, timeout=timeout,
                             max_findings=max_findings, stop_after=stop_after)


def plot(points, edges, truth=None, ax=None, *, title=None, point_size=6.0):
    """Draws a reconstruction with matplotlib; returns the Axes.

    With ``truth``, edges of the ground truth found are blue, wrong edges red and missing ones
    dashed orange (as a run's pictures); without, every edge is blue. ``ax``: the Axes to
    draw on (default: a new figure's).
    """
    return _plot.plot(points, edges, truth, ax, title=title, point_size=point_size)


def _real(value, what, zero=False):
    """``value`` as a finite float (>= 0 with ``zero``), or ValueError naming ``what``."""
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise ValueError(f"{what} is a number, not {value!r}")
    if not _math.isfinite(value) or (zero and value < 0):
        raise ValueError(f"{what} is a finite number{' >= 0' if zero else ''}, not {value!r}")
    return float(value)


def _whole(value, what):
    """``value`` as an int >= 0, or ValueError naming ``what``."""
    if isinstance(value, bool) or not isinstance(value, _numbers.Integral) or value < 0:
        raise ValueError(f"{what} is a whole number >= 0, not {value!r}")
    return int(value)
