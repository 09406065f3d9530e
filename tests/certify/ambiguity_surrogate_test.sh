#!/usr/bin/env bash
# scripts/ambiguity_surrogate.py, briefly, on its gear family (k = 12): what it writes is a case
# whose recorded epsilons are what `curvebench measure` reads from its files, with two different
# cycles through the same points (ambiguity_cases_test.sh); the point set has the family's
# 12-fold rotational symmetry; and the descent lowers the measured epsilon of its start.
# Usage: ambiguity_surrogate_test.sh CURVEBENCH
set -uo pipefail
curvebench="$1"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$root/tests/support/check.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

check "a short gear search runs" env OMP_NUM_THREADS=1 /usr/bin/python3 "$root/scripts/ambiguity_surrogate.py" \
  --family gear -k 12 --ratio 1.3864957676317802 --seed 1 --iterations 2 --powers 100 \
  -o "$work/gear" --curvebench "$curvebench"
check "what it writes re-measures as recorded, and both ground truths are cycles that differ" \
  bash "$root/tests/certify/ambiguity_cases_test.sh" "$curvebench" "$work/gear"

check "S is invariant under the rotation by 2 pi / 12" /usr/bin/python3 - "$work/gear/best/points.xy" <<'PY'
import math, sys
points = [tuple(map(float, l.split()[:2])) for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
c, s = math.cos(2 * math.pi / 12), math.sin(2 * math.pi / 12)
scale = max(math.hypot(x, y) for x, y in points)
sys.exit(any(min(math.hypot(c * x - s * y - u, s * x + c * y - v) for u, v in points) > 1e-9 * scale
             for x, y in points))
PY
check "the descent lowers its start's measured epsilon" /usr/bin/python3 - "$work/gear/log.jsonl" <<'PY'
import json, sys
start = json.loads(open(sys.argv[1]).readline())
sys.exit(not start["descent_measured"] < start["start_measured"])
PY
finish
