#!/usr/bin/env bash
# The glyph sweep at one epsilon (every DejaVu Sans glyph x every algorithm, as
# `curvebench rate -o`) run twice on this machine: locally with -j 2, and through Slurm as
# an array of TASKS tasks on a one-node cluster started here as the test does
# (tests/cli/slurm_cluster.sh; needs root, slurm-wlm and munge). Prints both wall times and
# checks that the two tables and results.csv agree, runtimes aside (scripts/compare_results.py).
#   scripts/slurm_glyph_sweep.sh [DIR]     (default out/glyph-sweep; written anew)
# Environment: EPSILON (0.4), TASKS (8), STRIDE (1: every glyph; 100 for a quick try).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
curvebench="$root/build/bench/curvebench"
[[ -x $curvebench ]] || { echo "build curvebench first: scripts/build.sh run" >&2; exit 2; }
dir="$(realpath -m "${1:-out/glyph-sweep}")"
epsilon="${EPSILON:-0.4}" tasks="${TASKS:-8}" stride="${STRIDE:-1}"
rate=(rate -c 'glyph:*' -e "$epsilon" --stride "$stride")
rm -rf "$dir" && mkdir -p "$dir"

start=$SECONDS
"$curvebench" "${rate[@]}" -o "$dir/local" -j 2 -q >"$dir/local.txt"
local_seconds=$((SECONDS - start))

source "$root/tests/cli/slurm_cluster.sh"
trap stop_slurm_cluster EXIT
start_slurm_cluster "$dir/cluster"
start=$SECONDS
"$curvebench" slurm "${rate[@]}" -o "$dir/slurm" --tasks "$tasks" --submit >"$dir/ids"
merge="$(awk '$1 == "merge" {print $3}' "$dir/ids")"
# The merge job's record stays MinJobAge seconds after it ends.
while scontrol show job -o "$merge" | grep -Eq 'JobState=(PENDING|RUNNING|CONFIGURING|COMPLETING)'; do sleep 1; done
slurm_seconds=$((SECONDS - start))
scontrol show job -o "$merge" | grep -q JobState=COMPLETED || { echo "the merge job failed: see $dir/slurm/slurm/logs" >&2; exit 1; }

diff "$dir/local.txt" "$dir/slurm/rate.txt" && echo "the same table"
/usr/bin/python3 "$root/scripts/compare_results.py" "$dir/local/results.csv" "$dir/slurm/results.csv"
cat "$dir/local.txt"
echo "glyphs every $stride at epsilon $epsilon: locally -j 2: $local_seconds s; Slurm, $tasks tasks of 1 CPU on $(nproc) cores: $slurm_seconds s"
