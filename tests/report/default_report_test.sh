#!/usr/bin/env bash
# The main job's report as a person sees it: runs the `default` suite, then loads its
# report.html in headless Chromium (scripts/check_report.sh), which fails if any chart or
# reconstruction picture is missing or broken. Keeps a screenshot in the build tree.
# Usage: default_report_test.sh PATH/TO/curvebench SCREENSHOT.png
set -euo pipefail
curvebench="$1" screenshot="$2"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# A 20 s limit instead of the default minute: only Optimal Transport's 10^5-point runtime
# job reaches it, and its timeout row is in the report either way.
"$curvebench" run default -o "$work/default" -q --timeout 20
"$root/scripts/check_report.sh" "$work/default" --screenshot "$screenshot"
