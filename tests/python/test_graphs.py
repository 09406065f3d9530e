"""curvebench.graph against independent oracles: scipy's Delaunay triangulation and
minimum spanning tree, brute force on small sets, and the command line's `graph`."""
import itertools

import numpy as np
import pytest
from scipy.sparse.csgraph import minimum_spanning_tree
from scipy.spatial import Delaunay
from scipy.spatial.distance import cdist

import curvebench
from files import read_edges, write_points


def edge_set(edges):
    return {tuple(sorted(map(int, e))) for e in np.asarray(edges).reshape(-1, 2)}


def random_points(n, seed):
    # Random doubles: in general position (no ties, no four cocircular) but for a rare draw.
    return np.random.default_rng(seed).random((n, 2))


@pytest.mark.parametrize("seed", range(5))
def test_delaunay_is_scipys_triangulation(seed):
    points = random_points(60, seed)
    expected = set()
    for triangle in Delaunay(points).simplices:
        expected |= {tuple(sorted((int(a), int(b)))) for a, b in itertools.combinations(triangle, 2)}
    assert edge_set(curvebench.graph(points, "delaunay")) == expected


@pytest.mark.parametrize("seed", range(5))
def test_emst_is_scipys_minimum_spanning_tree(seed):
    points = random_points(40, seed)
    tree = minimum_spanning_tree(cdist(points, points)).tocoo()
    assert edge_set(curvebench.graph(points, "emst")) == edge_set(np.column_stack([tree.row, tree.col]))


def brute_force(points, kind, k=2, beta=1.5):
    d = cdist(points, points)
    n = len(points)
    edges = set()
    for i, j in itertools.combinations(range(n), 2):
        others = [m for m in range(n) if m not in (i, j)]
        if kind == "gabriel":  # no point in the disc on ij as diameter
            keep = all(d[i, m] ** 2 + d[j, m] ** 2 > d[i, j] ** 2 for m in others)
        elif kind == "rng":  # no point nearer to both than they are to each other
            keep = all(max(d[i, m], d[j, m]) > d[i, j] for m in others)
        elif kind == "knn":  # one is among the other's k nearest
            keep = j in np.argsort(d[i])[1:k + 1] or i in np.argsort(d[j])[1:k + 1]
        elif kind == "sig":  # the circles of nearest-neighbour radius overlap
            r = np.sort(d, axis=1)[:, 1]
            keep = d[i, j] < r[i] + r[j]
        else:
            raise ValueError(kind)
        if keep:
            edges.add((i, j))
    return edges


@pytest.mark.parametrize("kind", ["gabriel", "rng", "knn", "sig"])
@pytest.mark.parametrize("seed", range(4))
def test_small_graphs_are_their_brute_force_definition(kind, seed):
    points = random_points(14, seed)
    assert edge_set(curvebench.graph(points, kind)) == brute_force(points, kind)


def test_knn_takes_k_and_beta_skeletons_their_identities():
    points = random_points(14, 7)
    assert edge_set(curvebench.graph(points, "knn", k=4)) == brute_force(points, "knn", k=4)
    # The lune-based beta-skeleton is the Gabriel graph at beta 1 and the RNG at beta 2.
    assert edge_set(curvebench.graph(points, "beta-lune", beta=1)) == brute_force(points, "gabriel")
    assert edge_set(curvebench.graph(points, "beta-lune", beta=2)) == brute_force(points, "rng")


def test_duplicates_are_merged_into_their_first_occurrence():
    points = random_points(20, 3)
    with_copies = np.vstack([points, points[[4, 0, 4]]])
    order = np.random.default_rng(0).permutation(len(with_copies))
    shuffled = with_copies[order]
    first = {}
    for position, original in enumerate(order):
        key = tuple(with_copies[original])
        first.setdefault(key, position)
    expected = {tuple(sorted((first[tuple(points[i])], first[tuple(points[j])])))
                for i, j in edge_set(curvebench.graph(points, "gabriel"))}
    assert edge_set(curvebench.graph(shuffled, "gabriel")) == expected


@pytest.mark.parametrize("kind", [k for k, _ in curvebench.graph_kinds()])
def test_every_graph_equals_the_command_lines(kind, cli, tmp_path, source):
    points = np.loadtxt(source / "data/hnncrust/crocodile-conf.p2d")
    arguments = {"beta-lune": ["--beta", 1.7], "beta-circle": ["--beta", 1.7], "knn": ["--k", 3]}.get(kind, [])
    cli("graph", kind, "-i", source / "data/hnncrust/crocodile-conf.p2d", "-o", tmp_path / "cli.edges", *arguments)
    parameters = {arguments[0][2:]: arguments[1]} if arguments else {}
    edges = curvebench.graph(points, kind, **parameters)
    assert edges.dtype == np.int64 and edges.shape[1] == 2
    np.testing.assert_array_equal(edges, read_edges(tmp_path / "cli.edges"))


def test_bad_input_raises_the_command_lines_errors(cli, tmp_path):
    points = random_points(10, 1)
    with pytest.raises(KeyError, match="unknown graph kind 'nope'"):
        curvebench.graph(points, "nope")
    with pytest.raises(ValueError, match="no parameter 'gamma'"):
        curvebench.graph(points, "gabriel", gamma=1)
    write_points(tmp_path / "p.xy", points)
    message = cli("graph", "beta-lune", "--beta", -1, "-i", tmp_path / "p.xy", "-o", tmp_path / "e", check=False).stderr
    with pytest.raises(ValueError) as raised:
        curvebench.graph(points, "beta-lune", beta=-1)
    assert str(raised.value) in message
    for bad in (np.array([[0.0, np.nan]]), np.zeros((3, 3)), np.zeros(4), [["a", "b"]]):
        with pytest.raises(ValueError):
            curvebench.graph(bad, "delaunay")
    with pytest.raises(ValueError, match="k is a whole number"):
        curvebench.graph(points, "knn", k=-1)
