#!/usr/bin/env bash
# Runs `curvebench hunt` on every built-in algorithm for SECONDS each (default 300), JOBS
# at a time (default: the number of cores), and prints one table row per algorithm: cases
# tried, findings, and each finding's kind and size. Findings go to OUT_DIR/ALGORITHM/
# with their replay.sh. Not part of CI (21 algorithms x 5 minutes is 105 CPU-minutes).
#   scripts/hunt_all.sh [SECONDS] [OUT_DIR] [JOBS]     e.g. scripts/hunt_all.sh 300 out/hunt
# CURVEBENCH names another binary; ALGORITHMS (e.g. "crust gathang") chooses some; SEED
# (default 0) is passed to every hunt.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-300}"
out="${2:-out/hunt}"
jobs="${3:-$(nproc)}"
curvebench="${CURVEBENCH:-$root/build/bench/curvebench}"
mkdir -p "$out"

if [[ -z "${ALGORITHMS:-}" ]]; then
  ALGORITHMS="$("$curvebench" list algorithms --names | tr '\n' ' ')"
fi

# One worker process per hunt (-j of the hunt is its own pool of one), JOBS hunts at once.
printf '%s\n' $ALGORITHMS | xargs -P "$jobs" -I{} sh -c \
  '"$1" hunt -a "$2" --seconds "$3" --seed "${SEED:-0}" -o "$4/$2" --json > "$4/$2.json" 2> "$4/$2.log" || echo "hunt $2: exit $?" >&2' \
  _ "$curvebench" {} "$seconds" "$out"

printf '| algorithm | cases | seconds | findings |\n|---|---|---|---|\n'
for algorithm in $ALGORITHMS; do
  /usr/bin/python3 -c '
import json, sys
try:
    s = json.load(open(sys.argv[1]))
except (OSError, ValueError):
    print("| %s | – | – | no summary: see %s |" % (sys.argv[2], sys.argv[1].replace(".json", ".log")))
    sys.exit()
kinds = "; ".join("%s on %d points" % (f["kind"], len(f["points"])) for f in s["findings"]) or "none"
print("| %s | %d | %.0f | %s |" % (s["algorithm"], s["cases"], s["seconds"], kinds))' "$out/$algorithm.json" "$algorithm"
done
