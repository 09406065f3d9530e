#!/usr/bin/env bash
# Re-measures every committed ambiguity case (docs/ambiguity/NAME/, written by `curvebench
# ambiguity -o`) from its files alone: `curvebench measure` reads each curve back from its
# SVG path and gives the recorded epsilon, the two ground truths through the same points
# differ, and each is a union of disjoint cycles covering every point: one cycle, or as many as
# the case's summary.json says its curve has components (components_1, components_2).
# Usage: ambiguity_cases_test.sh CURVEBENCH [CASES_DIR]   (default: docs/ambiguity)
set -uo pipefail
curvebench="$1"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$root/tests/support/check.sh"

cases=0
for dir in "${2:-$root/docs/ambiguity}"/*/; do
  name="$(basename "$dir")"
  cases=$((cases + 1))
  for k in 1 2; do
    recorded="$(/usr/bin/python3 -c 'import json, sys; print(repr(json.load(open(sys.argv[1]))["epsilon_" + sys.argv[2]]))' \
      "$dir/summary.json" "$k")"
    measured="$("$curvebench" measure --curve "svg:$dir/curve_$k.svg" -i "$dir/points.xy" -e "$dir/edges_$k.edges" --min-lfs 0 |
      /usr/bin/python3 -c 'import json, sys; print(repr(json.load(sys.stdin)["epsilon"]))')"
    check "$name: C$k measured epsilon $measured is the recorded $recorded" \
      /usr/bin/python3 -c 'import sys; a, b = map(float, sys.argv[1:]); sys.exit(abs(a - b) > 1e-9 * b)' "$measured" "$recorded"
  done
  check "$name: each ground truth is a cycle per component through every point, and they differ" /usr/bin/python3 - "$dir" <<'PY'
import json, sys
from pathlib import Path
d = Path(sys.argv[1])
n = sum(1 for line in open(d / "points.xy") if line.strip() and not line.startswith("#"))
summary = json.load(open(d / "summary.json"))
def cycles(k):
    name = f"edges_{k}.edges"
    edges = {tuple(sorted(map(int, l.split()[:2]))) for l in open(d / name) if l.strip() and not l.startswith("#")}
    adjacent = {i: [] for i in range(n)}
    for a, b in edges:
        adjacent[a].append(b), adjacent[b].append(a)
    if len(edges) != n or any(len(v) != 2 for v in adjacent.values()):
        sys.exit(f"{name}: not 2-regular on {n} points")
    unseen, count = set(range(n)), 0
    while unseen:  # walk each cycle from its smallest point
        start = previous = min(unseen)
        at = adjacent[start][0]
        unseen.discard(start)
        while at != start:
            unseen.discard(at)
            previous, at = at, adjacent[at][0] if adjacent[at][0] != previous else adjacent[at][1]
        count += 1
    if count != summary.get(f"components_{k}", 1):
        sys.exit(f"{name}: {count} cycles, but C{k} has {summary.get(f'components_{k}', 1)} components")
    return edges
sys.exit(cycles(1) == cycles(2))
PY
done
check "cases found" test "$cases" -ge 1
finish
