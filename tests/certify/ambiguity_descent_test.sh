#!/usr/bin/env bash
# scripts/ambiguity_descent.py on the committed case mirror-via-seed-2, briefly: what it writes is a
# mirror case (S = R(S), C2 = R(C1) as drawn), its recorded epsilon is what `curvebench measure` reads
# from its files, the descent never ends above its source (the source is a candidate), and a mirror
# pair added on a stretch of C1 joins S on both curves. The recorded epsilon is checked by
# ambiguity_cases_test.sh, run on what this writes.
# Usage: ambiguity_descent_test.sh CURVEBENCH
set -uo pipefail
curvebench="$1"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$root/tests/support/check.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source_case="$root/docs/ambiguity/mirror-via-seed-2"

descend() { /usr/bin/python3 "$root/scripts/ambiguity_descent.py" "$source_case" --curvebench "$curvebench" "$@"; }
check "a short descent runs" descend -o "$work/descent" --powers 200 --iterations 3
check "a descent with a pair added on C1's stretch 12-13 runs" \
  descend -o "$work/pair" --add-pair 12-13 --powers 200 --iterations 3

check "what it writes re-measures as recorded, and both ground truths are cycles that differ" \
  bash "$root/tests/certify/ambiguity_cases_test.sh" "$curvebench" "$work"
for name in descent pair; do
  dir="$work/$name"
  check "$name: S is mirror-symmetric and C2 is the mirror image of C1" /usr/bin/python3 - "$dir" <<'PY'
import re, sys
d = sys.argv[1]
points = [tuple(map(float, l.split()[:2])) for l in open(f"{d}/points.xy") if l.strip() and not l.startswith("#")]
scale = max(max(abs(x), abs(y)) for x, y in points)
for x, y in points:
    if min(abs(-x - u) + abs(y - v) for u, v in points) > 1e-12 * scale:
        sys.exit(f"({x}, {y}) has no mirror image in S")
path = lambda k: [float(v) for v in re.findall(r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?", open(f"{d}/curve_{k}.svg").read().split(' d="')[1].split('"')[0])]
c1, c2 = path(1), path(2)
sys.exit(len(c1) != len(c2) or any(abs(a + b) > 1e-12 * scale if i % 2 == 0 else abs(a - b) > 1e-12 * scale
                                   for i, (a, b) in enumerate(zip(c1, c2))))
PY
done

check "the descent ends no higher than its source" /usr/bin/python3 - "$source_case" "$work/descent" <<'PY'
import json, sys
before, after = (json.load(open(f"{d}/summary.json"))["max_epsilon"] for d in sys.argv[1:])
sys.exit(not after <= before * (1 + 1e-9))
PY
check "the added pair is in S and on both curves' cycles" /usr/bin/python3 - "$source_case" "$work/pair" <<'PY'
import sys
count = lambda d: sum(1 for l in open(f"{d}/points.xy") if l.strip() and not l.startswith("#"))
before, after = (count(d) for d in sys.argv[1:])
edges = lambda k: [tuple(map(int, l.split()[:2])) for l in open(f"{sys.argv[2]}/edges_{k}.edges") if l.strip()]
on_cycle = all({a for e in edges(k) for a in e} == set(range(after)) and len(edges(k)) == after for k in (1, 2))
sys.exit(not (after == before + 2 and on_cycle))
PY
finish
