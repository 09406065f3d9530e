#!/usr/bin/env bash
# Installs what is missing, then configures and builds curvebench (Release) in build/.
#   scripts/build.sh        everything: the command, tests, benchmarks, fuzz replays
#   scripts/build.sh run    only the `curvebench` command (and the libraries it links), so
#                           that the main job starts after a third of the build
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scope="${1:-test}"
case "$scope" in
  run) options=(-DCURVEBENCH_TESTS=OFF -DCURVEBENCH_BENCHMARKS=OFF) targets=(--target curvebench) ;;
  test) options=(-DCURVEBENCH_TESTS=ON -DCURVEBENCH_BENCHMARKS=ON) targets=() ;;
  *) echo "usage: $0 [run|test]" >&2; exit 2 ;;
esac
"$root/scripts/setup.sh" "$scope"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${options[@]}" >/dev/null
cmake --build "$root/build" -j"$(nproc)" "${targets[@]}"
