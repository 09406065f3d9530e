#!/usr/bin/env bash
# The glyph sweep run twice on this machine (`curvebench rate -c 'glyph:*' -o DIR`, every
# algorithm), and its two results.csv compared row for row, runtimes aside
# (scripts/compare_results.py): every algorithm, Optimal Transport included, must give
# the same rows. Prints both wall times, the rows that differ, and each run's table.
#   scripts/glyph_sweep_twice.sh [DIR]     (default out/glyph-sweep-twice; written anew)
# Environment: STRIDE (4: every fourth glyph, 1,465 of them), EPSILON (default: rate's
# 0.2, 0.4, 0.6), JOBS (2), ALGORITHMS (default: all; e.g. optimal-transport).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
curvebench="$root/build/bench/curvebench"
[[ -x $curvebench ]] || { echo "build curvebench first: scripts/build.sh run" >&2; exit 2; }
dir="$(realpath -m "${1:-out/glyph-sweep-twice}")"
rate=(rate -c 'glyph:*' --stride "${STRIDE:-4}" -j "${JOBS:-2}" -q)
[[ -n ${EPSILON:-} ]] && rate+=(-e "$EPSILON")
[[ -n ${ALGORITHMS:-} ]] && rate+=(-a "$ALGORITHMS")
rm -rf "$dir" && mkdir -p "$dir"
for run in first second; do
  start=$SECONDS
  "$curvebench" "${rate[@]}" -o "$dir/$run" >"$dir/$run.txt"
  echo "$run sweep: $((SECONDS - start)) s, $(($(wc -l <"$dir/$run/results.csv") - 1)) rows"
done
cat "$dir/first.txt"
diff -q "$dir/first.txt" "$dir/second.txt" && echo "the same table twice"
/usr/bin/python3 "$root/scripts/compare_results.py" "$dir/first/results.csv" "$dir/second/results.csv"
