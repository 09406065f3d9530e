"""Point and edge files as the command line reads and writes them."""
import pathlib

import numpy as np


def read_points(path):
    return np.loadtxt(path, ndmin=2, comments="#").reshape(-1, 2)


def read_edges(path):
    text = pathlib.Path(path).read_text().split()
    return np.array(text, dtype=np.int64).reshape(-1, 2)


def write_points(path, points):
    np.savetxt(path, np.asarray(points), fmt="%.17g")


def write_edges(path, edges):
    np.savetxt(path, np.asarray(edges, dtype=np.int64).reshape(-1, 2), fmt="%d")
