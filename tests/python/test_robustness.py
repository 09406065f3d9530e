"""Hypothesis-made arrays that nothing may crash on: duplicates, collinear runs, NaN,
infinity, huge and tiny values, wrong shapes and types. Each call either answers with
edges between the points or raises ValueError; the interpreter survives either way."""
import numpy as np
from hypothesis import given, settings, strategies as st
from hypothesis.extra import numpy as hnp

import curvebench

# The algorithms quick enough for every example; the slow ones see the small examples only.
ALGORITHMS = [a["name"] for a in curvebench.algorithms() if a["kind"] == "built-in"]
GRAPHS = [k for k, _ in curvebench.graph_kinds()]

coordinates = st.one_of(
    st.integers(-3, 3).map(float),                    # a small lattice: duplicates, collinear runs, cocircles
    st.floats(allow_nan=False, allow_infinity=False),  # anything finite, huge and subnormal included
    st.sampled_from([1e300, -1e300, 5e-324, -5e-324, 1e-300, 2.0 ** 1000, 0.0, -0.0]),
)


@st.composite
def degenerate_point_sets(draw, max_points=12):
    n = draw(st.integers(0, max_points))
    base = draw(hnp.arrays(np.float64, (n, 2), elements=coordinates))
    kind = draw(st.sampled_from(["as drawn", "duplicated", "collinear", "scaled"]))
    if kind == "duplicated" and n > 0:
        base = base[draw(st.lists(st.integers(0, n - 1), min_size=n, max_size=2 * n))]
    elif kind == "collinear" and n > 0:
        t = base[:, 0]
        with np.errstate(all="ignore"):
            line = np.column_stack([t, 2 * t + 1])
        base = line if np.isfinite(line).all() else base
    elif kind == "scaled":
        with np.errstate(all="ignore"):
            scaled = base * draw(st.sampled_from([2.0 ** 600, 2.0 ** -600, 1e-310]))
        base = scaled if np.isfinite(scaled).all() else base
    return base


def check_edges(edges, count):
    assert edges.dtype == np.int64 and edges.ndim == 2 and edges.shape[1] == 2
    assert (edges >= 0).all() and (edges < count).all() and (edges[:, 0] < edges[:, 1]).all()


# Every algorithm on a few dozen point sets each (the profile's examples times 8).
@settings(max_examples=settings().max_examples * 8)
@given(points=degenerate_point_sets(), name=st.sampled_from(ALGORITHMS))
def test_reconstruct_answers_or_raises_value_error(points, name):
    try:
        r = curvebench.reconstruct(points, name)
    except ValueError:
        return
    check_edges(r.edges, len(r.points))


@settings(max_examples=settings().max_examples * 4)
@given(points=degenerate_point_sets(), kind=st.sampled_from(GRAPHS))
def test_graph_answers_or_raises_value_error(points, kind):
    try:
        edges = curvebench.graph(points, kind)
    except ValueError:
        return
    check_edges(edges, len(points))


bad_values = st.sampled_from([np.nan, np.inf, -np.inf])


@given(points=degenerate_point_sets(max_points=6), where=st.integers(0, 11), value=bad_values,
       name=st.sampled_from(ALGORITHMS + ["graph"]))
def test_nan_and_infinity_raise_value_error(points, where, value, name):
    points = np.vstack([points, [[0.0, 0.0]]])
    points.flat[where % points.size] = value
    try:
        if name == "graph":
            curvebench.graph(points, "delaunay")
        else:
            curvebench.reconstruct(points, name)
    except ValueError as error:
        assert "non-finite" in str(error)
    else:
        raise AssertionError("no ValueError")


@given(array=hnp.arrays(dtype=st.sampled_from([np.float64, np.float32, np.int32, np.uint64, np.complex128, np.bool_, "U3"]),
                        shape=hnp.array_shapes(min_dims=0, max_dims=3, max_side=4), elements=None))
def test_wrong_shapes_and_types_raise_value_error_or_answer(array):
    try:
        r = curvebench.reconstruct(array, "nn-crust")
    except ValueError:
        return
    assert array.ndim == 2 and array.shape[1] == 2
    check_edges(r.edges, len(r.points))


@given(value=st.recursive(st.none() | st.booleans() | st.floats() | st.text(max_size=2) | st.integers(),
                          lambda children: st.lists(children, max_size=3), max_leaves=8))
def test_any_python_value_raises_value_error_or_answers(value):
    try:
        r = curvebench.reconstruct(value, "nn-crust")
    except ValueError:
        return
    check_edges(r.edges, len(r.points))


@given(points=degenerate_point_sets(max_points=8),
       edges=hnp.arrays(np.int64, hnp.array_shapes(min_dims=1, max_dims=2, max_side=4), elements=st.integers(-2, 10)))
def test_evaluate_and_measure_answer_or_raise_value_error(points, edges):
    for call in (lambda: curvebench.evaluate(points, edges, edges),
                 lambda: curvebench.measure("circle:r=1", points, edges)):
        try:
            call()
        except ValueError:
            pass
