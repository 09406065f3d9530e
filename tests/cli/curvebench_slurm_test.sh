#!/usr/bin/env bash
# `curvebench slurm` on a real Slurm: a one-node cluster started here from Debian's
# slurm-wlm and munge (tests/cli/slurm_cluster.sh). A 4-task array of a small sweep and its
# dependent merge give the same results.csv as a run on this machine, runtimes aside; so
# does the same array with one task cancelled mid-run and resubmitted alone (it resumes).
# A one-line `sbatch --array` without --shard shards through SLURM_ARRAY_TASK_*.
# If Slurm cannot start here the test says why and fails: it never passes without Slurm.
# Usage: curvebench_slurm_test.sh PATH/TO/curvebench
set -uo pipefail
curvebench="$(realpath "$1")"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
python=/usr/bin/python3
work="$(mktemp -d)"
source "$here/../support/check.sh"
source "$here/slurm_cluster.sh"
trap 'stop_slurm_cluster; rm -rf "$work"' EXIT
start=$SECONDS

if ! start_slurm_cluster "$work/cluster"; then
  echo "FAILED: Slurm cannot start on this machine (see the reason above); the test needs it"
  exit 1
fi
echo "ok: a one-node Slurm cluster is up ($(sinfo -h -o '%N, %c CPUs') in $((SECONDS - start)) s)"

# Rows of a results.csv without the runtime column, which no two runs share.
rows_without_runtime() {
  "$python" -c '
import csv, sys
for r in csv.DictReader(open(sys.argv[1], newline="")):
    r.pop("runtime_ms")
    print(sorted(r.items()))' "$1"
}
# The states of a job's tasks once none is pending or running (the records stay for
# MinJobAge), or "timeout" after $2 seconds.
wait_for_job() {
  local job="$1" deadline=$((SECONDS + $2)) states
  while ((SECONDS < deadline)); do
    states="$(scontrol show job -o "$job" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | tr '\n' ' ')"
    [[ -n $states && ! $states =~ PENDING|RUNNING|CONFIGURING|COMPLETING|REQUEUE|SUSPENDED ]] && { echo "$states"; return; }
    sleep 0.5
  done
  echo timeout
}
# Job ids from the output of `curvebench slurm --submit`.
job_id() { awk -v what="$1" '$1 == what && $2 == "job" {print $3}' "$2"; }

# A small sweep: 200 curves x 3 epsilons x 3 algorithms = 1,800 jobs, about 10 s on 2 cores
# here, so that a task runs long enough to be cancelled mid-run.
sweep=(run sampling-full -a crust,nn-crust,hnn-crust --pictures failures)
"$curvebench" "${sweep[@]}" -o "$work/local" -j 2 -q --no-report 2>/dev/null
check "the sweep runs on this machine" test $? -eq 0

# The array and its merge, as `curvebench slurm --submit` writes and submits them.
"$curvebench" slurm "${sweep[@]}" -o "$work/cluster" --tasks 4 --submit >"$work/ids" 2>"$work/slurm.err"
check "slurm --submit prints the array and merge job ids" test -n "$(job_id array "$work/ids")" -a -n "$(job_id merge "$work/ids")"
grep -q '^#SBATCH --array=1-4$' "$work/cluster/slurm/array.sbatch" && grep -q '^#SBATCH --requeue$' "$work/cluster/slurm/array.sbatch" &&
  grep -q -- '--resume' "$work/cluster/slurm/array.sbatch"
check "the array script is a 4-task array that may be requeued and resumes" test $? -eq 0
array_states="$(wait_for_job "$(job_id array "$work/ids")" 150)"
merge_states="$(wait_for_job "$(job_id merge "$work/ids")" 60)"
check "every array task completed ($array_states)" test "$array_states" = "COMPLETED "
check "the merge job ran after them and completed ($merge_states)" test "$merge_states" = "COMPLETED "
check "4 shards through Slurm, merged = the local run (runtimes aside)" \
  diff <(rows_without_runtime "$work/local/results.csv") <(rows_without_runtime "$work/cluster/results.csv")
check "the merge job wrote the report" test -s "$work/cluster/report.html"

