#!/usr/bin/env bash
# Loads DIR/report.html (bench/report/make_report.py) in headless Chromium and fails when an
# image or chart did not load, when the page has no chart, or when Chromium fails.
# The page's own script writes its counts into <div id="image-check" data-total data-broken
# data-charts data-broken-src>; this reads them from the dumped DOM.
# Usage: scripts/check_report.sh DIR [--screenshot FILE.png]
set -euo pipefail

usage() { echo "usage: $0 DIR [--screenshot FILE.png]" >&2; exit 2; }
fail() { echo "check_report: $*" >&2; exit 1; }

dir="" screenshot=""
while (($#)); do
  case "$1" in
    --screenshot) (($# >= 2)) || usage; screenshot="$2"; shift 2 ;;
    --screenshot=*) screenshot="${1#*=}"; shift ;;
    -*) usage ;;
    *) [[ -z "$dir" ]] || usage; dir="$1"; shift ;;
  esac
done
[[ -n "$dir" ]] || usage
[[ -f "$dir/report.html" ]] || fail "$dir/report.html not found"
command -v chromium >/dev/null || fail "chromium not installed (scripts/setup.sh installs it)"

url="$(/usr/bin/python3 -c 'import pathlib, sys; print(pathlib.Path(sys.argv[1]).resolve().as_uri())' "$dir/report.html")"
profile="$(mktemp -d)"  # a fresh profile, so parallel runs do not share one
trap 'rm -rf "$profile"' EXIT
# As root Chromium refuses to start without --no-sandbox; the virtual time budget lets
# every image load and the page's load handler run before the DOM is dumped.
flags=(--headless --no-sandbox --disable-gpu --virtual-time-budget=10000 --no-first-run
       --user-data-dir="$profile/data")

# Headless Chromium now and then hangs after its work is done (a zygote that never answers,
# seen once in CI under a full ctest load), so a run that times out is retried, up to three
# times, each on a fresh profile; any other failure fails at once.
chromium_run() {  # chromium_run ARGS...: stdout is the result; stderr goes to a log shown on failure
  local status attempt
  for attempt in 1 2 3; do
    status=0
    rm -rf "$profile/data"
    timeout -k 5 90 chromium "${flags[@]}" "$@" >"$profile/stdout" 2>"$profile/stderr" || status=$?
    ((status == 124 || status == 137)) || break
    echo "check_report: chromium timed out (attempt $attempt of 3)" >&2
  done
  if ((status)); then tail -n 20 "$profile/stderr" >&2; fail "chromium failed (exit $status) on $url"; fi
  cat "$profile/stdout"  # only a finished run's output, never a timed-out one's
}

dom="$(chromium_run --dump-dom "$url")"
element="$(grep -o '<div id="image-check"[^>]*>' <<<"$dom" || true)"
[[ -n "$element" ]] || fail "no image-check element in the page (not a make_report.py report?)"
attribute() { sed -n "s/.* $1=\"\\([^\"]*\\)\".*/\\1/p" <<<"$element"; }
[[ "$(attribute data-state)" == done ]] || fail "the page's image check did not run"
total="$(attribute data-total)" broken="$(attribute data-broken)" charts="$(attribute data-charts)"

if [[ -n "$screenshot" ]]; then
  rm -f "$screenshot"
  chromium_run --screenshot="$screenshot" --window-size=1400,2400 "$url" >/dev/null
  [[ -s "$screenshot" ]] || fail "chromium wrote no screenshot to $screenshot"
fi

echo "report: $total images, $broken broken, $charts charts"
((broken == 0)) || fail "broken images: $(attribute data-broken-src)"
((charts > 0)) || fail "the report has no chart"
