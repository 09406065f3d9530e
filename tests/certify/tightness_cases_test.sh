#!/usr/bin/env bash
# Replays every committed tightness case (docs/tightness/ALG/, written by `curvebench
# tightness`): the algorithm gives the recorded edges again, they are not the ground truth,
# and `curvebench measure` on the files alone gives the recorded epsilon (or rho), above the
# proven bound.
# Usage: tightness_cases_test.sh CURVEBENCH
set -uo pipefail
curvebench="$1"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$root/tests/support/check.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cases=0
for dir in "$root"/docs/tightness/*/; do
  name="$(basename "$dir")"
  cases=$((cases + 1))
  read -r algorithm measure bound recorded < <(/usr/bin/python3 -c '
import json, sys
c = json.load(open(sys.argv[1]))
print(c["algorithm"], c["measure"], repr(c["bound"]), repr(c["smallest_failure"]))' "$dir/case.json")
  "$curvebench" reconstruct -a "$algorithm" -i "$dir/points.xy" -o "$work/$name.edges" -q 2>/dev/null
  check "$name: the same edges as recorded" cmp -s "$work/$name.edges" "$dir/reconstruction.edges"
  exact="$("$curvebench" evaluate -i "$dir/points.xy" -e "$work/$name.edges" -g "$dir/truth.edges" |
    /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["exact"])')"
  check "$name: not exact" test "$exact" = False
  measured="$("$curvebench" measure --curve "$(cat "$dir/curve.txt")" -i "$dir/points.xy" -e "$dir/truth.edges" --min-lfs 0 |
    /usr/bin/python3 -c 'import json, sys; print(repr(json.load(sys.stdin)[sys.argv[1]]))' "$measure")"
  check "$name: measured $measure $measured is the recorded $recorded" \
    /usr/bin/python3 -c 'import sys; a, b = map(float, sys.argv[1:]); sys.exit(abs(a - b) > 1e-9 * b)' "$measured" "$recorded"
  check "$name: above the proven bound $bound" \
    /usr/bin/python3 -c 'import sys; sys.exit(not float(sys.argv[1]) >= float(sys.argv[2]))' "$measured" "$bound"
done
check "cases found" test "$cases" -ge 7
finish
