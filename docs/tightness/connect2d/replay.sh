#!/bin/sh
# connect2d does not reconstruct these 42 points of fourier:seed=285,harmonics=6,amplitude=0.57,decay=0.93
# (measured epsilon 1.219384460165843; proven bound 0.5). Run from this directory with curvebench on PATH.
set -e
curvebench reconstruct -a 'connect2d' -i points.xy -o replayed.edges --svg replayed.svg
cmp replayed.edges reconstruction.edges && echo 'the same edges as found'
curvebench evaluate -i points.xy -e replayed.edges -g truth.edges
curvebench measure --curve 'fourier:seed=285,harmonics=6,amplitude=0.57,decay=0.93' -i points.xy -e truth.edges --min-lfs 0
