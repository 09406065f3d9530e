#!/usr/bin/env bash
# The external algorithms under examples/, as a user meets them: the C++ one built outside
# the tree with its own CMakeLists.txt, both declared by examples/algorithms.json, each run
# through `run` (scored against NN-Crust's theorem: every job of the sampling suite exact,
# as the built-in NN-Crust is) and through `hunt`.
# Usage: examples_test.sh PATH/TO/curvebench PATH/TO/examples
set -uo pipefail
curvebench="$1"
python=/usr/bin/python3
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/../support/check.sh"

# A copy, as a user would keep their own: {dir} in the file finds the programs beside it.
cp -r "$2" "$work/examples"
check "the C++ example builds outside the tree" \
  sh -c "cmake -S '$work/examples/cpp' -B '$work/examples/cpp/build' >'$work/cmake.log' 2>&1 &&
         cmake --build '$work/examples/cpp/build' >>'$work/cmake.log' 2>&1 || { cat '$work/cmake.log'; exit 1; }"

file="$work/examples/algorithms.json"
"$curvebench" run sampling --algorithm-file "$file" -a naive-nn-crust-py -a naive-nn-crust-cpp -a nn-crust -j 2 \
  --no-report -q --pictures none -o "$work/run"
check "both examples reconstruct exactly what the built-in NN-Crust does, which is every sampling within its theorem" "$python" -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
by = {}
for r in rows:
    by.setdefault(r["algorithm"], {})[(r["input"], r["level"])] = r
ok = sorted(by) == ["naive-nn-crust-cpp", "naive-nn-crust-py", "nn-crust"]
ok = ok and all(len(v) == 90 and all(r["status"] == "ok" for r in v.values()) for v in by.values())
ok = ok and all(by[a][job]["exact"] == r["exact"] for a in ("naive-nn-crust-py", "naive-nn-crust-cpp")
                for job, r in by["nn-crust"].items())
# NN-Crust theorem: every epsilon-sampling with epsilon < 1/3 (the safe sampler measures below 0.25).
ok = ok and all(r["exact"] == "1" for (_, level), r in by["nn-crust"].items() if level == "epsilon=0.25")
# Start-up beside the runtime for a program, none for a built-in.
ok = ok and all(float(r["startup_ms"]) > 0 for a in ("naive-nn-crust-py", "naive-nn-crust-cpp") for r in by[a].values())
ok = ok and all(r["startup_ms"] == "" for r in by["nn-crust"].values())
sys.exit(0 if ok else 1)' "$work/run/results.csv"

for algorithm in naive-nn-crust-py naive-nn-crust-cpp; do
  "$curvebench" hunt --algorithm-file "$file" -a "$algorithm" --seconds 10 --json -o "$work/hunt-$algorithm" \
    >"$work/hunt-$algorithm.json"
  check "hunt runs $algorithm, and each finding has its replay" "$python" -c '
import json, os, sys
h = json.load(open(sys.argv[1]))
sys.exit(0 if h["cases"] > 0 and all(os.path.exists(f["replay"]) for f in h["findings"]) else 1)' "$work/hunt-$algorithm.json"
done

# A parameter from the file reaches the program. On a hexagon the paper's 90 degrees give
# the built-in NN-Crust's 6-cycle; at 180 degrees no point has a half neighbour, and the
# nearest-neighbour edges alone form a forest: at most 5 edges.
printf '2 0\n1 1.8\n-1 1.7\n-2 0.1\n-1 -1.75\n1 -1.8\n' >"$work/hexagon.xy"
"$curvebench" reconstruct -a nn-crust -i "$work/hexagon.xy" -o "$work/builtin.edges" -q
"$curvebench" reconstruct --algorithm-file "$file" -a naive-nn-crust-cpp -i "$work/hexagon.xy" -o "$work/90.edges" -q
"$curvebench" reconstruct --algorithm-file "$file" -a naive-nn-crust-cpp -p half_angle=180 -i "$work/hexagon.xy" \
  -o "$work/180.edges" -q
check "the hexagon's 6-cycle at 90 degrees, as the built-in NN-Crust's" \
  test "$(wc -l <"$work/builtin.edges")" -eq 6 -a "$(cat "$work/90.edges")" = "$(cat "$work/builtin.edges")"
check "at most 5 edges at 180 degrees" test "$(wc -l <"$work/180.edges")" -le 5
finish
