#!/bin/sh
# hnn-crust does not reconstruct these 15 points of fourier:seed=408,harmonics=1,amplitude=0.27,decay=0.68,components=2
# (measured rho 0.97800259376820553; proven bound 0.90000000000000002). Run from this directory with curvebench on PATH.
set -e
curvebench reconstruct -a 'hnn-crust' -i points.xy -o replayed.edges --svg replayed.svg
cmp replayed.edges reconstruction.edges && echo 'the same edges as found'
curvebench evaluate -i points.xy -e replayed.edges -g truth.edges
curvebench measure --curve 'fourier:seed=408,harmonics=1,amplitude=0.27,decay=0.68,components=2' -i points.xy -e truth.edges --min-lfs 0
