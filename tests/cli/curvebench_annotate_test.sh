#!/usr/bin/env bash
# Checks `curvebench annotate` and `curvebench make-input` without a browser: the page holds
# the points (kept ones, with their input numbering when duplicates merge) and the existing
# edges, a bad point or edge file is a one-line error, and make-input writes a job's input.
# The page itself is driven in Chromium by tests/browser/annotate_test.py.
# Usage: curvebench_annotate_test.sh PATH/TO/curvebench
set -uo pipefail
curvebench="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/../support/check.sh"
page_data() {  # the JSON the page embeds, pretty-printed with sorted keys
  /usr/bin/python3 -c 'import json, re, sys
text = open(sys.argv[1]).read()
block = re.search(r"<script type=\"application/json\" id=\"data\">(.*?)</script>", text, re.S).group(1)
print(json.dumps(json.loads(block), sort_keys=True))' "$1"
}

printf '0 0\n1 0\n1 1\n0 1\n' >"$work/square.xy"
printf '0 1\n1 2\n' >"$work/square.edges"
"$curvebench" annotate -i "$work/square.xy" -e "$work/square.edges" -o "$work/page" >"$work/out"
check "annotate exits 0 and prints the page's path" grep -qx "$work/page/square.annotate.html" "$work/out"
check "the page embeds the points and edges" test "$(page_data "$work/page/square.annotate.html")" = \
  '{"edges": [0, 1, 1, 2], "input_points": 4, "name": "square.xy", "points": [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0], "stem": "square"}'
check "the page needs no network" bash -c "! grep -qE '(src|href)=\"(https?:)?//' '$work/page/square.annotate.html'"

# A duplicate is merged: the page draws 3 points and saves the input's numbering (0, 1, 3).
printf '0 0\n1 0\n0 0\n0 1\n' >"$work/dup.xy"
"$curvebench" annotate -i "$work/dup.xy" -o "$work/page" >/dev/null 2>"$work/err"
check "duplicates: a note on stderr" grep -q "dup.xy:3: duplicate of the point on line 1, merged" "$work/err"
check "duplicates: kept points with their input indices" bash -c \
  "[[ '$(page_data "$work/page/dup.annotate.html")' == *'\"input_index\": [0, 1, 3]'* ]]"

# A malformed point file: status 2, one line naming file and line, no page.
printf '0 0\n1 x\n' >"$work/bad.xy"
"$curvebench" annotate -i "$work/bad.xy" -o "$work/page" 2>"$work/err"
check "a malformed point file exits with status 2" test $? -eq 2
check "its one line names file and line" grep -qx "curvebench: $work/bad.xy:2: .*" "$work/err"
check "no page for it" test ! -e "$work/page/bad.annotate.html"

printf '0 9\n' >"$work/far.edges"
"$curvebench" annotate -i "$work/square.xy" -e "$work/far.edges" -o "$work/page" 2>"$work/err"
check "an edge beyond the points exits with status 2" test $? -eq 2
check "and says so" grep -q "far.edges: edge 0 9 names a point beyond the 4 of the point file" "$work/err"
printf '0 1\n1 x\n' >"$work/bad.edges"
"$curvebench" annotate -i "$work/square.xy" -e "$work/bad.edges" -o "$work/page" 2>"$work/err"
check "a malformed edge file names its line" grep -q "bad.edges:2: " "$work/err"

# make-input: a job's input as results.csv names it, with its ground truth.
"$curvebench" make-input 'circle:r=1|uniform=12' -o "$work/circle" >/dev/null
check "make-input writes the 12 points" test "$(wc -l <"$work/circle.xy")" -eq 12
check "make-input writes the 12 ground-truth edges" test "$(wc -l <"$work/circle.edges")" -eq 12
"$curvebench" make-input 'circle:r=1|bogus=3' -o "$work/bogus" 2>"$work/err"
check "make-input rejects a malformed name" test $? -eq 2

finish
