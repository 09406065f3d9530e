#!/usr/bin/env bash
# End-to-end checks of the `curvebench` command line: exit codes, one-line errors that
# name FILE:LINE, the duplicate policy and the input-index convention of edge lists.
# Usage: curvebench_cli_test.sh PATH/TO/curvebench
set -uo pipefail
curvebench="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/../support/check.sh"

# A malformed file: exit status 2 and exactly one line on stderr, "curvebench: FILE:LINE: ...".
printf '0 0\n1 1\n2 x\n' >"$work/bad.xy"
"$curvebench" graph delaunay -i "$work/bad.xy" -o "$work/out.edges" 2>"$work/err"
status=$?
check "malformed input exits with status 2" test "$status" -eq 2
check "malformed input gives one line" test "$(wc -l <"$work/err")" -eq 1
check "the line names file and line" grep -q "^curvebench: $work/bad.xy:3: " "$work/err"

# Non-finite coordinates are rejected the same way.
printf '0 0\nnan 1\n' >"$work/nan.xy"
"$curvebench" graph emst -i "$work/nan.xy" -o "$work/out.edges" 2>"$work/err"
check "NaN exits with status 2 naming line 2" grep -q "nan.xy:2: " "$work/err"

# Duplicates are merged into their first occurrence and edges name input lines:
# kept points (0,0) (1,0) (0,1) are input points 0, 1, 3; their EMST is {0-1, 0-3}.
printf '0 0\n1 0\n0 0\n0 1\n' >"$work/dup.xy"
"$curvebench" graph emst -i "$work/dup.xy" -o "$work/dup.edges" 2>"$work/err"
check "duplicates: exit 0" test $? -eq 0
check "duplicates: one note naming both lines" grep -q "dup.xy:3: duplicate of the point on line 1, merged" "$work/err"
check "duplicates: edges in input indices" diff <(printf '0 1\n0 3\n') "$work/dup.edges"

# rate: a simplifier gets no exact rate (its output is never the interpolating truth),
# an interpolating algorithm its percentage.
"$curvebench" rate -c ellipse:a=2,b=1 -e 0.3 -a nn-crust,optimal-transport >"$work/rate.txt" 2>&1
check "rate: Optimal Transport is n/a, as a simplifier" grep -q "^optimal-transport *n/a (simplifies)" "$work/rate.txt"
check "rate: NN-Crust has its rate" grep -q "^nn-crust *100.0% (1)" "$work/rate.txt"

# Files as users have them: the same points with a UTF-8 byte-order mark, and as a CSV
# with a header line (x,y; pandas' unnamed index column), reconstruct to the plain file's edges.
"$curvebench" sample --curve ellipse:a=2,b=1 --epsilon 0.3 --safe -o "$work/plain" >/dev/null
{ printf '\xEF\xBB\xBF'; cat "$work/plain.xy"; } >"$work/bom.xy"
{ echo 'x,y'; tr ' ' ',' <"$work/plain.xy"; } >"$work/header.csv"
{ echo ',x,y'; awk '{ print NR - 1 "," $1 "," $2 }' "$work/plain.xy"; } >"$work/pandas.csv"
"$curvebench" reconstruct -a nn-crust -i "$work/plain.xy" -o "$work/plain.out" -q
# The ground truth lists the closing edge as "n-1 0"; reconstruct writes i < j, sorted.
check "the plain sample reconstructs to its ground truth" \
  diff <(awk '{ print ($1 < $2) ? $1 " " $2 : $2 " " $1 }' "$work/plain.edges" | sort -n -k1,1 -k2,2) "$work/plain.out"
for variant in bom.xy header.csv pandas.csv; do
  "$curvebench" reconstruct -a nn-crust -i "$work/$variant" -o "$work/$variant.edges" -q
  check "$variant gives the plain file's edges" diff "$work/plain.out" "$work/$variant.edges"
done
{ echo 'x,y'; tr ' ' ',' <"$work/plain.xy"; echo 'x,y'; } >"$work/late-header.csv"
"$curvebench" reconstruct -a nn-crust -i "$work/late-header.csv" -o "$work/late.edges" -q 2>"$work/err"
check "a header-like line after the first is an error naming its line" \
  grep -q "^curvebench: $work/late-header.csv:$(($(wc -l <"$work/plain.xy") + 2)): 'x' is not a number" "$work/err"

