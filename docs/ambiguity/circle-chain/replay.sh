#!/bin/sh
# Re-measures S against C1 and C2 with the project's unfloored epsilon.
cd "$(dirname "$0")"
${CURVEBENCH:-curvebench} measure --curve svg:curve_1.svg -i points.xy -e edges_1.edges --min-lfs 0
${CURVEBENCH:-curvebench} measure --curve svg:curve_2.svg -i points.xy -e edges_2.edges --min-lfs 0
