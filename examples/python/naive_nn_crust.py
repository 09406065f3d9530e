#!/usr/bin/python3
"""A naive NN-Crust (Dey and Kumar 1999) as an external curvebench algorithm.

    python3 naive_nn_crust.py POINTS EDGES

reads "x y" lines from POINTS and writes "i j" lines (0-based) to EDGES: each point is
joined to its nearest neighbour q and to its half neighbour, the nearest point r on the
other side (angle q-p-r above 90 degrees). With numpy and scipy from Debian
(python3-numpy, python3-scipy).

It decides in floating point, as most research code does; curvebench's own NN-Crust
(algorithms/nn_crust.h) decides exactly. `curvebench hunt` shows where that matters.
"""
import sys

import numpy as np
from scipy.spatial import cKDTree


def nn_crust(points):
    n = len(points)
    if n < 2:
        return set()
    tree = cKDTree(points)
    edges = set()
    for p in range(n):
        # Neighbours by distance, nearest first; widen the search until the half neighbour shows.
        k = min(n, 8)
        while True:
            _, order = tree.query(points[p], k=k)
            order = [int(q) for q in np.atleast_1d(order) if q != p]
            nearest = order[0]
            edges.add((min(p, nearest), max(p, nearest)))
            towards = points[nearest] - points[p]
            half = next((r for r in order[1:] if np.dot(points[r] - points[p], towards) < 0), None)
            if half is not None:
                edges.add((min(p, half), max(p, half)))
                break
            if k == n:
                break
            k = min(n, 2 * k)
    return edges


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: naive_nn_crust.py POINTS EDGES")
    points = np.loadtxt(sys.argv[1], ndmin=2).reshape(-1, 2)
    with open(sys.argv[2], "w") as out:
        for i, j in sorted(nn_crust(points)):
            out.write(f"{i} {j}\n")


if __name__ == "__main__":
    main()
