"""sample, measure and evaluate: against each other, against closed forms on the circle,
and against the command line's `sample`, `measure` and `evaluate` on the same files."""
import json
import math

import numpy as np
import pytest

import curvebench
from files import read_edges, read_points, write_edges, write_points


@pytest.mark.parametrize("n", [8, 20, 64])
def test_a_uniform_circle_sampling_measures_its_closed_forms(n):
    # lfs is the radius on a circle: n equal steps give epsilon 2 sin(pi / 2n) (an arc's
    # middle to its ends, over r), rho sin(pi / n) (half a chord over the reach), uniformity 1.
    s = curvebench.sample("circle:r=2", uniform=n)
    assert np.allclose(np.hypot(*s.points.T), 2) and np.allclose(s.lfs, 2, rtol=1e-3)
    m = curvebench.measure("circle:r=2", s.points, s.edges, minimum_lfs=0)
    assert m["epsilon"] == pytest.approx(2 * math.sin(math.pi / (2 * n)), rel=1e-3)
    assert m["rho"] == pytest.approx(math.sin(math.pi / n), rel=1e-3)
    assert m["uniformity"] == pytest.approx(1, abs=1e-9)
    assert m["points"] == n


@pytest.mark.parametrize("curve", ["circle:r=1", "ellipse:a=2,b=1", "fourier:seed=3", "star:seed=2,angle=60,rounding=0.1"])
@pytest.mark.parametrize("epsilon", [0.2, 0.5])
def test_a_safe_sampling_measures_just_below_its_epsilon(curve, epsilon):
    s = curvebench.sample(curve, epsilon=epsilon, safe=True)
    m = curvebench.measure(curve, s.points, s.edges, minimum_lfs=s.minimum_lfs)
    assert 0.9 * epsilon < m["epsilon"] <= epsilon
    assert 0 <= m["epsilon_at"]["parameter"]
    # Its ground truth, scored against itself, is exact at distance 0 (but for rounding).
    e = curvebench.evaluate(s.points, s.edges, s.edges)
    assert e["exact"] and e["hausdorff"] < 1e-12 * e["diagonal"] and e["manifold"]
    assert e["closed_components"] == 1 and e["edges"] == len(s.edges) == len(s.points)


def test_a_reconstruction_is_scored_as_the_truth_says():
    s = curvebench.sample("circle:r=1", epsilon=0.3, safe=True)
    found = curvebench.reconstruct(s.points, "nn-crust").edges
    assert curvebench.evaluate(s.points, found, s.edges)["exact"]
    broken = found[1:]  # one edge missing: an open path, not exact
    e = curvebench.evaluate(s.points, broken, s.edges, curve="circle:r=1")
    assert not e["exact"] and e["open_components"] == 1 and e["distances_to"] == "curve circle:r=1"
    assert e["hausdorff"] > 0


@pytest.mark.parametrize("options", [
    dict(epsilon=0.4),
    dict(epsilon=0.3, safe=True, uniform_noise=0.01, outliers=10, seed=4),
    dict(rho=0.5, safe=True, lfs_noise=0.2, seed=9),
    dict(random=40, seed=2),
    dict(uniform=33, crossing_samples=True),
])
def test_sample_writes_what_the_command_line_writes(options, cli, tmp_path):
    curve = "lissajous:a=1,b=2,seed=1" if options.get("crossing_samples") else "fourier:seed=5"
    arguments = []
    for key, value in options.items():
        flag = "--" + key.replace("_", "-")
        arguments += [flag] if value is True else [flag, value]
    cli("sample", "--curve", curve, "-o", tmp_path / "s", *arguments)
    s = curvebench.sample(curve, **options)
    np.testing.assert_array_equal(s.points, read_points(tmp_path / "s.xy"))
    np.testing.assert_array_equal(s.edges, read_edges(tmp_path / "s.edges"))
    np.testing.assert_array_equal(s.lfs, np.loadtxt(tmp_path / "s.lfs"))
    assert list(s.labels) == (tmp_path / "s.labels").read_text().split()
    assert s.outlier.sum() == list(s.labels).count("outlier")
    assert np.isnan(s.lfs[s.outlier]).all() and (s.component[s.outlier] == -1).all()


def test_measure_and_evaluate_report_what_the_command_line_reports(cli, tmp_path):
    s = curvebench.sample("fourier:seed=2", epsilon=0.35, safe=True)
    write_points(tmp_path / "s.xy", s.points)
    write_edges(tmp_path / "s.edges", s.edges)
    expected = json.loads(cli("measure", "--curve", "fourier:seed=2", "-i", tmp_path / "s.xy").stdout)
    measured = curvebench.measure("fourier:seed=2", s.points, s.edges)
    for key in ("epsilon", "epsilon_at", "rho", "rho_edge", "uniformity", "uniformity_at_point", "minimum_lfs", "points"):
        assert measured[key] == expected[key], key
    found = curvebench.reconstruct(s.points, "crust").edges
    write_edges(tmp_path / "found.edges", found)
    expected = json.loads(cli("evaluate", "-i", tmp_path / "s.xy", "-e", tmp_path / "found.edges", "-g",
                              tmp_path / "s.edges", "--curve", "fourier:seed=2").stdout)
    assert curvebench.evaluate(s.points, found, s.edges, curve="fourier:seed=2") == expected


def test_bad_requests_raise_the_command_lines_messages(cli, tmp_path):
    for arguments, options in (
            (["--curve", "circle:r=-1", "--epsilon", 0.3], dict(curve="circle:r=-1", epsilon=0.3)),
            (["--curve", "blah", "--epsilon", 0.3], dict(curve="blah", epsilon=0.3)),
            (["--curve", "circle", "--epsilon", -0.3], dict(curve="circle", epsilon=-0.3)),
            (["--curve", "circle", "--uniform", 0], dict(curve="circle", uniform=0))):
        message = cli("sample", "-o", tmp_path / "s", *arguments, check=False).stderr.strip()
        with pytest.raises(ValueError) as raised:
            curvebench.sample(**options)
        assert message == "curvebench: " + str(raised.value)
    with pytest.raises(ValueError, match="exactly one sampler"):
        curvebench.sample("circle")
    with pytest.raises(ValueError, match="exactly one sampler"):
        curvebench.sample("circle", epsilon=0.3, uniform=10)
    for bad in (dict(epsilon=float("nan")), dict(epsilon="x"), dict(uniform=-3), dict(uniform=2.5),
                dict(epsilon=0.3, seed=-1), dict(epsilon=0.3, outliers=float("inf"))):
        with pytest.raises(ValueError):
            curvebench.sample("circle", **bad)
    points = curvebench.sample("circle", uniform=10).points
    with pytest.raises(ValueError, match=r"edges\[0\]: index 10 out of range"):
        curvebench.evaluate(points, [[0, 10]], [[0, 1]])
    with pytest.raises(ValueError, match="integer indices"):
        curvebench.measure("circle", points, [[0.0, 1.0]])
    with pytest.raises(ValueError, match="non-finite"):
        curvebench.measure("circle", [[np.nan, 0]])
