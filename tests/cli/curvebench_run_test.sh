#!/usr/bin/env bash
# End-to-end checks of `curvebench run`, `merge` and `evaluate`: the columns of
# results.csv, exact reconstruction where a theorem promises it, a run killed halfway and
# resumed giving the same table as an uninterrupted one, and the metrics of one
# reconstruction against a closed form.
# Usage: curvebench_run_test.sh PATH/TO/curvebench
set -uo pipefail
curvebench="$1"
python=/usr/bin/python3  # Debian's, with the csv module; scripts/setup.sh installs it
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/../support/check.sh"
# Rows of a results.csv without the runtime column, which no two runs share.
rows_without_runtime() {
  "$python" -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
for r in rows:
    r.pop("runtime_ms")
    print(sorted(r.items()))' "$1"
}

run=(run sampling -a crust,nn-crust,hnn-crust -j 1 --no-report -q)
"$curvebench" "${run[@]}" -o "$work/full"
check "an uninterrupted run succeeds" test $? -eq 0
total=$(($(wc -l <"$work/full/results.csv") - 1))
check "one row per job: 30 curves x 3 levels x 3 algorithms" test "$total" -eq 270
check "the issue's columns are there" "$python" -c '
import csv, sys
header = next(csv.reader(open(sys.argv[1])))
need = "suite,input,algorithm,params,n_points,status,exact,hausdorff,rms,manifold,components,runtime_ms".split(",")
sys.exit(0 if all(c in header for c in need) else 1)' "$work/full/results.csv"
check "every job ran" "$python" -c '
import csv, sys
sys.exit(0 if all(r["status"] == "ok" for r in csv.DictReader(open(sys.argv[1]))) else 1)' "$work/full/results.csv"
# NN-Crust reconstructs every epsilon-sampling with epsilon < 1/3 (survey, "Guarantees as
# Sampling Conditions"); the safe sampler's measured epsilon is below the level.
check "nn-crust is exact at epsilon 0.25" "$python" -c '
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["algorithm"] == "nn-crust" and r["level"] == "epsilon=0.25"]
sys.exit(0 if len(rows) == 30 and all(r["exact"] == "1" for r in rows) else 1)' "$work/full/results.csv"

# The same run, killed (with its workers) once a third of the rows are in, then resumed.
setsid "$curvebench" "${run[@]}" -o "$work/cut" &
runner=$!
for _ in $(seq 1 3000); do
  [[ -f $work/cut/results.csv && $(wc -l <"$work/cut/results.csv") -gt $((total / 3)) ]] && break
  sleep 0.01
done
kill -9 -- "-$runner" 2>/dev/null
wait "$runner" 2>/dev/null
before=$(($(wc -l <"$work/cut/results.csv") - 1))
check "the run was killed halfway ($before of $total rows)" test "$before" -lt "$total"
"$curvebench" "${run[@]}" -o "$work/cut" --resume
check "the resumed run succeeds" test $? -eq 0
check "killed + resumed = uninterrupted" diff <(rows_without_runtime "$work/full/results.csv") \
  <(rows_without_runtime "$work/cut/results.csv")
"$curvebench" "${run[@]}" -o "$work/cut" 2>"$work/err"
check "an existing run is not overwritten without --resume" test $? -eq 2

# Two shards merged = the whole run.
for k in 1 2; do "$curvebench" "${run[@]}" --shard "$k/2" -o "$work/shard$k"; done
"$curvebench" merge --no-report -o "$work/merged" "$work/shard1" "$work/shard2" 2>/dev/null
check "merged shards = uninterrupted" diff <(rows_without_runtime "$work/full/results.csv") \
  <(rows_without_runtime "$work/merged/results.csv")

# evaluate: the unit square against its copy shifted by 0.1 (points 0-3 and 4-7):
# Hausdorff 0.1, RMS sqrt((2 s^2 - 2 s^3 / 3) / 4) = 0.0695222 (tests/geometry).
printf '0 0\n1 0\n1 1\n0 1\n0.1 0\n1.1 0\n1.1 1\n0.1 1\n' >"$work/squares.xy"
printf '0 1\n1 2\n2 3\n0 3\n' >"$work/first.edges"
printf '4 5\n5 6\n6 7\n4 7\n' >"$work/second.edges"
"$curvebench" evaluate -i "$work/squares.xy" -e "$work/first.edges" -g "$work/second.edges" >"$work/eval.json"
check "evaluate: distances, exactness and topology of a shifted square" "$python" -c '
import json, math, sys
e = json.load(open(sys.argv[1]))
ok = abs(e["hausdorff"] - 0.1) < 1e-12 and abs(e["rms"] - math.sqrt((2 * 0.01 - 2 * 0.001 / 3) / 4)) < 1e-6
ok = ok and e["exact"] is False and e["manifold"] is True and e["closed_components"] == 1 and e["unconnected"] == 4
sys.exit(0 if ok else 1)' "$work/eval.json"

# Bring your own algorithm: Crust wrapped as an external program (this very binary, run as
# `exec:`) scores exactly as the built-in Crust on every job of the sampling suite.
"$curvebench" run sampling -a crust -j 1 --no-report -q --pictures none -o "$work/builtin"
"$curvebench" run sampling -a "exec:$curvebench reconstruct -a crust -i {points} -o {edges} -q" -j 1 --no-report -q \
  --pictures none -o "$work/external"
check "an external wrapper of crust scores as crust does" "$python" -c '
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:])
columns = "status exact rms hausdorff normal_deviation true_topology components".split()
sys.exit(not (len(a) == len(b) == 90 and all(x[c] == y[c] for x, y in zip(a, b) for c in columns)))' \
  "$work/builtin/results.csv" "$work/external/results.csv"
"$curvebench" run smoke -a "exec:no-such-program {points} {edges}" -o "$work/bad" -q 2>"$work/bad.err"
check "a missing program is a one-line error and no run" \
  test $? -ne 0 -a "$(wc -l <"$work/bad.err")" -eq 1 -a ! -e "$work/bad/results.csv"

finish
