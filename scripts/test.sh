#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: the GoogleTest/RapidCheck suites,
# the fuzz corpus replays and benchmark smoke runs (ctest), then each libFuzzer target
# for FUZZ_SECONDS (default 60).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
(cd "$root/build" && ctest --output-on-failure -j"$(nproc)")
"$root/scripts/fuzz.sh" "${FUZZ_SECONDS:-60}"
