#!/usr/bin/env bash
# Checks bench/report/make_report.py and scripts/check_report.sh on synthetic results.csv
# files: charts, summary tables, gallery (cap, failures first and highlighted), the non-ok
# table, HTML escaping, a header-only and an all-failures file, and that the headless
# Chromium check fails on a missing chart. Expected counts are kept while writing the rows.
# Usage: report_test.sh [WORKDIR]   (WORKDIR keeps the reports and report.png; default: a temp dir)
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
make_report=(/usr/bin/python3 "$root/bench/report/make_report.py")
check_report="$root/scripts/check_report.sh"
if (($#)); then
  work="$1"
  rm -rf "$work/run" "$work/empty" "$work/failures"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
source "$root/tests/support/check.sh"
count() { grep -o -- "$1" "$2" | wc -l; }  # count PATTERN FILE: occurrences, not lines

header="job,suite,input,level,algorithm,params,n_points,status,exact,hausdorff,rms,normal_deviation,manifold,components,open_components,closed_components,unconnected,runtime_ms,picture,message"
csv_field() {  # RFC 4180: quote fields holding a comma or a quote
  if [[ "$1" == *[,\"]* ]]; then printf '"%s"' "${1//\"/\"\"}"; else printf '%s' "$1"; fi
}

# ---- a run with three suites: levels, no levels, no ground truth, failures of every kind
run="$work/run"
mkdir -p "$run/pictures"
echo "$header" >"$run/results.csv"
job=0 nonok=0
declare -A pictured=() highlighted=()
# row SUITE INPUT LEVEL ALGORITHM PARAMS STATUS EXACT RMS RUNTIME_MS PICTURE(y/n) MESSAGE
# EXACT and RMS empty = no ground truth; every metric is left empty when STATUS is not ok.
row() {
  local suite="$1" input="$2" level="$3" algorithm="$4" params="$5" status="$6" exact="$7" rms="$8"
  local runtime="$9" picture_flag="${10}" message="${11}" metrics picture=""
  if [[ "$status" == ok ]]; then
    local hausdorff="" deviation=""
    [[ -n "$rms" ]] && hausdorff="$(awk -v r="$rms" 'BEGIN { print 3 * r }')" deviation=2.5
    metrics="$exact,$hausdorff,$rms,$deviation,$([[ "$exact" == 0 ]] && echo 0 || echo 1),1,0,1,0,$runtime"
  else
    metrics=",,,,,,,,,"
    nonok=$((nonok + 1))
  fi
  if [[ "$picture_flag" == y ]]; then
    picture="$(printf 'pictures/%06d.svg' "$job")"
    printf '<svg xmlns="http://www.w3.org/2000/svg" width="120" height="120" viewBox="0 0 12 12"><circle cx="6" cy="6" r="5" fill="none" stroke="black"/><text x="2" y="7" font-size="3">%d</text></svg>\n' \
      "$job" >"$run/$picture"
    pictured[$suite]=$((${pictured[$suite]:-0} + 1))
    [[ "$status" != ok || "$exact" == 0 ]] && highlighted[$suite]=$((${highlighted[$suite]:-0} + 1))
  fi
  printf '%s\n' "$job,$suite,$(csv_field "$input"),$level,$algorithm,$(csv_field "$params"),$((50 + job)),$status,$metrics,$picture,$(csv_field "$message")" \
    >>"$run/results.csv"
  job=$((job + 1))
}

# sampling: 4 algorithms x 3 epsilons x 2 curves; sparse sampling breaks EMST and NN-Crust.
declare -A runtime_of=([crust]=1.8 [nn-crust]=0.4 [hnn-crust]=2.3 [emst]=0.05 [alpha-shape]=60 [beta-skeleton]=900 [gathan]=0.9)
for e in 0.25 0.5 0.75; do
  for curve in simple bunny; do
    for a in crust nn-crust hnn-crust emst; do
      input="svg:data/svg/$curve.svg|epsilon=$e"
      if [[ "$a/$curve/$e" == hnn-crust/bunny/0.75 ]]; then
        row sampling "$input" "epsilon=$e" "$a" "" failed "" "" "" n 'no manifold: "3 collinear" points, skipped'
      elif [[ "$e" == 0.75 && ( "$a" == emst || "$a/$curve" == nn-crust/bunny ) ]]; then
        row sampling "$input" "epsilon=$e" "$a" "" ok 0 3.5 "${runtime_of[$a]}" y ""
      else
        row sampling "$input" "epsilon=$e" "$a" "" ok 1 "0.00${#a}$((job % 9 + 1))" "${runtime_of[$a]}" y ""
      fi
    done
  done
done
# outliers: 3 algorithms x 3 shares; at 20 % alpha-shape crashes and beta-skeleton times out.
for p in 5 10 20; do
  for a in crust alpha-shape beta-skeleton; do
    params=""
    [[ "$a" == alpha-shape ]] && params="alpha=1.5"
    [[ "$a" == beta-skeleton ]] && params="beta=1.2,lune=1"
    input="file:data/hnncrust/mushroom.p2d|outliers=$p"
    if [[ "$a/$p" == alpha-shape/20 ]]; then
      row outliers "$input" "outliers=$p" "$a" "$params" crashed "" "" "" n 'signal 11 (SIGSEGV) in <alpha_shape> & "friends"'
    elif [[ "$a/$p" == beta-skeleton/20 ]]; then
      row outliers "$input" "outliers=$p" "$a" "$params" timeout "" "" "" y "exceeded 10000 ms"
    else
      row outliers "$input" "outliers=$p" "$a" "$params" ok "$([[ $p == 5 ]] && echo 1 || echo 0)" "0.0$p" "${runtime_of[$a]}" y ""
    fi
  done
done
# runtime: no level, no ground truth, 60 pictures (more than the gallery cap of 48).
for i in $(seq -w 1 12); do
  for a in crust nn-crust hnn-crust emst gathan; do
    row runtime "file:data/classic/c$i.p2d" "" "$a" "" ok "" "" "${runtime_of[$a]}" y ""
  done
done
algorithms=(crust nn-crust hnn-crust emst alpha-shape beta-skeleton gathan)

check "make_report succeeds" "${make_report[@]}" "$run"
html="$run/report.html"
for chart in status runtime rms-sampling exact-sampling rms-outliers exact-outliers; do
  check "chart $chart.svg is an SVG" grep -q "<svg" "$run/charts/$chart.svg"
done
check "no RMS chart for a suite without ground truth" test ! -e "$run/charts/rms-runtime.svg"
for a in "${algorithms[@]}"; do
  check "the summary tables name $a" grep -qF "</span>$a</td>" "$html"
done
expected_gallery=0 expected_highlighted=0
for s in "${!pictured[@]}"; do
  expected_gallery=$((expected_gallery + (pictured[$s] < 48 ? pictured[$s] : 48)))
  expected_highlighted=$((expected_highlighted + ${highlighted[$s]:-0}))
done
check "gallery has $expected_gallery pictures" test "$(count '<figure class="shot' "$html")" -eq "$expected_gallery"
check "$expected_highlighted pictures are highlighted" test "$(count '<figure class="shot fail"' "$html")" -eq "$expected_highlighted"
check "every highlighted picture says why" test "$(count '<span class="why">' "$html")" -eq "$expected_highlighted"
# Within each suite's gallery no highlighted picture may follow a plain one.
check "failures come first in every gallery" awk '
  /id="suite-/ { plain = 0 }
  /class="shot fail"/ { if (plain) exit 1 }
  /class="shot"/ { plain = 1 }' < <(grep -oE 'id="suite-[^"]*"|<figure class="shot[^"]*"' "$html")
check "non-ok table has $nonok rows" test "$(count '<tr class="nonok">' "$html")" -eq "$nonok"
check "messages are HTML-escaped" grep -qF '&lt;alpha_shape&gt; &amp; &quot;friends&quot;' "$html"
check "no raw markup from messages" bash -c '! grep -qF "<alpha_shape>" "$1"' _ "$html"
check "job count is stated" grep -qF "<b>$job</b> jobs" "$html"

# ---- summary.csv: a row per suite, level and algorithm, counted as the rows were written
summary="$run/summary.csv"
check "summary.csv has its header" bash -c 'head -n 1 "$1" | grep -q "^suite,level,algorithm,jobs,exact_k,exact_n,"' _ "$summary"
cell() { grep "^$1,$2,$3," "$summary" | cut -d, -f"$4"; }  # cell SUITE LEVEL ALGORITHM FIELD
check "EMST at epsilon 0.75: 0 of 2 exact" test "$(cell sampling epsilon=0.75 emst 5-6)" = "0,2"
check "HNN-Crust at 0.75: its failure counts as not exact" test "$(cell sampling epsilon=0.75 hnn-crust 5-6)" = "1,2"
check "summary rows: one per cell" test "$(($(wc -l <"$summary") - 1))" -eq $((3 * 4 + 3 * 3 + 5))
check "summary.json holds the same cells, typed" /usr/bin/python3 -c "
import csv, json, sys
rows = list(csv.DictReader(open('$summary')))
cells = json.load(open('$run/summary.json'))
emst = next(c for c in cells if (c['suite'], c['level'], c['algorithm']) == ('sampling', 'epsilon=0.75', 'emst'))
sys.exit(not (len(cells) == len(rows) and emst['exact_k'] == 0 and emst['exact_n'] == 2 and emst['exact_high'] > 60))"
check "summary table shows exact with its interval" grep -qF "0% [0–66] of 2" "$html"
check "the first screen is the algorithm x experiment matrix" grep -qF "<h2>Algorithms × experiments</h2>" "$html"

# ---- the headless check: passes as written, fails without a chart, passes again
check "check_report passes and writes a screenshot" "$check_report" "$run" --screenshot "$work/report.png"
check "the screenshot is a PNG" bash -c 'head -c 8 "$1" | grep -q PNG' _ "$work/report.png"
mv "$run/charts/rms-outliers.svg" "$work/rms-outliers.svg"
"$check_report" "$run" >"$work/check.out" 2>&1
check "check_report fails on a missing chart" test $? -eq 1
check "and names the missing chart" grep -qF "charts/rms-outliers.svg" "$work/check.out"
mv "$work/rms-outliers.svg" "$run/charts/rms-outliers.svg"
check "check_report passes with the chart back" "$check_report" "$run"

# ---- a header-only file
mkdir -p "$work/empty"
echo "$header" >"$work/empty/results.csv"
check "make_report succeeds on a header-only file" "${make_report[@]}" "$work/empty"
check "the empty report says so" grep -qF "No jobs" "$work/empty/report.html"

# ---- only failures, one row cut short after its status
mkdir -p "$work/failures"
{ echo "$header"
  echo "0,fuzz,file:a.p2d,,crust,,3,crashed,,,,,,,,,,,,signal 6"
  echo "1,fuzz,file:b.p2d,,emst,,4,timeout"; } >"$work/failures/results.csv"
check "make_report succeeds on failures only" "${make_report[@]}" "$work/failures"
check "both failures are listed" test "$(count '<tr class="nonok">' "$work/failures/report.html")" -eq 2
check "check_report passes on a report of failures" "$check_report" "$work/failures"

# ---- the Wilson score interval against published values (Newcombe 1998, method 3: 81 of
# 263 gives 25.53 to 36.62 %; 15 of 148 gives 6.24 to 16.05 %) and its edge cases
wilson() {  # wilson K N LOW HIGH: the interval of K of N, to 0.05 percentage points
  (cd "$root/bench/report" && /usr/bin/python3 -c "
import sys, make_report
k, n, low, high = make_report.wilson([True] * $1 + [False] * ($2 - $1))
sys.exit(not (k == $1 and n == $2 and abs(low - $3) < 0.05 and abs(high - $4) < 0.05))")
}
check "Wilson 81 of 263" wilson 81 263 25.53 36.62
check "Wilson 15 of 148" wilson 15 148 6.24 16.05
check "Wilson 0 of 10 starts at 0" wilson 0 10 0 27.8
check "Wilson 10 of 10 ends at 100" wilson 10 10 72.2 100
# Student-t interval of a mean: 1..5 has mean 3, s = 1.5811, t(4) = 2.7764: 3 -+ 1.9632.
mean_ci() {  # mean_ci VALUES MEAN LOW HIGH
  (cd "$root/bench/report" && /usr/bin/python3 -c "
import sys, make_report
m, n, low, high = make_report.mean_interval([$1])
sys.exit(not (abs(m - $2) < 1e-3 and abs(low - $3) < 1e-3 and abs(high - $4) < 1e-3))")
}
check "mean interval of 1..5" mean_ci "1, 2, 3, 4, 5" 3 1.0368 4.9632
check "mean interval of 2, 4 (t(1) = 12.706)" mean_ci "2, 4" 3 -9.706 15.706
check "t quantiles beyond the table (df 60: 2.0003, df 120: 1.9799)" /usr/bin/python3 -c "import sys; sys.path.insert(0, '$root/bench/report'); import make_report as m; sys.exit(not (abs(m.t975(60) - 2.0003) < 2e-4 and abs(m.t975(120) - 1.9799) < 2e-4))"
# McNemar's exact test: b = 10, c = 0 gives 2 / 2^10; b = 8, c = 2 gives 2 (1 + 10 + 45) / 2^10.
check "McNemar p-values" /usr/bin/python3 -c "import sys; sys.path.insert(0, '$root/bench/report'); import make_report as m; sys.exit(not (abs(m.mcnemar(10, 0) - 2 / 1024) < 1e-12 and abs(m.mcnemar(2, 8) - 0.109375) < 1e-12 and m.mcnemar(5, 5) == 1 and m.mcnemar(0, 0) == 1))"
# The leaders: A exact on 20 instances, B on the first 10 (p = 0.002: not a leader), C on 19 (p = 1: a leader).
check "leaders by McNemar" /usr/bin/python3 -c "
import sys; sys.path.insert(0, '$root/bench/report'); import make_report as m
rows = [{'input': str(i), 'level': '', 'algorithm': a, '_exact': ok} for i in range(20)
        for a, ok in (('A', True), ('B', i < 10), ('C', i != 5))]
result, best = m.leaders(rows, ['A', 'B', 'C'], '_exact')
sys.exit(not (best == 'A' and result['B'][1] < 0.05 and result['C'][1] >= 0.05 and result['A'][0][:2] == (20, 20)))"
# Beside the survey: on open-curves, VICUR (the survey's best) exact on 20 of 20 and Crust on 8 agrees; Crust on 20
# and VICUR on 8 (McNemar p = 2 / 2^12) differs; Crust on 19 ties with it, which ranks nothing. EMST, exact on all,
# is not among the survey's algorithms and does not count. On intersecting, a best of 2 of 20 ([2.8–30.1]%) overlaps
# the survey's 3 of 26 ([4.0–29.0]%); 20 of 20 ([83.9–100]%) does not.
check "survey comparison verdicts" /usr/bin/python3 -c "
import sys; sys.path.insert(0, '$root/bench/report'); import make_report as m
def run(vicur, other, suite='open-curves'):
    r = m.Run([])
    r.rows = [{'suite': suite, 'input': str(i), 'level': '', 'algorithm': a, '_exact': ok, '_ok': True}
              for i in range(20) for a, ok in (('vicur', i < vicur), ('crust', i < other), ('emst', True))]
    r.suites, r.algorithms = [suite], ['vicur', 'crust', 'emst']
    return r
row = m.SURVEY_ROWS[[x['suite'] for x in m.SURVEY_ROWS].index('open-curves')]
crossing = m.SURVEY_ROWS[[x['suite'] for x in m.SURVEY_ROWS].index('intersecting')]
sys.exit(not (m.survey_ours(run(20, 8), row)[1] and not m.survey_ours(run(8, 20), row)[1]
              and m.survey_ours(run(20, 19), row)[1] is None
              and m.survey_ours(run(2, 0, 'intersecting'), crossing)[1]
              and not m.survey_ours(run(20, 0, 'intersecting'), crossing)[1]))"
check "Wilson of nothing is empty" /usr/bin/python3 -c "import sys; sys.path.insert(0, '$root/bench/report'); import make_report; sys.exit(make_report.wilson([]) != (0, 0, None, None))"

finish
