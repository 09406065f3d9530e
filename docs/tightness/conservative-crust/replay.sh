#!/bin/sh
# conservative-crust does not reconstruct these 46 points of fourier:seed=73,harmonics=2,amplitude=0.40,decay=1.84,components=2
# (measured epsilon 0.27272229398878611; proven bound 0.0625). Run from this directory with curvebench on PATH.
set -e
curvebench reconstruct -a 'conservative-crust' -i points.xy -o replayed.edges --svg replayed.svg
cmp replayed.edges reconstruction.edges && echo 'the same edges as found'
curvebench evaluate -i points.xy -e replayed.edges -g truth.edges
curvebench measure --curve 'fourier:seed=73,harmonics=2,amplitude=0.40,decay=1.84,components=2' -i points.xy -e truth.edges --min-lfs 0