# An unknown graph kind is a usage error, not a crash.
"$curvebench" graph no-such-graph -i "$work/dup.xy" -o "$work/x" 2>/dev/null
status=$?
check "unknown kind is rejected" test "$status" -ne 0 -a "$status" -lt 128

# Every listed graph builds on a degenerate input (a 3x3 grid: collinear and cocircular).
printf '%s\n' '0 0' '1 0' '2 0' '0 1' '1 1' '2 1' '0 2' '1 2' '2 2' >"$work/grid.xy"
for kind in $("$curvebench" list graphs --names); do
  check "$kind on a grid" "$curvebench" graph "$kind" -i "$work/grid.xy" -o "$work/$kind.edges" --svg "$work/$kind.svg"
done
check "the grid's Delaunay triangulation has 16 edges" test "$(wc -l <"$work/delaunay.edges")" -eq 16
check "the grid's Gabriel graph is its 12 unit edges" test "$(wc -l <"$work/gabriel.edges")" -eq 12

# Sampling and measuring against closed forms: 12 equally spaced points on a unit circle
# form a sampling with epsilon = 2 sin(pi / 24), attained at arc midpoints, and
# uniformity 1; the safe sampler's measured epsilon stays below its target.
json_number() { sed -n "s/^  \"$1\": \([-0-9.e+]*\),\{0,1\}$/\1/p" "$2"; }
close_to() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= tol) }'; }
"$curvebench" sample --curve circle:r=1 --uniform 12 -o "$work/circle" >/dev/null
"$curvebench" measure --curve circle:r=1 -i "$work/circle.xy" >"$work/circle.json"
check "12 points on a circle: 12 edges" test "$(wc -l <"$work/circle.edges")" -eq 12
check "12 points on a circle: epsilon = 2 sin(pi/24)" \
  close_to "$(json_number epsilon "$work/circle.json")" 0.2610523844401031 1e-3
check "12 points on a circle: uniformity 1" close_to "$(json_number uniformity "$work/circle.json")" 1 1e-9
"$curvebench" sample --curve ellipse:a=3,b=1 --epsilon 0.25 --safe -o "$work/ellipse" --svg >/dev/null
"$curvebench" measure --curve ellipse:a=3,b=1 -i "$work/ellipse.xy" >"$work/ellipse.json"
check "safe sampling measures at most its epsilon" \
  awk -v e="$(json_number epsilon "$work/ellipse.json")" 'BEGIN { exit !(e > 0.2 && e <= 0.25) }'
check "the sample picture is written" grep -q "<svg" "$work/ellipse.svg"
# The survey's sampling tool's 0.33-sampling of blob2.svg (data/sample2d/) measures as one:
# its rounding kinks are not corners (it read 2.93 while they were).
data="$(dirname "${BASH_SOURCE[0]}")/../../data"
"$curvebench" measure --curve "svg:$data/svg/blob2.svg" -i "$data/sample2d/blob2_0.33.txt" >"$work/blob2.json"
check "the survey tool's blob2 sampling at 0.33 measures at most 0.35" \
  awk -v e="$(json_number epsilon "$work/blob2.json")" 'BEGIN { exit !(e > 0.3 && e <= 0.35) }'
"$curvebench" outliers -i "$work/ellipse.xy" --percent 10 --seed 3 -o "$work/outliers" >/dev/null
check "outliers are labelled" test "$(grep -c outlier "$work/outliers.labels")" -eq \
  "$(awk -v n="$(wc -l <"$work/ellipse.xy")" 'BEGIN { printf "%d", n / 10 + 0.5 }')"
"$curvebench" noise -i "$work/ellipse.xy" --uniform 0.01 --seed 3 -o "$work/noisy1" >/dev/null
"$curvebench" noise -i "$work/ellipse.xy" --uniform 0.01 --seed 3 -o "$work/noisy2" >/dev/null
check "same seed, same bytes" cmp -s "$work/noisy1.xy" "$work/noisy2.xy"
# A figure eight (lissajous 1:2, one crossing) uniformly sampled at 200 points: 200 chain
# edges; with --crossing-samples one more point, on both branches, so 202 edges.
"$curvebench" sample --curve lissajous:a=1,b=2,seed=3 --uniform 200 -o "$work/eight" >/dev/null
"$curvebench" sample --curve lissajous:a=1,b=2,seed=3 --uniform 200 --crossing-samples -o "$work/eight-x" >/dev/null
check "a figure eight's samples form one chain" test "$(wc -l <"$work/eight.edges")" -eq 200
check "a sample on the crossing splits an edge of each branch" \
  test "$(wc -l <"$work/eight-x.xy")" -eq 201 -a "$(wc -l <"$work/eight-x.edges")" -eq 202
