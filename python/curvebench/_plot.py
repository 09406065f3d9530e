"""Pictures of reconstructions with matplotlib, coloured as a run's pictures are
(bench/runner/run.cpp): ground-truth edges found in blue, wrong edges red, missing ones
dashed orange; without a ground truth, every edge blue."""
import numpy as np


def _segments(points, edges):
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    return points[edges] if len(edges) else np.empty((0, 2, 2))


def _edge_set(edges):
    edges = np.sort(np.asarray(edges, dtype=np.int64).reshape(-1, 2), axis=1)
    return {(int(i), int(j)) for i, j in edges}


def plot(points, edges, truth=None, ax=None, *, title=None, point_size=6.0):
    """See curvebench.plot."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    points = np.asarray(points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 2:
        raise ValueError(f"points: an (n, 2) array of coordinates, not shape {points.shape}")
    for what, given in (("edges", edges), ("truth", truth)):
        if given is None:
            continue
        array = np.asarray(given)
        if array.size and (array.ndim != 2 or array.shape[1] != 2 or array.dtype.kind not in "iu"
                           or array.min() < 0 or array.max() >= len(points)):
            raise ValueError(f"{what}: an (m, 2) array of indices below {len(points)}")
    if ax is None:
        ax = plt.figure().add_subplot()
    layers = []
    if truth is None:
        layers.append((sorted(_edge_set(edges)), dict(colors="#1f4e99", linewidths=1.5, label="reconstructed")))
    else:
        found, expected = _edge_set(edges), _edge_set(truth)
        layers += [(sorted(expected - found), dict(colors="#ff9900", linewidths=2, linestyles=(0, (5, 4)), label="missing")),
                   (sorted(found & expected), dict(colors="#1f4e99", linewidths=1.5, label="reconstructed")),
                   (sorted(found - expected), dict(colors="#e00000", linewidths=2.5, label="wrong"))]
    for chosen, style in layers:
        if chosen:
            ax.add_collection(LineCollection(_segments(points, chosen), **style))
    ax.scatter(points[:, 0], points[:, 1], s=point_size, c="black", zorder=3, label="points")
    ax.set_aspect("equal")
    ax.autoscale_view()
    if title:
        ax.set_title(title)
    return ax
