"""Python functions as algorithms: in reconstruct (in this process), and in run, certify,
tightness and hunt (in the runner's forked worker processes), where an exception, a
crash, a hang or output that is not edges costs only its own job."""
import faulthandler
import itertools
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest
from scipy.spatial import cKDTree

import curvebench


def nn_crust(points):
    """NN-Crust in ten lines (Dey and Kumar 1999), in floating point: each point joins its
    nearest neighbour and its nearest point on the other side."""
    n = len(points)
    _, near = cKDTree(points).query(points, k=min(n, 12))
    edges = set()
    for p in range(n):
        q = near[p, 1]
        edges.add((min(p, q), max(p, q)))
        half = next((r for r in near[p, 2:] if np.dot(points[r] - points[p], points[q] - points[p]) < 0), None)
        if half is not None:
            edges.add((min(p, half), max(p, half)))
    return sorted(edges)


python_nn_crust = curvebench.algorithm(nn_crust, name="python-nn-crust", epsilon_below=1 / 3,
                                       capabilities={"multiple": "yes", "manifold": "yes"})


def test_a_function_reconstructs_in_process_as_the_built_in_does():
    s = curvebench.sample("fourier:seed=4", epsilon=0.3, safe=True)
    mine = curvebench.reconstruct(s.points, python_nn_crust)
    np.testing.assert_array_equal(mine.edges, curvebench.reconstruct(s.points, "nn-crust").edges)
    assert mine.algorithm == "python-nn-crust"
    # A plain function and a lambda get names of their own; the decorated one still calls through.
    assert curvebench.reconstruct(s.points, nn_crust).algorithm == "python-nn-crust"
    assert python_nn_crust(s.points) == nn_crust(s.points)
    listed = {a["name"]: a for a in curvebench.algorithms()}
    assert listed["python-nn-crust"]["kind"] == "python"
    assert listed["python-nn-crust"]["condition"]["epsilon_below"] == pytest.approx(1 / 3)


def test_parameters_are_declared_checked_and_passed():
    @curvebench.algorithm(parameters={"k": (2, 1, 10), "scale": {"default": 0.5, "minimum": 0, "maximum": 1}})
    def chain(points, k, scale):
        assert isinstance(k, int) and isinstance(scale, float)
        return [(i, i + 1) for i in range(min(k, len(points) - 1))]

    points = np.random.default_rng(0).random((8, 2))
    assert len(curvebench.reconstruct(points, chain).edges) == 2
    assert len(curvebench.reconstruct(points, chain, k=5).edges) == 5
    with pytest.raises(ValueError, match="k"):
        curvebench.reconstruct(points, chain, k=11)
    with pytest.raises(ValueError, match="has no parameter 'j'"):
        curvebench.reconstruct(points, chain, j=1)
    params = {a["name"]: a for a in curvebench.algorithms()}["chain"]["parameters"]
    assert [(p["name"], p["type"], p["default"]) for p in params] == [("k", "integer", 2), ("scale", "real", 0.5)]


def test_names_are_free_and_a_redefinition_rebinds():
    first = curvebench.algorithm(lambda p: [], name="rebound")
    again = curvebench.algorithm(lambda p: [(0, 1)], name="rebound")
    assert again is first and len(curvebench.reconstruct([[0, 0], [1, 0]], "rebound").edges) == 1
    with pytest.raises(ValueError, match="taken"):
        curvebench.algorithm(lambda p: [], name="rebound", epsilon_below=0.5)
    with pytest.raises(ValueError, match="the name is taken"):
        curvebench.algorithm(lambda p: [], name="crust")
    with pytest.raises(ValueError, match="a name is lowercase"):
        curvebench.algorithm(lambda p: [], name="Bad Name")
    a, b = curvebench.algorithm(lambda p: []), curvebench.algorithm(lambda p: [])
    assert a.name != b.name and a.name.startswith("lambda")

    def crust(points):  # a built-in's name: its own is taken, so it gets another
        return []
    assert curvebench.algorithm(crust).name == "crust.2"


def test_edges_may_be_any_sequence_set_or_generator_of_pairs():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    cycle = [(0, 1), (1, 2), (2, 3), (0, 3)]
    for given in (cycle, set(cycle), (e for e in cycle), np.array(cycle, dtype=np.uint8), tuple(cycle)):
        edges = curvebench.reconstruct(square, lambda p, given=given: given).edges
        np.testing.assert_array_equal(edges, sorted(cycle))


