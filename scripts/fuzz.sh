#!/usr/bin/env bash
# Runs every libFuzzer target of curvebench for a while: the crash hunt CI runs, and the
# way a person grows the committed seed corpora.
#
#   scripts/fuzz.sh [SECONDS] [NAME...] fuzz each target (or the NAMEd ones) SECONDS
#                                      (default: $FUZZ_SECONDS, else 60)
#   scripts/fuzz.sh --merge [SECONDS]  the same, then add to fuzz/corpus/NAME/ the fewest
#                                      new inputs that reach code the corpus does not
#                                      (edges, not hit counts, so the corpus stays small)
#   --jobs N                           targets side by side (default: one per core); a
#                                      campaign in the background takes --jobs 1
#
# Builds the clang tree build-fuzz/ (packages: scripts/setup.sh; nothing is installed
# here), finds the targets in it (fuzz/fuzz_NAME), and runs them one after another. New
# inputs go to a temporary directory placed before the committed corpus fuzz/corpus/NAME/,
# which is only read, so a run leaves the repository as it was (unless --merge). Targets
# run side by side, one per core (libFuzzer is single-threaded), so CI's minute per
# target costs a minute per core count.
# Per-target libFuzzer flags (max_len, ...) come from fuzz/NAME.options (`key = value`
# lines, as in OSS-Fuzz), a dictionary from fuzz/NAME.dict. Findings and each target's log go to
# build-fuzz/artifacts/NAME/. Prints one line per target (runs, wall and CPU seconds);
# exits 1 if any found something.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-fuzz
seconds=${FUZZ_SECONDS:-60}
merge=false
jobs=$(nproc)
names=()
while (($# > 0)); do
  case $1 in
    --merge) merge=true ;;
    --jobs) jobs=${2:-}; shift ;;
    *[!a-z_]* | '') [[ $1 =~ ^[0-9]+$ ]] || { echo "usage: $0 [--merge] [--jobs N] [SECONDS] [NAME...]" >&2; exit 2; }
      seconds=$1 ;;
    *) names+=("$1") ;;
  esac
  shift
done
[[ $jobs =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: --jobs takes a positive number" >&2; exit 2; }

# ASan's default quarantine (256 MB of freed memory held back to catch use-after-free)
# inflated reconstruction's resident memory, with its many small exact-number allocations:
# 1.2 GB after loading the corpus (0.85 GB with freed memory released to the OS each second,
# 0.26 GB with a 16 MB quarantine), past the 2 GB guard in 19 minutes, while its live heap
# was 57 MB. With 32 MB it started at 0.39 GB and peaked at 0.87 GB in 25 minutes; 32 MB
# still spans far more than one input's lifetime, which is all a use-after-free here needs.
export ASAN_OPTIONS=${ASAN_OPTIONS:-quarantine_size_mb=32}

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

if ! { CXX=clang++-14 cmake -S "$root" -B "$build" -G Ninja -DCURVEBENCH_FUZZ=ON &&
  cmake --build "$build" -j "$(nproc)"; } >"$scratch/build.log" 2>&1; then
  cat "$scratch/build.log" >&2
  exit 1
fi

# The libFuzzer flags for target $1, one per line.
flags_for() {
  local name=$1 key value
  printf '%s\n' -timeout=10 -rss_limit_mb=2048 "-artifact_prefix=$build/artifacts/$name/"
  if [[ -f $root/fuzz/$name.options ]]; then
    while IFS='=' read -r key value; do
      key=${key//[[:space:]]/} value=${value//[[:space:]]/}
      [[ -n $key && $key != \[* && $key != \#* ]] && printf -- '-%s=%s\n' "$key" "$value"
    done <"$root/fuzz/$name.options"
  fi
  if [[ -f $root/fuzz/$name.dict ]]; then printf -- '-dict=%s\n' "$root/fuzz/$name.dict"; fi
}

# Fuzzes one target; prints its summary line and returns 1 on a finding.
fuzz_target() {
  local binary=$1 name=${1##*/fuzz_}
  local corpus=$root/fuzz/corpus/$name new=$scratch/$name log=$build/artifacts/$name/fuzz.log
  local -a flags seeds=()
  mapfile -t flags < <(flags_for "$name")
  if $merge; then mkdir -p "$corpus"; fi
  if [[ -d $corpus ]]; then seeds=("$corpus"); fi
  mkdir -p "$new" "$build/artifacts/$name"

  # libFuzzer's budget is wall time; CPU time (bash's `time`: user and system seconds)
  # is what a campaign is measured in, since a starved fuzzer runs fewer inputs.
  local TIMEFORMAT='%0U s user + %0S s system' cpu=$scratch/$name.cpu
  if ! { time "$binary" "${flags[@]}" -max_total_time="$seconds" "$new" "${seeds[@]}" >"$log" 2>&1; } 2>"$cpu"; then
    local finding
    finding=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -n 1)
    echo "fuzz $name: FINDING ${finding:-(no input saved)}, CPU $(<"$cpu"), log $log"
    tail -n 40 "$log" | sed 's/^/    /' >&2
    if [[ -n $finding ]]; then echo "    reproduce: $binary $finding" >&2; fi
    return 1
  fi
  local done_line
  done_line=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1 runs in \2 s/p' "$log")
  echo "fuzz $name: ${done_line:-? runs}, CPU $(<"$cpu"), no finding"

  if $merge; then
    local before after
    before=$(find "$corpus" -type f | wc -l)
    "$binary" "${flags[@]}" -merge=1 -use_counters=0 "$corpus" "$new" >>"$log" 2>&1
    after=$(find "$corpus" -type f | wc -l)
    echo "fuzz $name: merged $((after - before)) new inputs into fuzz/corpus/$name/"
  fi
}

status=0
mapfile -t targets < <(find "$build/fuzz" -maxdepth 1 -type f -name 'fuzz_*' -perm -u+x | sort)
if ((${#targets[@]} == 0)); then echo "fuzz: no fuzz_* target in $build/fuzz" >&2; exit 1; fi
if ((${#names[@]} > 0)); then
  chosen=()
  for name in "${names[@]}"; do
    [[ -x $build/fuzz/fuzz_$name ]] || { echo "fuzz: no target $name in $build/fuzz" >&2; exit 2; }
    chosen+=("$build/fuzz/fuzz_$name")
  done
  targets=("${chosen[@]}")
fi
running=0
for binary in "${targets[@]}"; do
  if ((running == jobs)); then wait -n || status=1; ((running--)); fi
  fuzz_target "$binary" &
  ((++running))
done
while ((running > 0)); do wait -n || status=1; ((running--)); done
exit $status