"$curvebench" sample --curve no-such-curve --uniform 5 -o "$work/x" 2>"$work/err"
check "a bad curve spec is a one-line error" test "$?" -eq 2 -a "$(wc -l <"$work/err")" -eq 1

# The survey's image pipeline: a rasterized circle is a white disk in a P5 file; its
# boundary samples form one cycle (as many edges as points), in pixel centres or, from
# --curve, near the curve itself; the same seed gives the same bytes; a malformed image or
# an open curve is a one-line error.
byte_at() { od -An -tu1 -j "$2" -N1 "$1" | tr -d ' '; }
"$curvebench" rasterize --curve circle:r=1 --resolution 64 -o "$work/disk.pgm" >/dev/null
check "rasterize writes a 64 x 64 P5 image" test "$(head -c 13 "$work/disk.pgm" | tr '\n' ' ')" = "P5 64 64 255 "
check "the disk's centre is white" test "$(byte_at "$work/disk.pgm" $((13 + 32 * 64 + 32)))" -eq 255
check "the image's corner is black" test "$(byte_at "$work/disk.pgm" 13)" -eq 0
"$curvebench" image-sample -i "$work/disk.pgm" --radius 4 --seed 5 -o "$work/disk" >/dev/null
check "image-sample of a disk: more than 10 points" test "$(wc -l <"$work/disk.xy")" -gt 10
check "image-sample of a disk: one cycle" test "$(wc -l <"$work/disk.edges")" -eq "$(wc -l <"$work/disk.xy")"
check "image-sample: points are pixel centres" awk '{ if ($1 * 2 != int($1 * 2) || $1 == int($1)) exit 1 }' "$work/disk.xy"
"$curvebench" image-sample -i "$work/disk.pgm" --radius 4 --seed 5 -o "$work/disk2" >/dev/null
check "image-sample: same seed, same bytes" cmp -s "$work/disk.xy" "$work/disk2.xy"
"$curvebench" image-sample --curve ellipse:a=2,b=1 --resolution 200 --radius 5 -o "$work/pixels" --svg >/dev/null
check "image-sample --curve: points within 0.05 of the ellipse" \
  awk '{ d = sqrt($1 * $1 / 4 + $2 * $2) - 1; if (d < -0.05 || d > 0.05) exit 1 }' "$work/pixels.xy"
check "image-sample --svg draws a picture" grep -q "<svg" "$work/pixels.svg"
printf 'P2\n2 2\n255\n0 1\n2 x\n' >"$work/bad.pgm"
"$curvebench" image-sample -i "$work/bad.pgm" --radius 2 -o "$work/x" 2>"$work/err"
check "a malformed image exits with status 2" test "$?" -eq 2
check "a malformed image is one line naming FILE:LINE" \
  test "$(wc -l <"$work/err")" -eq 1 -a -n "$(grep "^curvebench: $work/bad.pgm:5: " "$work/err")"
printf '0 0\n1 0\n1 1\n' >"$work/open.xy"
printf '0 1\n1 2\n' >"$work/open.edges"
"$curvebench" rasterize --curve "truth:$work/open.xy:$work/open.edges" --resolution 50 -o "$work/x.pgm" 2>"$work/err"
check "rasterizing an open curve is a one-line error" test "$?" -eq 2 -a "$(wc -l <"$work/err")" -eq 1
"$curvebench" image-sample --curve circle:r=1 --radius 2 -o "$work/x" 2>/dev/null
status=$?
check "image-sample --curve without --resolution is a usage error" test "$status" -ne 0 -a "$status" -lt 128

