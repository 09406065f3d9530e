#!/usr/bin/env python3
"""Compares curvebench's safe epsilon sampler with the survey's sampling tool, sample2d
(stefango74/sampling2d), on the SVG files it samples.

  scripts/survey_sampling_table.py SAMPLE2D_DIR [CURVEBENCH]

SAMPLE2D_DIR holds sample2d's samplings as NAME_EPSILON.txt (`x y` per line, as
data/sample2d/ does for four of them), for NAME.svg in data/svg/. For each it prints
sample2d's point count, ours (curvebench sample --safe), their ratio, and the epsilon
that curvebench measure reads for sample2d's sampling and for ours, as a Markdown table.
"""
import json
import pathlib
import subprocess
import sys
import tempfile

root = pathlib.Path(__file__).resolve().parent.parent
samplings = pathlib.Path(sys.argv[1])
curvebench = sys.argv[2] if len(sys.argv) > 2 else str(root / "build/bench/curvebench")


def measure(curve, points):
    out = subprocess.run([curvebench, "measure", "--curve", curve, "-i", str(points)], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)["epsilon"]


print("| file | epsilon | sample2d points | our points | ours / theirs | measured epsilon of sample2d's | of ours |")
print("|---|---|---|---|---|---|---|")
with tempfile.TemporaryDirectory() as scratch:
    for theirs in sorted(samplings.glob("*_*.txt"), key=lambda p: (p.stem.rsplit("_", 1)[0].lower(), float(p.stem.rsplit("_", 1)[1]))):
        name, epsilon = theirs.stem.rsplit("_", 1)
        curve = f"svg:{root}/data/svg/{name}.svg"
        their_count = sum(1 for line in theirs.read_text().splitlines() if line.strip() and not line.startswith("#"))
        base = pathlib.Path(scratch) / f"{name}_{epsilon}"
        subprocess.run([curvebench, "sample", "--curve", curve, "--epsilon", epsilon, "--safe", "-o", str(base)],
                       check=True, capture_output=True)
        our_count = sum(1 for _ in open(f"{base}.xy"))
        print(f"| {name} | {epsilon} | {their_count} | {our_count} | {our_count / their_count:.2f} "
              f"| {measure(curve, theirs):.4g} | {measure(curve, f'{base}.xy'):.4g} |", flush=True)
