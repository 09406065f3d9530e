#!/bin/sh
# crust does not reconstruct these 12 points of fourier:seed=680,harmonics=1,amplitude=0.20,decay=1.68,components=2
# (measured epsilon 0.6740413003713422; proven bound 0.252). Run from this directory with curvebench on PATH.
set -e
curvebench reconstruct -a 'crust' -i points.xy -o replayed.edges --svg replayed.svg
cmp replayed.edges reconstruction.edges && echo 'the same edges as found'
curvebench evaluate -i points.xy -e replayed.edges -g truth.edges
curvebench measure --curve 'fourier:seed=680,harmonics=1,amplitude=0.20,decay=1.68,components=2' -i points.xy -e truth.edges --min-lfs 0