# Reconstruction: every listed algorithm runs; NN-Crust closes 12 points of a circle into
# their 12-cycle, edges in input indices, with a duplicate merged; a bad parameter is a
# one-line error.
check "list names the registered algorithms" test "$("$curvebench" list --names | wc -l)" -ge 9
awk 'BEGIN { for (k = 0; k < 12; ++k) printf "%.17g %.17g\n", cos(k * 3.14159265358979 / 6), sin(k * 3.14159265358979 / 6);
             printf "%.17g %.17g\n", 1, 0 }' >"$work/ring.xy"
# Every edge indexes a line of the --points-out file.
edges_index_points() {  # edges_index_points EDGES POINTS
  awk -v n="$(grep -c . "$2")" '$1 < 0 || $2 >= n || $1 >= $2 { bad = 1 } END { exit bad }' "$1"
}
for algorithm in $("$curvebench" list --names); do
  "$curvebench" reconstruct -q -a "$algorithm" -i "$work/ring.xy" -o "$work/ring-$algorithm.edges" \
    --points-out "$work/ring-$algorithm.xy" 2>/dev/null
  check "$algorithm reconstructs a 13-line file" test $? -eq 0
  check "$algorithm: its edges index its --points-out" edges_index_points "$work/ring-$algorithm.edges" "$work/ring-$algorithm.xy"
done
check "an interpolating algorithm's --points-out is the input" test "$(grep -c . "$work/ring-nn-crust.xy")" -eq 13
"$curvebench" reconstruct -q -a stretch-denoise -i "$work/ring.xy" -o "$work/x.edges" 2>"$work/err"
check "a denoising algorithm without --points-out is an error that says so" test "$?" -eq 2 -a "$(grep -c -- --points-out "$work/err")" -eq 1
{ cat "$work/ring.xy"; echo "40 40"; } >"$work/ring-outlier.xy"
"$curvebench" reconstruct -q -a nn-crust+outlier-filter -i "$work/ring-outlier.xy" -o "$work/filtered.edges" \
  --points-out "$work/filtered.xy"
check "nn-crust+outlier-filter keeps the 12 ring points" test "$(grep -c . "$work/filtered.xy")" -eq 12
check "nn-crust+outlier-filter: the 12-cycle" diff <(awk 'BEGIN { for (k = 0; k < 11; ++k) print k, k + 1; print 0, 11 }' | sort -n -k1,1 -k2,2) \
  "$work/filtered.edges"
check "nn-crust: the 12-cycle" diff <(awk 'BEGIN { for (k = 0; k < 11; ++k) print k, k + 1; print 0, 11 }' | sort -n -k1,1 -k2,2) \
  "$work/ring-nn-crust.edges"
head -12 "$work/ring.xy" >"$work/ring12.xy"
"$curvebench" reconstruct -a beta-skeleton -p beta=0.5 -i "$work/ring12.xy" -o "$work/x.edges" 2>"$work/err"
check "an out-of-range parameter is a one-line error" test "$?" -eq 2 -a "$(wc -l <"$work/err")" -eq 1

# slurm writes its scripts without Slurm (cli.slurm runs them on a cluster).
"$curvebench" slurm run smoke -a nn-crust --pictures none -o "$work/cluster" --tasks 3 --time 5:00 2>/dev/null
check "slurm writes a 3-task array of shards K/3 that resume" \
  grep -q -- '--shard "$shard/3" .* --resume' "$work/cluster/slurm/array.sbatch"
check "slurm writes the merge of the 3 shards with their --pictures" \
  grep -q -- "merge -o $work/cluster --pictures none $work/cluster/shard-{1..3}" "$work/cluster/slurm/merge.sbatch"
"$curvebench" slurm run smoke --shard 1/2 -o "$work/cluster" --tasks 2 2>"$work/err"
check "slurm refuses the options its scripts set" test $? -eq 2 -a "$(grep -c -- '--shard' "$work/err")" -eq 1
"$curvebench" slurm run no-such-suite -o "$work/cluster" --tasks 2 2>"$work/err"
check "slurm refuses an unknown suite before writing anything" test $? -eq 2 -a "$(grep -c no-such-suite "$work/err")" -eq 1
SLURM_ARRAY_TASK_ID=9 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=4 "$curvebench" run smoke -o "$work/bad-task" 2>"$work/err"
check "a task ID outside its array is a one-line error" test $? -eq 2 -a "$(grep -c 'outside the array 1..4' "$work/err")" -eq 1

finish
