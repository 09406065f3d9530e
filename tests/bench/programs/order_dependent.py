#!/usr/bin/env python3
"""A test algorithm with one planted defect, for `curvebench hunt`: it joins the points in
the order the file lists them, so its curve changes when the input is permuted.
Usage: order_dependent.py POINTS EDGES"""
import sys

count = sum(1 for line in open(sys.argv[1]) if line.strip())
with open(sys.argv[2], "w") as edges:
    for i in range(count - 1):
        edges.write(f"{i} {i + 1}\n")
