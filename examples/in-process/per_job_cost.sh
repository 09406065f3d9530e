#!/usr/bin/env bash
# The per-job cost of the example's algorithm in-process against the same code behind
# exec:, on the `runtime` suite (n = 10^3 and 10^4 on one smooth curve): REPEAT runs of
# each, alternating, one worker; prints the median runtime_ms per n and mode, and the median
# wall time of a whole run. runtime_ms is the algorithm call in-process and the program's
# wall time (start-up, file writing and reading included) behind exec:.
#
#   examples/in-process/per_job_cost.sh MY_CURVEBENCH EXAMPLES_DIR [REPEAT]
#
# MY_CURVEBENCH is the example's my-curvebench; EXAMPLES_DIR a copy of examples/ whose
# cpp/build/naive_nn_crust is built (docs/own-algorithm.md).
set -euo pipefail
program="$1" examples="$2" repeat="${3:-5}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for ((k = 0; k < repeat; ++k)); do
  for mode in in-process exec; do
    if [[ $mode == in-process ]]; then
      arguments=(-a naive-nn-crust)
    else
      arguments=(--algorithm-file "$examples/algorithms.json" -a naive-nn-crust-cpp)
    fi
    start=$(date +%s%N)
    "$program" run runtime "${arguments[@]}" -j 1 -q --no-report --pictures none -o "$work/$mode-$k" >/dev/null
    echo "$mode $(($(date +%s%N) - start))" >>"$work/wall.txt"
  done
done
/usr/bin/python3 - "$work" "$repeat" <<'PYTHON'
import csv, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
print(f"| n | in-process runtime_ms | exec: runtime_ms | exec: startup_ms | difference |  (median of {repeat})")
print("|---|---|---|---|---|")
times = {}
for mode in ("in-process", "exec"):
    for k in range(repeat):
        for row in csv.DictReader(open(f"{work}/{mode}-{k}/results.csv")):
            times.setdefault((row["n_points"], mode), []).append((float(row["runtime_ms"]), row["startup_ms"]))
for n in sorted({n for n, _ in times}, key=int):
    inside = statistics.median(t for t, _ in times[(n, "in-process")])
    outside = statistics.median(t for t, _ in times[(n, "exec")])
    startup = statistics.median(float(s) for _, s in times[(n, "exec")])
    print(f"| {n} | {inside:.2f} | {outside:.2f} | {startup:.2f} | {outside - inside:+.2f} |")
walls = {}
for line in open(f"{work}/wall.txt"):
    mode, seconds = line.split()
    walls.setdefault(mode, []).append(int(seconds) / 1e9)
for mode, values in walls.items():
    print(f"{mode}: a whole run of the suite takes {statistics.median(values):.3f} s (median of {len(values)})")
PYTHON
