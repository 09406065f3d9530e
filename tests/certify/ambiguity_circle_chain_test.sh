#!/usr/bin/env bash
# scripts/ambiguity_circle_chain.py, and the committed case docs/ambiguity/circle-chain, against an
# exact computation on the circles the case records (summary.json: circles_1, circles_2 as x, y, r):
# - every point lies on one circle of each family, the circles of a family are disjoint, and each
#   ground truth joins the points around each circle in angular order;
# - the recorded epsilon (curvebench measure on the written Bezier curves) is within 1e-3 of
#   max d(x, S) / lfs(x) over 100,000 points x of each circle, where for equal disjoint circles
#   lfs(x) = min(r, distance from x to the nearest bisector with another centre of its family)
#   (the medial axis is the centres and the Voronoi diagram of the centres; x lies inside its
#   centre's convex cell, so the distance to the cell's boundary is that to the nearest bisector);
# - epsilon < 1 at 20 circles per family, falls from 20 to 40 circles, and stays above the straight
#   chain's closed form, 2 sin(pi/4 - theta/2) at the s/r where it equals 2 sin(theta/2) / (s/r - 1),
#   cos(theta) = s / 2r.
# Usage: ambiguity_circle_chain_test.sh CURVEBENCH
set -uo pipefail
curvebench="$1"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$root/tests/support/check.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

chain() { /usr/bin/python3 "$root/scripts/ambiguity_circle_chain.py" --curvebench "$curvebench" "$@"; }
check "20 circles per family, s/r chosen by the script" chain -o "$work/n20" --circles 20
check "40 circles per family at s/r 1.6328" chain -o "$work/n40" --circles 40 --ratio 1.6328
check "what it writes re-measures as recorded, with a cycle per circle" \
  bash "$root/tests/certify/ambiguity_cases_test.sh" "$curvebench" "$work"
check "--ratio outside (1/cos(pi/2N), 2) is refused" bash -c '! "$@" 2>/dev/null' _ \
  /usr/bin/python3 "$root/scripts/ambiguity_circle_chain.py" --curvebench "$curvebench" -o "$work/bad" \
  --circles 20 --ratio 2.5

for dir in "$work/n20" "$work/n40" "$root/docs/ambiguity/circle-chain"; do
  check "$(basename "$dir"): points, circles and ground truths agree, and the exact epsilon is the recorded one" \
    /usr/bin/python3 - "$dir" <<'PY'
import json, math, sys
import numpy as np
from scipy.spatial import cKDTree
d = sys.argv[1]
summary = json.load(open(f"{d}/summary.json"))
S = np.loadtxt(f"{d}/points.xy", ndmin=2)
scale = np.abs(S).max()
nearest = cKDTree(S)
for k in (1, 2):
    circles = np.array(summary[f"circles_{k}"])
    c, r = circles[:, :2], circles[:, 2]
    gap = np.linalg.norm(c[:, None] - c[None], axis=2) - r[:, None] - r[None]
    np.fill_diagonal(gap, np.inf)
    if gap.min() <= 0 or np.ptp(r) > 1e-12 * r.max():
        sys.exit(f"C{k}: circles not equal and disjoint")
    on = np.abs(np.linalg.norm(S[:, None] - c[None], axis=2) - r[None]) < 1e-12 * scale
    if not (on.sum(axis=1) == 1).all():
        sys.exit(f"C{k}: a point is not on exactly one circle")
    expected = set()
    for i in range(len(c)):
        members = np.flatnonzero(on[:, i])
        members = members[np.argsort(np.arctan2(*(S[members] - c[i]).T[::-1]))]
        expected |= {tuple(sorted((int(a), int(b)))) for a, b in zip(members, np.roll(members, -1))}
    edges = {tuple(sorted(map(int, l.split()[:2]))) for l in open(f"{d}/edges_{k}.edges") if l.strip()}
    if edges != expected:
        sys.exit(f"C{k}: ground truth is not the angular order around each circle")
    worst = 0.0
    t = np.linspace(0, 2 * math.pi, 100000, endpoint=False)
    for i in range(len(c)):
        x = c[i] + r[i] * np.column_stack([np.cos(t), np.sin(t)])
        dist = nearest.query(x)[0]
        lfs = np.full(len(t), r[i])
        for j in range(len(c)):
            if j != i:
                e = (c[j] - c[i]) / np.linalg.norm(c[j] - c[i])
                lfs = np.minimum(lfs, np.linalg.norm(c[j] - c[i]) / 2 - (x - c[i]) @ e)
        worst = max(worst, (dist / lfs).max())
    recorded = summary[f"epsilon_{k}"]
    if abs(worst - recorded) > 1e-3 * worst:
        sys.exit(f"C{k}: exact epsilon {worst} but recorded {recorded}")
    print(f"C{k}: exact {worst:.6f}, recorded {recorded:.6f}")
PY
done

check "epsilon < 1 at 20 circles, lower at 40, and above the straight chain's 0.9276" /usr/bin/python3 - "$work" <<'PY'
import json, math, sys
from scipy.optimize import brentq
theta = lambda u: math.acos(u / 2)
u = brentq(lambda u: 2 * math.sin(theta(u) / 2) / (u - 1) - 2 * math.sin(math.pi / 4 - theta(u) / 2), 1.2, 1.99)
limit = 2 * math.sin(math.pi / 4 - theta(u) / 2)
e20, e40 = (json.load(open(f"{sys.argv[1]}/{n}/summary.json"))["max_epsilon"] for n in ("n20", "n40"))
print(f"straight chain {limit:.6f} at s/r {u:.6f}; 20 circles {e20:.6f}, 40 circles {e40:.6f}")
sys.exit(not (abs(limit - 0.92760) < 1e-5 and limit < e40 < e20 < 1))
PY
finish
