#!/usr/bin/python3
"""Writes the circle-chain ambiguity case: a point set that is an epsilon-sample, epsilon < 1, of two
different smooth curves, each a union of disjoint circles.

Both curves are collections of closed curves, as the survey's smooth curve is (section "Definitions
and Notations": "a (collection of) bounded 1-manifold(s)") and as Bjerkevik's curves are. 2N circles
of one radius r sit with their centres evenly on the unit circle, alternately of family A and of
family B; C1 is the union of the A circles, C2 that of the B circles, and S is the set of points where
an A circle crosses a B circle. Each circle crosses its two neighbours, so S has 4N points and every
point lies on both curves; the circles of one family are disjoint, so each curve is embedded; and the
ground truths differ, since C1 joins the points around A circles and C2 around B circles.

Why epsilon < 1: with neighbouring centres a distance s apart, an A circle carries four samples, two
in each lens with a neighbour, at the angles +-theta about the neighbour's direction, cos(theta) =
s / (2r). Its medial axis (of C1) is its centre and the bisectors with the next A circles, 2s away, so
lfs = r on the free arcs between the lenses and lfs = s - r where a lens faces the next A circle. On
a straight chain (N -> infinity) epsilon is the larger of 2 sin(pi/4 - theta/2) (a free arc's
midpoint) and 2 sin(theta/2) / (s/r - 1) (a lens arc's); they are equal at s/r = 1.64359, where
epsilon = 0.92760. On the ring the free arcs on the outside are wider by pi/N, which costs about
1.1/N; at N = 16 epsilon is just below 1 (0.9965).

Each circle is written as cubic Bezier arcs between its samples, none longer than --piece degrees
(15 by default). They pass through S exactly as written and meet with one tangent and one curvature,
1/r, so each curve is twice differentiable in arc length, and they leave the circle by less than
1e-7 r. A C2 cubic spline through the same nodes was tried first and measured 5e-3 higher: its
curvature errs by O(h^2). The ratio s/r is chosen by minimising the measured epsilon (bounded scalar
search), unless --ratio is given. The epsilons recorded are `curvebench measure`'s on the written
files (scripts/ambiguity_case_files.py); the test certify.ambiguity_circle_chain checks them against
an exact computation on the circles themselves (measure reads up to 2e-4 below it: its lfs, the
distance to a sampled medial axis, errs upward by that much on the straight bisectors here).

usage: scripts/ambiguity_circle_chain.py -o OUT [--circles N] [--ratio U] [--piece DEG] [--curvebench PATH]
Needs python3-numpy and python3-scipy (scripts/setup.sh installs them).
"""
import argparse
import math
import os
import shutil

import numpy as np
from scipy.optimize import minimize_scalar

import ambiguity_case_files as case_files


def ring(n, ratio):
    """The two families as lists of (centre, radius): n circles each, centres alternating on the unit
    circle, neighbours s apart, radius s / ratio."""
    s = 2 * math.sin(math.pi / (2 * n))
    r = s / ratio
    centre = lambda k: np.array([math.cos(math.pi * k / n), math.sin(math.pi * k / n)])
    return [[(centre(2 * i + f), r) for i in range(n)] for f in (0, 1)]


def crossings(a, b):
    (c1, r1), (c2, r2) = a, b
    d = float(np.linalg.norm(c2 - c1))
    along = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    across = math.sqrt(r1 * r1 - along * along)
    e = (c2 - c1) / d
    n = np.array([-e[1], e[0]])
    return [c1 + along * e + across * n, c1 + along * e - across * n]


