#!/usr/bin/python3
"""Draws one of the authors' point sets four ways: the input, the authors' FitConnect, and
ours (fit-connect, stretch-denoise) at their defaults.

usage: draw.py CURVEBENCH POINTS AUTHORS_OUTPUT PICTURE.png

AUTHORS_OUTPUT is the text the headless driver of the authors' program prints (README.md
in this folder): lines `class I C`, `proj I X Y` (the point's blended position) and
`edge I J` (on input indices). Ours is run here through `CURVEBENCH reconstruct`.
"""
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_points(path):
    points = []
    for line in open(path):
        fields = line.split()
        if len(fields) >= 2 and not line.startswith("#"):
            points.append((float(fields[0]), float(fields[1])))
    return points


def authors(path):
    projected, edges = {}, []
    for line in open(path):
        fields = line.split()
        if fields[0] == "proj":
            projected[int(fields[1])] = (float(fields[2]), float(fields[3]))
        elif fields[0] == "edge":
            edges.append((int(fields[1]), int(fields[2])))
    kept = sorted({v for e in edges for v in e})
    index = {v: k for k, v in enumerate(kept)}
    return [projected[v] for v in kept], [(index[a], index[b]) for a, b in edges]


def ours(curvebench, points_file, algorithm):
    with tempfile.TemporaryDirectory() as folder:
        edges_file, out_points = os.path.join(folder, "e"), os.path.join(folder, "p")
        subprocess.run([curvebench, "reconstruct", "-a", algorithm, "-i", points_file, "-o", edges_file,
                        "--points-out", out_points, "-q"], check=True)
        points = read_points(out_points)
        edges = [tuple(map(int, line.split()[:2])) for line in open(edges_file) if line.strip()]
    return points, edges


def panel(axes, title, points, edges, background):
    axes.scatter([p[0] for p in background], [p[1] for p in background], s=2, c="#bbbbbb", linewidths=0)
    for a, b in edges:
        axes.plot([points[a][0], points[b][0]], [points[a][1], points[b][1]], c="#1f4e9c", lw=0.9)
    if points is not background:
        axes.scatter([p[0] for p in points], [p[1] for p in points], s=5, c="#c0392b", linewidths=0, zorder=3)
    axes.set_title(title, fontsize=9)
    axes.set_aspect("equal")
    axes.axis("off")


def main():
    curvebench, points_file, authors_file, picture = sys.argv[1:5]
    name = os.path.basename(points_file)
    data = read_points(points_file)
    theirs = authors(authors_file)
    fit = ours(curvebench, points_file, "fit-connect")
    stretch = ours(curvebench, points_file, "stretch-denoise")
    figure, axes = plt.subplots(1, 4, figsize=(16, 4.4))
    panel(axes[0], f"{name}: input, {len(data)} points", data, [], data)
    panel(axes[1], f"authors' FitConnect: {len(theirs[0])} points", *theirs, data)
    panel(axes[2], f"ours, fit-connect: {len(fit[0])} points", *fit, data)
    panel(axes[3], f"ours, stretch-denoise: {len(stretch[0])} points", *stretch, data)
    figure.tight_layout()
    figure.savefig(picture, dpi=80)


if __name__ == "__main__":
    main()
