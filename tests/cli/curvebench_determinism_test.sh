#!/usr/bin/env bash
# Every registered algorithm gives the same output for the same input, whatever runs
# beside it: the suite `determinism` (one or two inputs of every experiment, 30 sources)
# run with one worker, with two, and with two on shuffled input points
# (--shuffle-points: edges mapped back to the input's indices; an algorithm that returns
# points of its own gets the input as made), must give the same results.csv byte for byte,
# runtime_ms and startup_ms aside (scripts/compare_results.py), and the same pictures:
# --pictures all draws every job's edges, so that two edge sets with equal metrics differ
# there. The runner forks each job's worker from a parent that makes inputs 8 sources per
# worker at a time: one and two workers fork from parents in different states (another
# heap), and the 30 sources make four batches with one worker and two with two.
# The comparison must be able to fail: a copy of a row with one field changed is caught,
# a changed runtime is not.
# Usage: curvebench_determinism_test.sh PATH/TO/curvebench
set -uo pipefail
curvebench="$1"
python=/usr/bin/python3
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
compare=("$python" "$root/scripts/compare_results.py")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$root/tests/support/check.sh"

run=(run determinism --no-report -q --pictures all)
start=$SECONDS
"$curvebench" "${run[@]}" -j 1 -o "$work/one"
check "the run with one worker succeeds" test $? -eq 0
"$curvebench" "${run[@]}" -j 2 -o "$work/two"
check "the run with two workers succeeds" test $? -eq 0
"$curvebench" "${run[@]}" -j 2 --shuffle-points 20261206 -o "$work/shuffled"
check "the run on shuffled points succeeds" test $? -eq 0
echo "three runs: $((SECONDS - start)) s"

"$curvebench" list algorithms --names | sort >"$work/registry"
"$python" -c '
import csv, sys
print("\n".join(sorted({r["algorithm"] for r in csv.DictReader(open(sys.argv[1]))})))' "$work/one/results.csv" >"$work/ran"
check "every registered algorithm ran ($(wc -l <"$work/registry") of them)" diff "$work/registry" "$work/ran"
check "no job crashed or timed out (such a row says nothing of the output)" "$python" -c '
import collections, csv, sys
status = collections.Counter(r["status"] for r in csv.DictReader(open(sys.argv[1])))
print("statuses:", dict(status))
sys.exit(1 if status["crashed"] or status["timeout"] else 0)' "$work/one/results.csv"

check "one worker = two workers = two on shuffled points (results.csv, timings aside)" \
  "${compare[@]}" "$work/one/results.csv" "$work/two/results.csv" "$work/shuffled/results.csv"
check "the same pictures (every job's edges) in all three runs" \
  bash -c 'diff -rq "$1/pictures" "$2/pictures" && diff -rq "$1/pictures" "$3/pictures"' _ \
  "$work/one" "$work/two" "$work/shuffled"

# The comparison itself: a changed runtime is no difference; one changed field in one row
# (the Hausdorff distance, in its last digit), a row missing and a row twice are.
"$python" - "$work/one/results.csv" "$work" <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
header, body = rows[0], rows[1:]
h, t = header.index("hausdorff"), header.index("runtime_ms")
def write(name, body):
    with open(f"{sys.argv[2]}/{name}.csv", "w", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows([header] + body)
slower = [r[:] for r in body]
for r in slower:
    r[t] = "1e9"
write("slower", slower)
changed = [r[:] for r in body]
k = next(i for i, r in enumerate(changed) if r[h])
changed[k][h] = changed[k][h][:-1] + ("1" if changed[k][h][-1] != "1" else "2")
write("changed", changed)
write("missing", body[:-1])
write("doubled", body + [body[0]])
EOF
"${compare[@]}" "$work/one/results.csv" "$work/slower.csv" >/dev/null
check "compare_results: runtimes aside, a run is the same as itself" test $? -eq 0
"${compare[@]}" "$work/one/results.csv" "$work/changed.csv" >"$work/changed.out"
check "compare_results: one digit changed in one row is caught, and named" \
  bash -c '[[ $1 -eq 1 ]] && grep -q "differs in .*: hausdorff:" "$2" && grep -q "^1 rows differ" "$2"' _ $? "$work/changed.out"
"${compare[@]}" "$work/one/results.csv" "$work/missing.csv" >/dev/null
check "compare_results: a missing row is caught" test $? -eq 1
"${compare[@]}" "$work/one/results.csv" "$work/doubled.csv" >/dev/null
check "compare_results: a row twice is caught" test $? -eq 1
finish
