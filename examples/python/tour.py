#!/usr/bin/python3
"""A tour of curvebench from Python (docs/python.md), run in CI as the ctest python.tour.

    PYTHONPATH=build/python python3 examples/python/tour.py [OUT]

samples a curve, reconstructs it with three algorithms, draws them to OUT/tour.png,
certifies a ten-line Python NN-Crust against NN-Crust's theorem (epsilon < 1/3), and runs
a benchmark suite into a pandas DataFrame. OUT defaults to ./tour-out.
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # pictures to files, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

import curvebench  # noqa: E402

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "tour-out")
out.mkdir(parents=True, exist_ok=True)

# 1. Sample a curve: a random smooth closed curve, safely at epsilon 0.3 (its measured
#    epsilon stays below 0.3), with its ground truth and lfs.
curve = "fourier:seed=7"
s = curvebench.sample(curve, epsilon=0.3, safe=True)
measured = curvebench.measure(curve, s.points, s.edges)
print(f"{curve}: {len(s)} points, measured epsilon {measured['epsilon']:.3f}, "
      f"lfs from {s.lfs.min():.3f} to {s.lfs.max():.3f}")

# 2. Reconstruct it with three algorithms, each scored against the ground truth.
names = ["crust", "nn-crust", "hnn-crust"]
results = {name: curvebench.reconstruct(s.points, name) for name in names}
for name, r in results.items():
    e = curvebench.evaluate(s.points, r.edges, s.edges)
    print(f"{name:10s} {len(r.edges):4d} edges in {1e3 * r.runtime:6.3f} ms: exact {e['exact']}")

# 3. Draw them: ground-truth edges found blue, wrong red, missing dashed orange.
figure, axes = plt.subplots(1, 3, figsize=(12, 4))
for ax, (name, r) in zip(axes, results.items()):
    curvebench.plot(r.points, r.edges, truth=s.edges, ax=ax, title=name)
figure.savefig(out / "tour.png", dpi=80)
print(f"pictures: {out / 'tour.png'}")


# 4. A ten-line NN-Crust in Python (floating point, as most research code), certified
#    against the theorem it claims: every epsilon-sampling with epsilon < 1/3 of a smooth
#    closed curve is reconstructed exactly. Each case runs in a worker process of its own.
@curvebench.algorithm(name="tour-nn-crust", epsilon_below=1 / 3, capabilities={"multiple": "yes"})
def nn_crust(points):
    _, near = cKDTree(points).query(points, k=min(len(points), 12))
    edges = set()
    for p, row in enumerate(near):
        q = row[1]
        edges.add((min(p, q), max(p, q)))
        half = next((r for r in row[2:] if np.dot(points[r] - points[p], points[q] - points[p]) < 0), None)
        if half is not None:
            edges.add((min(p, half), max(p, half)))
    return sorted(edges)


summary = curvebench.certify(nn_crust, count=20, curves="mixed")
print(f"certify {summary['algorithm']}: epsilon < {summary['bound']:.4f}, {summary['cases']} cases: "
      f"{summary['passed']} passed, {summary['failures']} failures, {summary['inconclusive']} inconclusive")
assert summary["failures"] == 0, summary["counterexamples"]

# 5. Run a suite into a DataFrame: the Python NN-Crust beside the built-in one.
run = curvebench.run("sampling", [nn_crust, "nn-crust"])
table = run.results.groupby(["algorithm", "level"]).agg(jobs=("job", "size"), exact=("exact", "mean"),
                                                         runtime_ms=("runtime_ms", "median"))
print(table.to_string())
print(run.summary[["algorithm", "level", "jobs"] + [c for c in run.summary.columns if c.startswith("exact")]]
      .to_string(index=False))
assert (run.results.status == "ok").all()