# The faults: task 2 cancelled mid-run, so that its merge never runs (afterok); task 3
# requeued mid-run, as a preempted task is, so that it starts again and resumes. Task 2
# resubmitted alone resumes its shard too, and a new merge gives the same table.
"$curvebench" slurm "${sweep[@]}" --no-report -o "$work/fault" --tasks 4 --submit >"$work/ids" 2>>"$work/slurm.err"
array="$(job_id array "$work/ids")"
# Waits until shard $1 has more than 5 rows.
wait_for_rows() {
  local csv="$work/fault/shard-$1/results.csv"
  for _ in $(seq 600); do
    [[ -f $csv && $(wc -l <"$csv") -gt 6 ]] && return
    sleep 0.1
  done
}
wait_for_rows 2
scancel "${array}_2"
wait_for_rows 3
scontrol requeue "${array}_3"
# A requeued job waits (BeginTime) a while before it may start again; here it need not.
sleep 1
scontrol update JobId="${array}_3" StartTime=now
array_states="$(wait_for_job "$array" 150)"
shard2="$work/fault/shard-2/results.csv"
rows_before=$(($(wc -l <"$shard2") - 1))
jobs2="$("$python" -c 'import json, sys; print(json.load(open(sys.argv[1]))["jobs"])' "$work/fault/shard-2/run.json")"
check "task 2 was cancelled mid-run ($rows_before of $jobs2 rows in; tasks: $array_states)" \
  test "$rows_before" -gt 0 -a "$rows_before" -lt "$jobs2" -a "$array_states" = "CANCELLED COMPLETED "
log3="$work/fault/slurm/logs/array-${array}_3.out"
requeued_and_resumed() { grep -q "DUE TO JOB REQUEUE" "$log3" && grep -Eq '\([1-9][0-9]* done before\)' "$log3"; }
check "task 3, requeued mid-run, started again and resumed: $(grep -o 'DUE TO JOB REQUEUE\|([0-9]* done before)' "$log3" | tr '\n' ' ')" \
  requeued_and_resumed
scancel "$(job_id merge "$work/ids")"  # waits on afterok forever: DependencyNeverSatisfied
"$curvebench" merge --no-report -o "$work/fault-early" "$work/fault"/shard-{1..4} 2>"$work/merge.err"
check "merge refuses the cut shard, by number: $(cat "$work/merge.err")" \
  grep -q "shard 2 has $rows_before of its $jobs2 jobs" "$work/merge.err"
again="$(sbatch --parsable --array=2 "$work/fault/slurm/array.sbatch")"
merge="$(sbatch --parsable --dependency="afterok:$again" "$work/fault/slurm/merge.sbatch")"
again_states="$(wait_for_job "$again" 120)"
merge_states="$(wait_for_job "$merge" 60)"
check "the resubmitted task and its merge completed ($again_states/ $merge_states)" \
  test "$again_states $merge_states" = "COMPLETED  COMPLETED "
check "the resubmitted task resumed: its log says $rows_before done before" \
  grep -q "($rows_before done before)" "$work/fault/slurm/logs/array-${again}_2.out"
check "cut, resubmitted and merged = the local run (runtimes aside)" \
  diff <(rows_without_runtime "$work/local/results.csv") <(rows_without_runtime "$work/fault/results.csv")

# One sbatch line, no --shard: each task takes its shard from SLURM_ARRAY_TASK_*.
sbatch --wait --array=1-2 -o "$work/env-%a.out" \
  --wrap "'$curvebench' run smoke -a nn-crust,emst -o '$work/env'-\$SLURM_ARRAY_TASK_ID -j 1 -q --no-report" >/dev/null
"$curvebench" run smoke -a nn-crust,emst -o "$work/env-local" -j 1 -q --no-report 2>/dev/null
"$curvebench" merge --no-report -o "$work/env" "$work/env-1" "$work/env-2" 2>/dev/null
check "an array without --shard shards by its task ids: $(grep -ho 'shard [0-9]/[0-9]' "$work"/env-*.out | tr '\n' ' ')" \
  diff <(rows_without_runtime "$work/env-local/results.csv") <(rows_without_runtime "$work/env/results.csv")

echo "slurm test: $((SECONDS - start)) s"
finish
