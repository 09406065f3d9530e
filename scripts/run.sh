#!/usr/bin/env bash
# The main job on bundled data: the benchmark's `default` suite (every registered algorithm
# on sampled curves, lfs noise, outliers, the sharp-corner family and the bundled point
# sets), scored and charted in out/default/report.html.
#   scripts/run.sh [SUITE [OUTPUT_DIR]]    another suite (`curvebench list suites`), elsewhere
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh" run

suite="${1:-default}"
out="${2:-$root/out/$suite}"
# A fresh run each time; `curvebench run --resume` continues an interrupted one instead.
rm -rf "$out"
"$root/build/bench/curvebench" run "$suite" -o "$out"
echo "open $out/report.html in a browser"
