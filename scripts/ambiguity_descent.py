#!/usr/bin/python3
"""Descends a mirror ambiguity case (docs/ambiguity/, `curvebench ambiguity --mirror -o`) to a smaller
max epsilon, by quasi-Newton steps on a smooth surrogate of epsilon rather than by random climbing.

The family is the one `curvebench ambiguity --mirror` searches (survey, section "Sampling Conditions",
epsilon-sampling; docs/tightness-and-ambiguity.md): S = R(S) for the mirror R(x, y) = (-x, y),
C1 the closed C2 cubic spline through its knots (the samples in C1's order, with free via points
between them) on free knot intervals, and C2 = R(C1), so that epsilon is the same on both and only
C1 is measured. The variables are the samples (one per mirror pair, x = 0 on the axis), the via
points and the log knot intervals.

Why a surrogate: epsilon(C, S) = max over x on C of d(x, S) / lfs(x) is a max of kinked functions, on
which the C++ hill climbing plateaus. Here C1 is sampled densely (PER points per length lfs, at least
4 per knot interval); lfs(x) is the distance to the centres of the medial balls of those samples (each
ball's radius the smallest tangent circle through another sample of C1, on each side) and to the
centres of curvature at the curvature maxima, where the medial axis ends; the ratio is evaluated at the
samples and at every point where C1 crosses a Voronoi edge of S, found by secant steps, since d(x, S)
and so the ratio peak exactly there. The descent minimises the power mean of the ratios (exponent
p = 200, then 1000, 5000: a smooth stand-in for the max) with L-BFGS on finite differences.
Decisions here are in floating point: this is a search, not a certificate. Every case it writes is
re-measured by `curvebench measure`, and that value is the one recorded in summary.json and checked
by the tests certify.ambiguity_cases and certify.ambiguity_descent.

Steps that change the sampling:
  --refine M       adds M via points per knot interval (at equal parameter steps; C1 barely moves)
  --add-pair A-B   adds a mirror pair of samples on C1's stretch from sample A to sample B
  --crossings      adds every crossing of C1 with R(C1) that is not a sample: both curves pass there
                   unchanged, so epsilon cannot grow, and the descent gains variables
and, after the descent, --hops N basin hops: a Gaussian step of --hop-size on every variable, a short
descent, kept when the measured epsilon falls (the best case is rewritten at once).

usage: scripts/ambiguity_descent.py SRC -o OUT [--refine M] [--add-pair A-B ...] [--crossings]
                                    [--per N] [--powers 200,1000,5000] [--iterations N]
                                    [--hops N] [--hop-size S] [--seed S] [--curvebench PATH]
Needs python3-numpy and python3-scipy (scripts/setup.sh installs them); python3-numba, when present,
compiles the ratio kernel, which is then several times faster.
"""
import argparse
import math
import os
import shutil
import re
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import minimize

import ambiguity_case_files as case_files

MIRROR = np.array([-1.0, 1.0])


# ---- ratio d(x, S) / lfs(x) along a dense polyline ------------------------------------------------

