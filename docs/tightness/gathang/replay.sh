#!/bin/sh
# gathang does not reconstruct these 46 points of fourier:seed=715,harmonics=4,amplitude=0.54,decay=1.23
# (measured epsilon 0.70394019171801825; proven bound 0.5). Run from this directory with curvebench on PATH.
set -e
curvebench reconstruct -a 'gathang' -i points.xy -o replayed.edges --svg replayed.svg
cmp replayed.edges reconstruction.edges && echo 'the same edges as found'
curvebench evaluate -i points.xy -e replayed.edges -g truth.edges
curvebench measure --curve 'fourier:seed=715,harmonics=4,amplitude=0.54,decay=1.23' -i points.xy -e truth.edges --min-lfs 0