def test_a_function_that_moves_points_returns_them():
    def centroids(points):
        moved = (points + np.roll(points, -1, axis=0)) / 2
        return [(i, (i + 1) % len(moved)) for i in range(len(moved))], moved

    points = curvebench.sample("circle:r=1", uniform=12).points
    r = curvebench.reconstruct(points, centroids)
    assert r.moved and r.points.shape == (12, 2) and len(r.edges) == 12


def test_in_process_a_python_exception_comes_back_as_itself():
    def broken(points):
        raise ZeroDivisionError("planted")

    with pytest.raises(ZeroDivisionError, match="planted") as raised:
        curvebench.reconstruct([[0, 0], [1, 1]], broken)
    assert "broken" in str(raised.traceback[-1].name)


@pytest.mark.parametrize("result, message", [
    (None, "returned None"),
    ([0, 1], r"an \(m, 2\) array of indices, not shape \(2,\)"),
    ([[0, 1.5]], "integer indices, not dtype float64"),
    ([[0, 9]], r"edges\[0\]: index 9 out of range \(3 points\)"),
    ([[0, -1]], "index -1 out of range"),
    ([[1, 1]], "a self-loop at 1"),
    ("edges", "integer indices"),
    (([[0, 1]], [[0, np.nan]]), "non-finite"),
])
def test_output_that_is_not_edges_is_invalid_output(result, message):
    with pytest.raises(curvebench.InvalidOutput, match=message):
        curvebench.reconstruct([[0, 0], [1, 0], [0, 1]], lambda p: result)


# The `smoke` suite: two circles, of 33 points (epsilon 0.1) and of 6 (epsilon 0.6).
SMALL = 10


def test_in_run_an_exception_and_a_crash_are_their_jobs_rows():
    @curvebench.algorithm(name="raise-then-abort")
    def planted(points):
        if len(points) < SMALL:
            raise ValueError("planted: too few points")
        faulthandler.disable()  # pytest's handler would print this process's traceback
        os.abort()

    run = curvebench.run("smoke", [planted, "nn-crust"], timeout=5)
    frame = run.results
    assert (frame[frame.algorithm == "nn-crust"].status == "ok").all()
    mine = frame[frame.algorithm == "raise-then-abort"].set_index("n_points")
    assert mine.status.to_dict() == {33: "crashed", 6: "failed"}
    assert mine.message[6] == "ValueError: planted: too few points"
    assert "signal 6" in mine.message[33]
    assert run.counts == {"jobs": 4, "resumed": 0, "ok": 2, "failed": 1, "invalid_output": 0, "crashed": 1,
                          "timeout": 0}


def test_in_run_invalid_output_and_a_hang_are_their_jobs_rows():
    @curvebench.algorithm(name="shape-then-hang")
    def planted(points):
        if len(points) < SMALL:
            return np.zeros(5, dtype=np.int64)
        time.sleep(60)

    start = time.monotonic()
    frame = curvebench.run("smoke", [planted], timeout=2).results.set_index("n_points")
    assert time.monotonic() - start < 30
    assert frame.status.to_dict() == {33: "timeout", 6: "invalid-output"}
    assert "not shape (5,)" in frame.message[6]


def test_what_a_worker_prints_is_printed_once(capfd):
    @curvebench.algorithm(name="printing")
    def printing(points):
        print(f"worker saw {len(points)} points")
        return nn_crust(points)

    print("before the run", end="")  # in this process's buffer while the workers fork
    frame = curvebench.run("smoke", [printing]).results
    out = capfd.readouterr().out
    assert (frame.status == "ok").all()
    assert out.count("before the run") == 1
    assert out.count("worker saw 33 points") == 1 and out.count("worker saw 6 points") == 1


def test_in_run_a_python_nn_crust_equals_the_built_in_job_by_job():
    run = curvebench.run("sampling", [python_nn_crust, "nn-crust"])
    frame = run.results
    mine = frame[frame.algorithm == "python-nn-crust"].reset_index(drop=True)
    theirs = frame[frame.algorithm == "nn-crust"].reset_index(drop=True)
    assert len(mine) == len(theirs) > 0 and (mine.status == "ok").all()
    # Exact wherever the built-in is, at epsilon 0.25 (the theorem: below 1/3) everywhere.
    for column in ("input", "exact", "components", "manifold"):
        assert mine[column].tolist() == theirs[column].tolist(), column
    assert mine[mine.level == "epsilon=0.25"].exact.all()
    summary = run.summary.set_index(["algorithm", "level"])
    assert (summary.exact_low <= summary.exact_pct).all() and (summary.exact_pct <= summary.exact_high).all()
    assert summary.loc[("python-nn-crust", "epsilon=0.25"), "exact_pct"] == 100