def _ratios_numpy(x, dx, q, S, tips):
    tangent = dx / np.linalg.norm(dx, axis=1)[:, None]
    normal = np.stack([-tangent[:, 1], tangent[:, 0]], axis=1)
    v = x[None, :, :] - x[:, None, :]
    s = np.einsum("ijk,ik->ij", v, normal)
    np.fill_diagonal(s, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.einsum("ijk,ijk->ij", v, v) / (2 * s)
    centres = []
    for side in (1, -1):
        radius = np.where(side * s > 0, side * r, np.inf).min(axis=1)
        finite = np.isfinite(radius)
        centres.append(x[finite] + side * radius[finite, None] * normal[finite])
    medial = np.vstack(centres + [tips])
    lfs2 = ((q[:, None, :] - medial[None]) ** 2).sum(-1).min(1)
    d2 = ((q[:, None, :] - S[None]) ** 2).sum(-1).min(1)
    return np.sqrt(d2 / lfs2), np.sqrt(lfs2)


try:
    import numba

    @numba.njit
    def _ratios_compiled(x, dx, q, S, tips):
        n = x.shape[0]
        medial = np.empty((2 * n + tips.shape[0], 2))
        m = 0
        for i in range(tips.shape[0]):
            medial[m, 0], medial[m, 1] = tips[i, 0], tips[i, 1]
            m += 1
        for i in range(n):
            length = math.sqrt(dx[i, 0] ** 2 + dx[i, 1] ** 2)
            nx, ny = -dx[i, 1] / length, dx[i, 0] / length
            left, right = np.inf, np.inf
            for j in range(n):
                if j == i:
                    continue
                vx, vy = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1]
                s = vx * nx + vy * ny
                if s > 0:
                    left = min(left, (vx * vx + vy * vy) / (2 * s))
                elif s < 0:
                    right = min(right, -(vx * vx + vy * vy) / (2 * s))
            if left < np.inf:
                medial[m, 0], medial[m, 1] = x[i, 0] + left * nx, x[i, 1] + left * ny
                m += 1
            if right < np.inf:
                medial[m, 0], medial[m, 1] = x[i, 0] - right * nx, x[i, 1] - right * ny
                m += 1
        out = np.empty(q.shape[0])
        lfs = np.empty(q.shape[0])
        for k in range(q.shape[0]):
            lfs2, d2 = np.inf, np.inf
            for c in range(m):
                lfs2 = min(lfs2, (q[k, 0] - medial[c, 0]) ** 2 + (q[k, 1] - medial[c, 1]) ** 2)
            for p in range(S.shape[0]):
                d2 = min(d2, (q[k, 0] - S[p, 0]) ** 2 + (q[k, 1] - S[p, 1]) ** 2)
            out[k] = math.sqrt(d2 / lfs2)
            lfs[k] = math.sqrt(lfs2)
        return out, lfs

    _ratios = _ratios_compiled
except ImportError:
    _ratios = _ratios_numpy


def voronoi_crossings(spline, u, S):
    """Points of the curve where the nearest sample changes: there d(x, S), and the ratio, peak."""
    nearest = ((spline(u)[:, None, :] - S[None]) ** 2).sum(-1).argmin(1)
    following = np.roll(nearest, -1)
    i = np.nonzero(nearest != following)[0]
    if len(i) == 0:
        return np.zeros((0, 2))
    u1 = np.where(i + 1 < len(u), u[(i + 1) % len(u)], 2 * u[-1] - u[-2])
    return bisector_crossings(spline, S[nearest[i]], S[following[i]], u[i], u1)


def bisector_crossings(spline, a, b, u0, u1):
    """Where the curve crosses the bisector of samples a and b between parameters u0 and u1 (each
    row one crossing), by three steps of regula falsi."""
    f = lambda w: ((spline(w) - a) ** 2).sum(1) - ((spline(w) - b) ** 2).sum(1)
    f0, f1 = f(u0), f(u1)
    for _ in range(3):
        w = u0 - f0 * (u1 - u0) / np.where(f1 != f0, f1 - f0, 1)
        fw = f(w)
        keep_left = np.sign(fw) == np.sign(f0)
        u0, f0 = np.where(keep_left, w, u0), np.where(keep_left, fw, f0)
        u1, f1 = np.where(keep_left, u1, w), np.where(keep_left, f1, fw)
    return spline(u0 - f0 * (u1 - u0) / np.where(f1 != f0, f1 - f0, 1))


