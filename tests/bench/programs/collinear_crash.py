#!/usr/bin/env python3
"""A test algorithm with one planted defect, for `curvebench hunt`: it kills itself with
SIGSEGV on exactly collinear input (three or more points, all on one line, decided on the
doubles' exact values); otherwise it writes no edge, which no law can fault.
Usage: collinear_crash.py POINTS EDGES"""
import os
import signal
import sys
from fractions import Fraction

points = [tuple(Fraction(float(v)) for v in line.split()) for line in open(sys.argv[1]) if line.strip()]
if len(points) >= 3:
    (ax, ay), (bx, by) = points[0], points[1]
    if all((bx - ax) * (cy - ay) == (by - ay) * (cx - ax) for cx, cy in points[2:]):
        os.kill(os.getpid(), signal.SIGSEGV)
open(sys.argv[2], "w").close()
