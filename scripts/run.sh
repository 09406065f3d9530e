#!/usr/bin/env bash
# The main job on bundled data: every proximity graph of a bundled curve sample, each
# written as an edge list and an SVG picture under out/graphs/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"

input="${1:-$root/data/hnncrust/crocodile-conf.p2d}"
out="$root/out/graphs"
mkdir -p "$out"
curvebench="$root/build/bench/curvebench"
for kind in $("$curvebench" list graphs --names); do
  "$curvebench" graph "$kind" -i "$input" -o "$out/$kind.edges" --svg "$out/$kind.svg"
  echo "$kind: $(wc -l <"$out/$kind.edges") edges -> $out/$kind.svg"
done
