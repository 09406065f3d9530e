#!/usr/bin/env bash
# Certifies every theorem of the registry on COUNT cases each (default 10000) at 0.95 of
# its bound, over the benchmark's smooth families in turn (--curves mixed: Fourier curves,
# pairs side by side, nested pairs, rounded stars, and open curves for the theorem that
# covers them, Conservative Crust's), and prints one table row per theorem:
# cases, passed, failures, inconclusive, hypothesis violations and the CPU time it took.
# Not part of CI (10,000 cases of one theorem take minutes to an hour of CPU here).
#   scripts/certify_theorems.sh [COUNT] [OUT_DIR]      e.g. scripts/certify_theorems.sh 10000 out/theorems
# Each theorem's run is resumable: run the script again with the same OUT_DIR (the CPU
# time is then that of the resumed part). CURVEBENCH names another binary; THEOREMS
# (e.g. "nn-crust hnn-crust:rho") chooses some.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
count="${1:-10000}"
out="${2:-out/theorems}"
curvebench="${CURVEBENCH:-$root/build/bench/curvebench}"
python=/usr/bin/python3
mkdir -p "$out"

# The theorems: each algorithm with a proven epsilon bound (Lenz states one without proof,
# and the registry gives it none), and HNN-Crust's rho theorem.
if [[ -z "${THEOREMS:-}" ]]; then
  THEOREMS="$("$curvebench" list algorithms | awk '/epsilon < / && !/no proof/ {print $1}' | tr '\n' ' ')hnn-crust:rho"
fi

printf '| theorem | cases | passed | failures | inconclusive | hypothesis violations | CPU time |\n'
printf '|---|---|---|---|---|---|---|\n'
for theorem in $THEOREMS; do
  algorithm="${theorem%%:*}"
  flags=()
  [[ "$theorem" == *:rho ]] && flags=(--rho)
  dir="$out/${theorem/:/-}"
  [[ -f "$dir/results.csv" ]] && flags+=(--resume)
  # The CPU time of the run and of its worker processes (GNU time: a child's usage
  # includes the descendants it waited for).
  summary="$(/usr/bin/time -f '%U %S' -o "$dir.time" "$curvebench" certify -a "$algorithm" "${flags[@]}" \
             --curves mixed --count "$count" --below-bound 0.95 -o "$dir" --json -q)"
  "$python" -c '
import json, sys
s = json.loads(sys.argv[1])
cpu = sum(float(x) for x in open(sys.argv[2]).read().split()[-2:])
print("| %s, %s < %g | %d | %d | %d | %d | %d | %.0f s |" % (s["algorithm"], s["measure"], s["bound"], s["cases"],
      s["passed"], s["failures"], s["inconclusive"], s["hypothesis_violations"], cpu))' "$summary" "$dir.time"
done