def arc_path(centre, r, angles, piece):
    """SVG path data of circle (centre, r) as cubic Bezier arcs from each of the given angles to the
    next, split so that none spans more than `piece` radians. An arc's ends and their tangents are
    the circle's, and its handles, of length 2/3 r sin(phi/2) (sqrt(cos(phi/2)^2 + 3) - cos(phi/2)),
    give it curvature exactly 1/r at both ends: consecutive arcs meet with one tangent and one
    curvature, so the curve is twice differentiable in arc length, as the survey's smooth curve is.
    (The usual handles, 4/3 tan(phi/4) r, agree to third order in phi but not in end curvature.)"""
    angles = sorted(angles)
    point = lambda t: centre + r * np.array([math.cos(t), math.sin(t)])
    tangent = lambda t: np.array([-math.sin(t), math.cos(t)])
    f = lambda p: "%r %r" % (float(p[0]), float(p[1]))
    d = "M " + f(point(angles[0]))
    for i, (a, b) in enumerate(zip(angles, angles[1:] + [angles[0] + 2 * math.pi])):
        m = max(1, math.ceil((b - a) / piece))
        for j in range(m):
            t0, t1 = a + (b - a) * j / m, a + (b - a) * (j + 1) / m
            half = (t1 - t0) / 2
            handle = 2 / 3 * r * math.sin(half) * (math.sqrt(math.cos(half) ** 2 + 3) - math.cos(half))
            end = point(angles[0]) if i == len(angles) - 1 and j == m - 1 else point(t1)  # closes exactly
            d += f" C {f(point(t0) + handle * tangent(t0))} {f(end - handle * tangent(t1))} {f(end)}"
    return d + " Z"


def write(directory, n, ratio, piece, curvebench, record):
    families = ring(n, ratio)
    samples, on = [], [[[] for _ in range(n)] for _ in (0, 1)]
    for i in range(n):
        for j in (i, (i - 1) % n):  # A circle i meets B circles i and i - 1
            for p in crossings(families[0][i], families[1][j]):
                on[0][i].append(len(samples))
                on[1][j].append(len(samples))
                samples.append(p)
    paths, cycles = [], []
    for family, members in zip(families, on):
        arcs, components = [], []
        for (centre, r), indices in zip(family, members):
            angle = {q: math.atan2(samples[q][1] - centre[1], samples[q][0] - centre[0]) for q in indices}
            components.append(sorted(indices, key=angle.get))
            arcs.append(arc_path(centre, r, list(angle.values()), piece))
        paths.append(" ".join(arcs))
        cycles.append(components)
    circles = [[[float(c[0]), float(c[1]), float(r)] for c, r in family] for family in families]
    return case_files.write_case(directory, samples, paths, cycles, curvebench,
                                 {"components_1": n, "components_2": n, "ratio": ratio,
                                  "circles_1": circles[0], "circles_2": circles[1], **record})


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-o", "--out", required=True)
    parser.add_argument("--circles", type=int, default=40, help="circles per family (N)")
    parser.add_argument("--ratio", type=float, help="s / r (default: the one minimising epsilon)")
    parser.add_argument("--piece", type=float, default=15.0, help="longest Bezier arc, degrees")
    parser.add_argument("--curvebench", default=os.path.join(here, "..", "build", "bench", "curvebench"))
    args = parser.parse_args()
    n, piece = args.circles, math.radians(args.piece)
    if n < 3:
        parser.error("need at least 3 circles per family")
    if not 0 < args.piece <= 90:
        parser.error("--piece must lie in (0, 90] degrees")
    # Neighbours must cross (s < 2r); next neighbours, 2 sin(pi/n) = 2 s cos(pi/2n) apart, must not.
    low, high = 1 / math.cos(math.pi / (2 * n)) + 1e-9, 2.0 - 1e-9
    ratio = args.ratio
    if ratio is None:
        trial = args.out + ".trial"
        ratio = minimize_scalar(lambda u: max(write(trial, n, u, piece, args.curvebench, {})),
                                bounds=(max(low, 1.3), min(high, 1.9)), method="bounded",
                                options={"xatol": 1e-5}).x
        shutil.rmtree(trial)
    elif not low < ratio < high:
        parser.error(f"--ratio must lie in ({low:.6f}, {high:.6f}): neighbours cross, next ones do not")
    epsilons = write(args.out, n, ratio, piece, args.curvebench,
                     {"family": "circle chain", "piece_degrees": args.piece})
    print(f"written {args.out}: {4 * n} points, s/r {ratio:.6f}, epsilon {epsilons[0]!r} (C1), "
          f"{epsilons[1]!r} (C2)")


if __name__ == "__main__":
    main()
