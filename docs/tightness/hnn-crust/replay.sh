#!/bin/sh
# hnn-crust does not reconstruct these 104 points of fourier:seed=486,harmonics=7,amplitude=0.28,decay=0.62
# (measured epsilon 0.6529218802990657; proven bound 0.46999999999999997). Run from this directory with curvebench on PATH.
set -e
curvebench reconstruct -a 'hnn-crust' -i points.xy -o replayed.edges --svg replayed.svg
cmp replayed.edges reconstruction.edges && echo 'the same edges as found'
curvebench evaluate -i points.xy -e replayed.edges -g truth.edges
curvebench measure --curve 'fourier:seed=486,harmonics=7,amplitude=0.28,decay=0.62' -i points.xy -e truth.edges --min-lfs 0
