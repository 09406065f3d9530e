#!/bin/sh
# nn-crust does not reconstruct these 22 points of fourier:seed=402,harmonics=3,amplitude=0.58,decay=1.36
# (measured epsilon 0.70564953957886734; proven bound 0.33333333333333331). Run from this directory with curvebench on PATH.
set -e
curvebench reconstruct -a 'nn-crust' -i points.xy -o replayed.edges --svg replayed.svg
cmp replayed.edges reconstruction.edges && echo 'the same edges as found'
curvebench evaluate -i points.xy -e replayed.edges -g truth.edges
curvebench measure --curve 'fourier:seed=402,harmonics=3,amplitude=0.58,decay=1.36' -i points.xy -e truth.edges --min-lfs 0