def test_a_python_thread_runs_on_while_run_forks_workers():
    ticks = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks[0] += 1

    thread = threading.Thread(target=count)
    thread.start()
    try:
        frame = curvebench.run("smoke", [python_nn_crust]).results
    finally:
        stop.set()
        thread.join()
    assert (frame.status == "ok").all() and ticks[0] > 0


def test_certify_holds_a_python_nn_crust_to_its_theorem():
    summary = curvebench.certify(python_nn_crust, count=12, curves="mixed")
    assert summary["algorithm"] == "python-nn-crust" and summary["bound"] == pytest.approx(1 / 3)
    assert summary["cases"] == 12 and summary["failures"] == 0
    assert summary["passed"] + summary["inconclusive"] == 12


def test_certify_shrinks_a_counterexample_of_a_wrong_claim(tmp_path):
    # A claim NN-Crust cannot keep: epsilon < 1.5. Cases sampled at 0.95 of it fail, and shrink.
    bold = curvebench.algorithm(nn_crust, name="bold-nn-crust", epsilon_below=1.5)
    summary = curvebench.certify(bold, count=4, out=tmp_path / "certify")
    assert summary["failures"] > 0 and len(summary["counterexamples"]) == summary["failures"]
    case = summary["counterexamples"][0]
    points, truth = case["sample"]["points"], case["sample"]["truth"]
    assert case["epsilon"] < 1.5 and points.shape == (case["points"], 2)
    assert len(truth) == len(points)  # a closed curve's ground truth: a cycle
    assert not curvebench.evaluate(points, bold(points), truth)["exact"]
    assert (tmp_path / "certify" / "results.csv").exists() and os.path.exists(case["replay"])


def test_tightness_searches_a_python_algorithm_in_process():
    record = curvebench.tightness(python_nn_crust, curves=2, seconds=30, moves=5)
    assert record["algorithm"] == "python-nn-crust" and record["bound"] == pytest.approx(1 / 3)
    assert record["curves"] == 2
    if "smallest_failure" in record:  # the case it found, as arrays, and the function's edges on it
        sample = record["sample"]
        assert sample["points"].shape == (record["points"], 2) and record["directory"] is None
        np.testing.assert_array_equal(sample["reconstruction"], nn_crust(sample["points"]))


def test_hunt_finds_a_planted_bug_and_shrinks_it(tmp_path):
    def with_planted_bug(points):
        """NN-Crust with a degenerate-case branch for three collinear points, off by one."""
        edges = nn_crust(points) if len(points) >= 2 else []
        if 3 <= len(points) <= 16:
            p = np.asarray(points)
            for i, j, k in itertools.combinations(range(len(p)), 3):
                if (p[j, 0] - p[i, 0]) * (p[k, 1] - p[i, 1]) == (p[j, 1] - p[i, 1]) * (p[k, 0] - p[i, 0]):
                    return edges + [(k, len(p))]  # the bug: one past the last point
        return edges

    summary = curvebench.hunt(with_planted_bug, seconds=30, stop_after=1, out=tmp_path / "hunt")
    assert summary["findings"], summary
    finding = summary["findings"][0]
    assert finding["kind"] == "invalid-output" and "out of range" in finding["message"], finding
    # Shrunk to the smallest input that shows it: three collinear points.
    (ax, ay), (bx, by), (cx, cy) = finding["points"]
    assert (bx - ax) * (cy - ay) == (by - ay) * (cx - ax)
    assert finding["shrink_steps"] > 0 and os.path.exists(finding["replay"])


def test_a_worker_process_knows_it_is_one():
    seen = []

    def where(points):
        seen.append(curvebench._core.in_worker_process())
        if not curvebench._core.in_worker_process():
            raise RuntimeError("not in a worker")
        return nn_crust(points)

    frame = curvebench.run("smoke", [where]).results
    assert (frame.status == "ok").all() and seen == []  # appended in the workers' copies only


def test_ctrl_c_stops_a_run_and_its_workers(tmp_path):
    script = f"""
import os, time, curvebench
def sleeper(points):
    open(os.path.join({str(tmp_path)!r}, str(os.getpid())), "w").close()
    time.sleep(60)
try:
    curvebench.run("smoke", [sleeper], jobs=2)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
"""
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while len(os.listdir(tmp_path)) < 2 and time.monotonic() < deadline:  # both workers started
        time.sleep(0.05)
    start = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=30)
    assert "KeyboardInterrupt" in out and time.monotonic() - start < 5
    for worker in map(int, os.listdir(tmp_path)):
        with pytest.raises(ProcessLookupError):
            os.kill(worker, 0)  # killed by the run, and reaped
