# Sourced by the shell tests: `check DESCRIPTION COMMAND...` runs a check that must
# succeed and counts the failures; `finish` prints the closing line and exits non-zero if
# any check failed.
failures=0
check() {
  local what="$1"; shift
  if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; failures=$((failures + 1)); fi
}
finish() {
  echo "$((failures == 0 ? 1 : 0)) passed, $failures failed"
  exit $((failures > 0))
}
