"""curvebench.reconstruct against the command line's `reconstruct` on the same files, for
every algorithm, and its handling of arrays and bad input."""
import threading
import time

import numpy as np
import pytest

import curvebench
from files import read_edges, read_points, write_points

BUILT_IN = [a["name"] for a in curvebench.algorithms() if a["kind"] == "built-in"]
# Inputs on which every algorithm runs within a second: a drawing (130 points), and for
# the denoising algorithms a noisy one.
DRAWING = "data/hnncrust/crocodile-conf.p2d"
PARAMETERS = {"beta-skeleton": {"beta": 1.7}, "alpha-shape": {}, "crawl": {}}


def parameter_text(parameters):
    return ",".join(f"{k}={v}" for k, v in parameters.items())


@pytest.mark.parametrize("name", BUILT_IN)
def test_every_algorithm_gives_the_command_lines_edges(name, cli, tmp_path, source):
    file = source / DRAWING
    points = read_points(file)
    parameters = PARAMETERS.get(name, {})
    arguments = ["-p", parameter_text(parameters)] if parameters else []
    cli("reconstruct", "-a", name, "-i", file, "-o", tmp_path / "cli.edges", "--points-out", tmp_path / "cli.xy", "-q",
        *arguments)
    result = curvebench.reconstruct(points, name, **parameters)
    np.testing.assert_array_equal(result.edges, read_edges(tmp_path / "cli.edges"))
    np.testing.assert_array_equal(result.points, read_points(tmp_path / "cli.xy"))
    assert result.edges.dtype == np.int64 and result.points.dtype == np.float64
    assert result.algorithm == name and result.runtime >= 0


def test_an_outlier_filtered_algorithm_and_an_exec_program_equal_the_command_lines(cli, tmp_path, source):
    file = source / DRAWING
    points = read_points(file)
    for name in ("nn-crust+outlier-filter", f"exec:/usr/bin/python3 {source}/examples/python/naive_nn_crust.py "
                                            "{points} {edges}"):
        cli("reconstruct", "-a", name, "-i", file, "-o", tmp_path / "cli.edges", "--points-out", tmp_path / "cli.xy", "-q")
        result = curvebench.reconstruct(points, name)
        np.testing.assert_array_equal(result.edges, read_edges(tmp_path / "cli.edges"))
        np.testing.assert_array_equal(result.points, read_points(tmp_path / "cli.xy"))


def test_a_float64_c_contiguous_array_is_read_in_place_and_others_are_converted():
    points = curvebench.sample("circle:r=1", uniform=50).points
    assert curvebench.reconstruct(points, "nn-crust").points is points
    fortran = np.asfortranarray(points)
    as_list = points.tolist()
    expected = curvebench.reconstruct(points, "nn-crust").edges
    np.testing.assert_array_equal(curvebench.reconstruct(fortran, "nn-crust").edges, expected)
    np.testing.assert_array_equal(curvebench.reconstruct(as_list, "nn-crust").edges, expected)
    integers = np.array([[0, 0], [10, 0], [10, 10], [0, 10]])
    np.testing.assert_array_equal(curvebench.reconstruct(integers, "nn-crust").edges,
                                  curvebench.reconstruct(integers.astype(float), "nn-crust").edges)


def test_duplicates_get_no_edges_and_edges_unpack():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], dtype=float)
    edges, points = curvebench.reconstruct(square, "crust")
    assert 4 not in edges
    assert points.shape == (5, 2)


def test_no_points_give_no_edges_as_an_empty_file_does():
    r = curvebench.reconstruct(np.empty((0, 2)), "nn-crust")
    assert r.edges.shape == (0, 2)


def test_the_gil_is_released_while_the_cpp_runs():
    points = curvebench.sample("fourier:seed=1", uniform=200000).points
    ticks = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks[0] += 1
            time.sleep(0)

    thread = threading.Thread(target=count)
    thread.start()
    try:
        before = ticks[0]
        result = curvebench.reconstruct(points, "nn-crust")
        during = ticks[0] - before
    finally:
        stop.set()
        thread.join()
    assert result.runtime > 0.05
    # Held, the GIL would let the thread tick only around the call: a few times at most.
    assert during > 100


def test_bad_input_raises_the_command_lines_messages(cli, tmp_path):
    points = np.random.default_rng(1).random((10, 2))
    write_points(tmp_path / "p.xy", points)

    def cli_message(*arguments):
        done = cli("reconstruct", "-i", tmp_path / "p.xy", "-o", tmp_path / "e", *arguments, check=False)
        assert done.returncode != 0
        return done.stderr.strip().removeprefix("curvebench: ")

    with pytest.raises(ValueError) as raised:
        curvebench.reconstruct(points, "nn-crust", foo=1)
    assert str(raised.value) == cli_message("-a", "nn-crust", "-p", "foo=1")
    with pytest.raises(ValueError) as raised:
        curvebench.reconstruct(points, "beta-skeleton", beta=0.5)
    assert str(raised.value) == cli_message("-a", "beta-skeleton", "-p", "beta=0.5")
    with pytest.raises(KeyError, match="unknown algorithm 'no-such'"):
        curvebench.reconstruct(points, "no-such")
    with pytest.raises(ValueError, match="unknown algorithm 'no-such'"):  # both a KeyError and a ValueError
        curvebench.reconstruct(points, "no-such")
    with pytest.raises(ValueError, match="exec: the command needs"):
        curvebench.reconstruct(points, "exec:true")
    with pytest.raises(ValueError, match="parameter beta is a number"):
        curvebench.reconstruct(points, "beta-skeleton", beta="big")
    for bad, message in (([[0.0, np.nan]], "point 0 has a non-finite"), ([[np.inf, 0.0]], "point 0 has a non-finite"),
                         (np.zeros((3, 3)), r"an \(n, 2\) array"), (np.zeros(6), r"not shape \(6,\)"),
                         (np.zeros((2, 2), dtype=complex), "real coordinates"), ([["a", "b"]], "real coordinates"),
                         ([[1, 2], [3]], "not an array of numbers"), (np.array([]), r"not shape \(0,\)")):
        with pytest.raises(ValueError, match=message):
            curvebench.reconstruct(bad, "nn-crust")


def test_algorithms_lists_names_parameters_conditions_and_capabilities(cli):
    listed = {a["name"]: a for a in curvebench.algorithms()}
    names = cli("list", "algorithms", "--names").stdout.split()
    assert [n for n in listed if listed[n]["kind"] == "built-in"] == names
    nn = listed["nn-crust"]
    assert nn["condition"]["epsilon_below"] == pytest.approx(1 / 3)
    assert nn["capabilities"]["manifold"] == "yes" and nn["capabilities"]["guarantee"] is True
    beta = listed["beta-skeleton"]["parameters"][0]
    assert (beta["name"], beta["minimum"], beta["maximum"]) == ("beta", 1, 1e6)