def medial_tips(spline, t, per=40):
    """Where the medial axis ends: the centres of curvature at the curvature maxima of the curve whose
    osculating disk holds no other point of it. A grid misses these between its points, and a descent
    then sharpens a bend there unseen; so each maximum is refined (golden section) and added."""
    h = np.diff(t)
    u = (t[:-1, None] + np.outer(h, np.arange(per) / per)).ravel()
    def curvature(w):
        d1, d2 = spline(w, 1), spline(w, 2)
        return (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    k = curvature(u)
    points = spline(u)
    tips = []
    for side in (1, -1):
        ks = side * k
        peaks = np.nonzero((ks > 0) & (ks >= np.roll(ks, 1)) & (ks > np.roll(ks, -1)))[0]
        if len(peaks) == 0:
            continue
        step = np.diff(np.append(u, t[-1]))
        lo, hi = u[peaks] - step[peaks - 1], u[peaks] + step[peaks]
        tips.append(osculating_centres(spline, curvature, lo, hi, side, points, 20, period=t[-1]))
    return np.ascontiguousarray(np.vstack(tips)) if tips else np.zeros((0, 2))


def osculating_centres(spline, curvature, lo, hi, side, points, iterations, period=None):
    """The centres of curvature at the curvature maxima (of side * curvature) bracketed by [lo, hi],
    refined by `iterations` golden-section steps (parameters modulo `period` when given), kept where
    the osculating disk holds none of `points` (within 0.999 of its radius)."""
    wrap = (lambda w: w % period) if period else (lambda w: w)
    g = (math.sqrt(5) - 1) / 2
    for _ in range(iterations):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        left_higher = side * curvature(wrap(a)) > side * curvature(wrap(b))
        hi, lo = np.where(left_higher, b, hi), np.where(left_higher, lo, a)
    w = wrap(0.5 * (lo + hi))
    kw = side * curvature(w)
    d1 = spline(w, 1)
    normal = side * np.stack([-d1[:, 1], d1[:, 0]], axis=1) / np.linalg.norm(d1, axis=1)[:, None]
    centres = spline(w) + normal / kw[:, None]
    empty = ((centres[:, None, :] - points[None]) ** 2).sum(-1).min(1) >= (0.999 / kw) ** 2
    return centres[empty]


def closed_spline(knots, intervals):
    t = np.concatenate([[0.0], np.cumsum(intervals)])
    return CubicSpline(t, np.vstack([knots, knots[:1]]), bc_type="periodic"), t


# ---- the mirror case ------------------------------------------------------------------------------

class MirrorCase:
    """S, and C1 as knots (('sample', i) or ('via', j)) with knot intervals; C2 = R(C1)."""

    def __init__(self, samples, knots, intervals):
        self.samples = np.asarray(samples, float)
        mirrored = self.samples * MIRROR
        self.partner = [int(np.argmin(((mirrored - p) ** 2).sum(1))) for p in self.samples]
        scale = np.ptp(self.samples, axis=0).max()
        for i, j in enumerate(self.partner):
            if np.linalg.norm(mirrored[i] - self.samples[j]) > 1e-9 * scale:
                sys.exit(f"sample {i} has no mirror image in S: not a mirror case")
        self.representatives = sorted({min(i, j) for i, j in enumerate(self.partner)})
        self.on_axis = np.array([self.partner[r] == r for r in self.representatives])
        layout, via = [], []
        for q in knots:
            d = ((self.samples - q) ** 2).sum(1)
            i = int(np.argmin(d))
            if d[i] <= (1e-12 * scale) ** 2:
                layout.append(("sample", i))
            else:
                layout.append(("via", len(via)))
                via.append(q)
        self.layout = layout
        self.via_count = len(via)
        self.counts = None  # (per, dense samples per knot interval), set by grid()
        reps = self.samples[self.representatives].copy()
        reps[self.on_axis, 0] = 0.0
        self.x0 = np.concatenate([reps.ravel(), np.array(via).ravel(), np.log(intervals)])

    def unpack(self, x):
        nr, nv = len(self.representatives), self.via_count
        reps = x[:2 * nr].reshape(-1, 2).copy()
        reps[self.on_axis, 0] = 0.0
        via = x[2 * nr:2 * nr + 2 * nv].reshape(-1, 2)
        samples = np.empty_like(self.samples)
        for k, r in enumerate(self.representatives):
            samples[r] = reps[k]
            samples[self.partner[r]] = reps[k] * MIRROR
        knots = np.array([samples[i] if kind == "sample" else via[i] for kind, i in self.layout])
        return samples, knots, np.exp(x[2 * nr + 2 * nv:])

    def grid(self, spline, t, samples, per):
        """Curve parameters of the dense samples. Their spacing must stay well below lfs, or the medial
        balls between two strands that nearly touch come out too large; so the count of each knot
        interval is its length in units of lfs (PER per unit, at least 4), taken at the first call
        and then fixed, so that the surrogate stays smooth in x."""
        if self.counts is None or self.counts[0] != per:
            fine = 48
            u = (t[:-1, None] + np.outer(np.diff(t), np.arange(fine) / fine)).ravel()
            points = np.ascontiguousarray(spline(u))
            lfs = _ratios(points, np.ascontiguousarray(spline(u, 1)), points, samples, medial_tips(spline, t))[1]
            step = np.linalg.norm(np.roll(points, -1, axis=0) - points, axis=1)
            units = (step / lfs).reshape(len(t) - 1, fine).sum(1)
            self.counts = (per, np.clip(np.ceil(per * units), 4, 400).astype(int))
        return np.concatenate([t[k] + (t[k + 1] - t[k]) * np.arange(c) / c for k, c in enumerate(self.counts[1])])

    def ratios(self, x, per):
        samples, knots, intervals = self.unpack(x)
        spline, t = closed_spline(knots, intervals)
        u = self.grid(spline, t, samples, per)
        points = np.ascontiguousarray(spline(u))
        query = np.ascontiguousarray(np.vstack([points, voronoi_crossings(spline, u, samples)]))
        return _ratios(points, np.ascontiguousarray(spline(u, 1)), query, samples, medial_tips(spline, t))[0]

    def power_mean(self, x, power, per):
        try:
            r = self.ratios(x, per)
        except ValueError:  # knot intervals out of range
            return 1e9
        top = r.max()
        return top * np.mean((r / top) ** power) ** (1 / power) if np.isfinite(top) else 1e9

    def order(self, k):
        order = [i for kind, i in self.layout if kind == "sample"]
        return order if k == 1 else [self.partner[i] for i in order]


def read_case(directory):
    """S and C1 (knots and knot intervals) from a case directory; the intervals are recovered from
    the ratio of the Bezier handles at each knot, which for a C1 spline is the ratio of the intervals."""
    samples = np.loadtxt(os.path.join(directory, "points.xy"), comments="#", ndmin=2)[:, :2]
    path = open(os.path.join(directory, "curve_1.svg")).read().split(' d="')[1].split('"')[0]
    numbers = np.array([float(v) for v in re.findall(r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?", path)]).reshape(-1, 2)
    knots = np.vstack([numbers[0:1], numbers[3::3]])[:-1]
    handle_out = np.linalg.norm(numbers[1::3] - knots, axis=1)
    handle_in = np.linalg.norm(knots - np.roll(numbers[2::3], 1, axis=0), axis=1)
    intervals = np.ones(len(knots))
    for i in range(1, len(knots)):
        intervals[i] = intervals[i - 1] * handle_out[i] / handle_in[i]
    return samples, knots, intervals / intervals.mean()


def insert_samples(case, x, insertions):
    """C1 with new samples at the given curve parameters (sorted (u, point) pairs)."""
    samples, knots, intervals = case.unpack(x)
    t = np.concatenate([[0.0], np.cumsum(intervals)])
    new_samples = [*samples]
    new_knots, new_intervals = [], []
    for k in range(len(knots)):
        new_knots.append(knots[k])
        cuts = [t[k]]
        for u, p in insertions:
            if t[k] < u < t[k + 1]:
                new_knots.append(p)
                new_samples.append(p)
                cuts.append(u)
        cuts.append(t[k + 1])
        new_intervals.extend(np.diff(cuts))
    return MirrorCase(new_samples, new_knots, new_intervals)


def with_crossings(case, x):
    """Every crossing of C1 with R(C1) off the axis that is not a sample becomes a mirror pair."""
    samples, knots, intervals = case.unpack(x)
    spline, t = closed_spline(knots, intervals)
    u = np.linspace(0, t[-1], 20000, endpoint=False)
    a = spline(u)
    b = np.roll(a, -1, axis=0)
    c, d = a * MIRROR, b * MIRROR
    scale = np.ptp(samples, axis=0).max()
    found = []
    for i in range(len(u)):
        r, s = b[i] - a[i], d - c
        den = r[0] * s[:, 1] - r[1] * s[:, 0]
        w = c - a[i]
        with np.errstate(divide="ignore", invalid="ignore"):
            along = (w[:, 0] * s[:, 1] - w[:, 1] * s[:, 0]) / den
            other = (w[:, 0] * r[1] - w[:, 1] * r[0]) / den
        for j in np.nonzero((along >= 0) & (along < 1) & (other >= 0) & (other < 1))[0]:
            p = a[i] + along[j] * r
            if np.min(np.linalg.norm(samples - p, axis=1)) > 1e-4 * scale and abs(p[0]) > 1e-4 * scale:
                found.append((u[i] + along[j] * (u[1] - u[0]), p))
    insertions = []
    for u_right, p in (e for e in found if e[1][0] > 0):  # each pair once, its mirror image exact
        u_left = min((e for e in found if e[1][0] < 0), key=lambda e: np.linalg.norm(e[1] - p * MIRROR))[0]
        insertions += [(u_right, p), (u_left, p * MIRROR)]
    return insert_samples(case, x, sorted(insertions, key=lambda e: e[0])), len(insertions) // 2


def with_pair(case, x, a, b):
    """A mirror pair on C1's stretch from sample a to sample b: q between C1 there and C2 nearby."""
    samples, knots, intervals = case.unpack(x)
    spline, t = closed_spline(knots, intervals)
    where = {i: k for k, (kind, i) in enumerate(case.layout) if kind == "sample"}
    ta = t[where[a]]
    tb = t[where[b]] if where[b] > where[a] else t[-1] + t[where[b]]
    u = np.linspace(0, t[-1], 20000, endpoint=False)
    curve = spline(u)
    for fraction in (0.5, 0.35, 0.65, 0.25, 0.75):
        um = (ta + fraction * (tb - ta)) % t[-1]
        c = spline(um)
        j = int(np.argmin(((curve - c * MIRROR) ** 2).sum(1)))
        q = 0.5 * (c + curve[j] * MIRROR)
        if abs(q[0]) > 0.15 * np.linalg.norm(spline(ta) - spline(tb % t[-1])) and abs(u[j] - um) > 1e-6:
            return insert_samples(case, x, sorted([(um, q), (u[j], q * MIRROR)], key=lambda e: e[0]))
    sys.exit(f"no room for a mirror pair on the stretch {a}-{b}")


def with_via_points(case, x, m):
    samples, knots, intervals = case.unpack(x)
    spline, t = closed_spline(knots, intervals)
    new_knots, new_intervals = [], []
    for k in range(len(knots)):
        for j in range(m + 1):
            new_knots.append(knots[k] if j == 0 else spline(t[k] + intervals[k] * j / (m + 1)))
            new_intervals.append(intervals[k] / (m + 1))
    return MirrorCase(samples, new_knots, new_intervals)


# ---- output ---------------------------------------------------------------------------------------

def bezier_path(knots, intervals, transform):
    spline, t = closed_spline(knots, intervals)
    f = lambda p: "%r %r" % tuple(float(v) for v in transform * p)
    d = "M " + f(spline(t[0]))
    for i in range(len(t) - 1):
        h = t[i + 1] - t[i]
        p0, p3 = spline(t[i]), spline(t[i + 1])
        d += f" C {f(p0 + spline(t[i], 1) * h / 3)} {f(p3 - spline(t[i + 1], 1) * h / 3)} {f(p3)}"
    return d + " Z"


def write_case(case, x, directory, curvebench, summary):
    samples, knots, intervals = case.unpack(x)
    paths = [bezier_path(knots, intervals, transform) for transform in (np.array([1.0, 1.0]), MIRROR)]
    record = {"via_points": 2 * case.via_count, "order_1": case.order(1), "order_2": case.order(2), **summary}
    return case_files.write_case(directory, samples, paths, [[case.order(1)], [case.order(2)]], curvebench, record)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("source")
    parser.add_argument("-o", "--out", required=True)
    parser.add_argument("--refine", type=int, default=0)
    parser.add_argument("--add-pair", action="append", default=[])
    parser.add_argument("--crossings", action="store_true")
    parser.add_argument("--per", type=int, default=4)
    parser.add_argument("--powers", default="200,1000,5000")
    parser.add_argument("--iterations", type=int, default=300)
    parser.add_argument("--hops", type=int, default=0)
    parser.add_argument("--hop-size", type=float, default=0.002)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--curvebench", default=os.path.join(here, "..", "build", "bench", "curvebench"))
    args = parser.parse_args()

    case = MirrorCase(*read_case(args.source))
    x = case.x0
    if args.refine:
        case = with_via_points(case, x, args.refine)
        x = case.x0
    for spec in args.add_pair:
        a, b = map(int, spec.split("-"))
        case = with_pair(case, x, a, b)
        x = case.x0
    added = 0
    if args.crossings:
        case, added = with_crossings(case, x)
        x = case.x0
    start = time.process_time()
    surrogate = case.ratios(x, args.per).max()
    print(f"start: {len(case.samples)} samples, {len(x)} variables, surrogate epsilon {surrogate:.4f}", flush=True)
    trial = args.out + ".trial"
    best = None
    if not (args.refine or args.add_pair or args.crossings):  # the source itself is a candidate
        best = (max(write_case(case, x, trial, args.curvebench, {})), x.copy())
    for power in map(float, args.powers.split(",")):
        x = minimize(case.power_mean, x, args=(power, args.per), method="L-BFGS-B",
                     options={"maxiter": args.iterations, "eps": 1e-7}).x
        epsilons = write_case(case, x, trial, args.curvebench, {})
        print(f"power {power:g}: surrogate {case.ratios(x, args.per).max():.4f}, measured {max(epsilons):.6f}",
              flush=True)
        if best is None or max(epsilons) < best[0]:
            best = (max(epsilons), x.copy())
    summary = {"source": os.path.basename(os.path.normpath(args.source)), "refine": args.refine,
               "added_pairs": args.add_pair, "crossing_pairs_added": added, "per": args.per,
               "powers": args.powers, "iterations": args.iterations, "hops": args.hops,
               "hop_size": args.hop_size, "seed": args.seed}
    write_case(case, best[1], args.out, args.curvebench, summary)
    rng = np.random.default_rng(args.seed)
    for hop in range(args.hops):  # basin hopping: L-BFGS stalls on the kinks of the max
        y = best[1] + args.hop_size * rng.standard_normal(len(x))
        for power in (300, 3000):
            y = minimize(case.power_mean, y, args=(power, args.per), method="L-BFGS-B",
                         options={"maxiter": 200, "eps": 1e-7}).x
        if case.ratios(y, args.per).max() < best[0] * 1.01:
            epsilons = write_case(case, y, trial, args.curvebench, {})
            if max(epsilons) < best[0]:  # written at once, so that a long run can be stopped
                best = (max(epsilons), y)
                write_case(case, y, args.out, args.curvebench, {**summary, "hops_done": hop + 1})
        print(f"hop {hop + 1}: best measured {best[0]:.6f}", flush=True)
    shutil.rmtree(trial)
    summary["cpu_seconds"] = round(time.process_time() - start, 1)
    epsilons = write_case(case, best[1], args.out, args.curvebench, summary)
    print(f"written {args.out}: epsilon {epsilons[0]!r} (C1), {epsilons[1]!r} (C2)")


if __name__ == "__main__":
    main()
