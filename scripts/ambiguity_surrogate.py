#!/usr/bin/python3
"""Searches one-curve ambiguity cases (issue 43) in families with k-fold rotational symmetry, by
L-BFGS on a smooth surrogate of the larger epsilon of two curves through the same points.

A case is a point set S and two simple closed C2 curves C1, C2 through S that visit it in different
cyclic orders (docs/tightness-and-ambiguity.md, "The ambiguity hunt"). Here both curves and S are
invariant under the rotation R by 2 pi / k, so one period stands for all: the variables are the
samples of one period (S is their k rotations), and for each curve its via points of one period and
its log knot intervals of one period. Each curve is the closed C2 cubic spline (periodic end
conditions) through its knots, the period's knot list repeated k times under R: a knot is a sample
of this or a neighbouring period, or a via point. The spline through rotated knots on repeated
intervals is itself R-invariant, so the surrogate evaluates one period only. The cyclic orders are
fixed by the knot lists (the combinatorics of the family) and never change during the search;
closure and C2 come from the periodic spline; simplicity is kept by the surrogate itself, since near
a self-crossing or cusp the medial balls shrink and the ratio blows up, and is checked at the end by
`curvebench measure` (which reads inf for a crossing or cusp).

Surrogate (as in scripts/ambiguity_descent.py, whose spline, Voronoi and medial-tip helpers it
reuses): each curve sampled at PER points per length lfs in one period; lfs the distance to the
centres of the medial balls of those samples (shrinking tangent balls against the whole curve,
rotated k times) and to the centres of curvature at curvature maxima (4 to 60 samples per knot
interval, counts fixed at the first evaluation); the ratio d(x, S) / lfs(x) at
the samples and at the curve's crossings with Voronoi edges of S. The objective is the power mean of
the ratios of both curves, exponents raised in stages (--powers), minimised by L-BFGS-B on finite
differences, then optional basin hops. Every value recorded is `curvebench measure`'s on the written
files (scripts/ambiguity_case_files.py); the surrogate's is printed as a guide only.

Families (--family):
  gear    the circle-chain ring (scripts/ambiguity_circle_chain.py, N = k circles per family) read
          as a ladder: per period the lens points P_i, Q_i (A_i with B_i) and P'_i, Q'_i (B_i with
          A_i+1). C1 runs over the A tops, down the lenses and under the B bottoms (the A circles
          with their inner arcs replaced by necks under B); C2 over the B tops and under the A
          bottoms. One closed curve each, around the centre; orders P Q Q' P' and P P' Q' Q+1.
  snake   the same ring, period two A and two B circles (k = N / 2): C1 keeps each A circle but one
          arc, alternately the inner and the outer one, and crosses B circles by diagonal necks
          (Q -> P', P -> Q'), a serpentine closed around the ring; C2 the same on the B circles.
  rotfourier  C1 a random simple Fourier curve with harmonics 1 + jk (R-invariant), C2 its mirror
          image in the x axis; S the crossings of the two (invariant under the dihedral group),
          kept only when the two cyclic orders differ. Via points between samples.
Starts differ by --seed: the ring's s/r, a Gaussian jitter of --jitter on every variable, or the
Fourier coefficients.

usage: scripts/ambiguity_surrogate.py --family gear|snake|rotfourier -k K -o OUT [--starts N]
           [--seed S] [--vias M] [--per P] [--powers 100,300,1000,3000] [--iterations N]
           [--hops N] [--hop-size H] [--jitter J] [--ratio U] [--seconds T] [--curvebench PATH]
Writes OUT/best (the best case, layout of docs/ambiguity/*/) and OUT/log.jsonl (one line per start).
Needs python3-numpy and python3-scipy; run single-threaded (it sets OMP_NUM_THREADS=1).
"""
import argparse
import json
import math
import os
import shutil
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
import numpy as np
from scipy.optimize import minimize

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ambiguity_case_files as case_files
from ambiguity_descent import bezier_path, bisector_crossings, closed_spline, osculating_centres
import ambiguity_circle_chain as chain


def rotation(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


# ---- the symmetric two-curve case ------------------------------------------------------------------

class SymCase:
    """k, the period's samples, and per curve a knot list of ('s', i, m) (sample i of period +m) or
    ('v', j, 0) (via j), with its via points and knot intervals of one period."""

    def __init__(self, k, samples, layouts, vias, intervals):
        self.k = k
        self.ns = len(samples)
        self.layouts = layouts
        self.nv = [len(v) for v in vias]
        self.R = [rotation(2 * math.pi * p / k) for p in range(k)]
        self.counts = [None, None]
        parts = [np.asarray(samples, float).ravel()]
        for c in (0, 1):
            parts += [np.asarray(vias[c], float).reshape(-1), np.log(np.asarray(intervals[c], float))]
        self.x0 = np.concatenate(parts)

    def unpack(self, x):
        ns, k = self.ns, self.k
        base = x[:2 * ns].reshape(-1, 2)
        S = np.vstack([base @ R.T for R in self.R])  # period p holds indices p * ns .. p * ns + ns - 1
        pos = 2 * ns
        curves = []
        for c in (0, 1):
            via = x[pos:pos + 2 * self.nv[c]].reshape(-1, 2)
            pos += 2 * self.nv[c]
            L = len(self.layouts[c])
            h = np.exp(x[pos:pos + L])
            pos += L
            period = np.array([base[i] @ self.R[m % k].T if kind == "s" else via[i]
                               for kind, i, m in self.layouts[c]])
            knots = np.vstack([period @ R.T for R in self.R])
            curves.append((knots, np.tile(h, k)))
        return S, curves

    def order(self, c):
        L, out = self.layouts[c], []
        for p in range(self.k):
            out += [((p + m) % self.k) * self.ns + i for kind, i, m in L if kind == "s"]
        return out

    def curve_ratios(self, S, knots, h, c, per):
        spline, t = closed_spline(knots, h)
        L = len(self.layouts[c])
        if self.counts[c] is None or self.counts[c][0] != per:
            fine = 24
            u = (t[:L, None] + np.outer(np.diff(t[:L + 1]), np.arange(fine) / fine)).ravel()
            step = np.linalg.norm(np.diff(spline(np.append(u, t[L])), axis=0), axis=1)
            # lfs estimated as for the search below, once, with a coarse grid
            self.counts[c] = (per, None)
            lfs = self._lfs(spline, t, S, u, c, coarse=True)
            units = (step / lfs).reshape(L, fine).sum(1)
            self.counts[c] = (per, np.clip(np.ceil(per * units), 4, 60).astype(int))
        cnt = self.counts[c][1]
        u = np.concatenate([t[j] + (t[j + 1] - t[j]) * np.arange(n) / n for j, n in enumerate(cnt)])
        q = np.vstack([spline(u), self._voronoi(spline, u, t[L], S)])
        return self._ratio(spline, t, S, u, q)

    def _medial(self, spline, t, u):
        x0 = spline(u)
        d0 = spline(u, 1)
        xs = np.vstack([x0 @ R.T for R in self.R])
        tangent = d0 / np.linalg.norm(d0, axis=1)[:, None]
        normal = np.stack([-tangent[:, 1], tangent[:, 0]], axis=1)
        v = xs[None, :, :] - x0[:, None, :]
        s = np.einsum("ijk,ik->ij", v, normal)
        vv = np.einsum("ijk,ijk->ij", v, v)
        s[vv < 1e-24] = 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            r = vv / (2 * s)
        centres = []
        for side in (1, -1):
            radius = np.where(side * s > 0, side * r, np.inf).min(axis=1)
            ok = np.isfinite(radius)
            centres.append(x0[ok] + side * radius[ok, None] * normal[ok])
        c0 = np.vstack(centres + [self._tips(spline, t, u, xs)])
        return np.vstack([c0 @ R.T for R in self.R])

    def _tips(self, spline, t, u, xs):
        """Medial-axis ends of one period (as medial_tips in ambiguity_descent.py: centres of curvature
        at curvature maxima, refined by golden section, kept when the osculating disk is empty)."""
        h = np.diff(u, append=2 * u[-1] - u[-2])
        def curvature(w):
            d1, d2 = spline(w, 1), spline(w, 2)
            return (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
        w = np.concatenate([[u[0] - h[0]], u, [u[-1] + h[-1]]])
        kk = curvature(w)
        tips = []
        for side in (1, -1):
            ks = side * kk
            peaks = np.nonzero((ks[1:-1] > 0) & (ks[1:-1] >= ks[:-2]) & (ks[1:-1] > ks[2:]))[0] + 1
            if len(peaks) == 0:
                continue
            tips.append(osculating_centres(spline, curvature, w[peaks - 1], w[peaks + 1], side, xs, 14))
        return np.vstack(tips) if tips else np.zeros((0, 2))

    def _lfs(self, spline, t, S, u, c, coarse=False):
        medial = self._medial(spline, t, u)
        q = spline(u)
        return np.sqrt(((q[:, None, :] - medial[None]) ** 2).sum(-1).min(1))

    def _ratio(self, spline, t, S, u, q):
        medial = self._medial(spline, t, u)
        lfs2 = ((q[:, None, :] - medial[None]) ** 2).sum(-1).min(1)
        d2 = ((q[:, None, :] - S[None]) ** 2).sum(-1).min(1)
        return np.sqrt(d2 / lfs2)

    @staticmethod
    def _voronoi(spline, u, u_end, S):
        uu = np.append(u, u_end)
        near = ((spline(uu)[:, None, :] - S[None]) ** 2).sum(-1).argmin(1)
        i = np.nonzero(near[:-1] != near[1:])[0]
        if len(i) == 0:
            return np.zeros((0, 2))
        return bisector_crossings(spline, S[near[i]], S[near[i + 1]], uu[i], uu[i + 1])

    def ratios(self, x, per):
        S, curves = self.unpack(x)
        return [self.curve_ratios(S, knots, h, c, per) for c, (knots, h) in enumerate(curves)]

    def objective(self, x, power, per):
        try:
            r = np.concatenate(self.ratios(x, per))
        except ValueError:
            return 1e9
        top = r.max()
        if not np.isfinite(top):
            return 1e9
        return top * np.mean((r / top) ** power) ** (1 / power)

    def surrogate(self, x, per):
        try:
            return float(max(r.max() for r in self.ratios(x, per)))
        except ValueError:
            return math.inf

    def write(self, x, directory, curvebench, record):
        S, curves = self.unpack(x)
        paths = [bezier_path(knots, h, np.array([1.0, 1.0])) for knots, h in curves]
        orders = [self.order(0), self.order(1)]
        rec = {"k": self.k, "via_points": [self.k * n for n in self.nv], "order_1": orders[0],
               "order_2": orders[1], **record}
        return case_files.write_case(directory, S, paths, [[orders[0]], [orders[1]]], curvebench, rec)


# ---- families --------------------------------------------------------------------------------------

def _ring_points(n, ratio, i):
    """P, Q (A_i with B_i, outer then inner) and P', Q' (B_i with A_i+1), and the circles."""
    fam = chain.ring(n, ratio)
    A, B, A1 = fam[0][i % n], fam[1][i % n], fam[0][(i + 1) % n]
    outer_first = lambda pts: sorted(pts, key=lambda p: -np.linalg.norm(p))
    P, Q = outer_first(chain.crossings(A, B))
    P1, Q1 = outer_first(chain.crossings(B, A1))
    return (P, Q, P1, Q1), (A, B, A1)


def _arc_points(circle, a, b, m, avoid):
    """m points strictly inside the arc of `circle` from a to b that does not contain `avoid`."""
    c, r = circle
    ang = lambda p: math.atan2(p[1] - c[1], p[0] - c[0])
    ta, tb, tv = ang(a), ang(b), ang(avoid)
    ccw = (tb - ta) % (2 * math.pi)
    if 0 < (tv - ta) % (2 * math.pi) < ccw:  # the ccw arc holds `avoid`: go clockwise
        ccw = ccw - 2 * math.pi
    return [c + r * np.array([math.cos(ta + ccw * j / (m + 1)), math.sin(ta + ccw * j / (m + 1))])
            for j in range(1, m + 1)]


def _build(k, samples, seq, vias_per_edge, close_rot):
    """Turns a per-period sequence of (('s', i, m) or ('v', point)) into layout, vias and intervals
    (chord lengths, centripetal-like)."""
    layout, vias, pts = [], [], []
    for item in seq:
        if item[0] == "s":
            layout.append(item)
            pts.append(np.asarray(samples[item[1]]) @ rotation(2 * math.pi * item[2] / k).T)
        else:
            layout.append(("v", len(vias), 0))
            vias.append(np.asarray(item[1]))
            pts.append(np.asarray(item[1]))
    nxt = pts[0] @ close_rot.T
    chords = [np.linalg.norm((pts[j + 1] if j + 1 < len(pts) else nxt) - pts[j]) for j in range(len(pts))]
    return layout, np.array(vias).reshape(-1, 2), np.maximum(np.array(chords), 1e-6)


def family_ring(kind, k, ratio, m):
    """gear (k = N) or snake (k = N / 2) on the circle-chain ring with s/r = ratio; m vias per arc."""
    n = k if kind == "gear" else 2 * k
    fam = chain.ring(n, ratio)
    A, B = fam
    if kind == "gear":
        (P, Q, P1, Q1), (Ai, Bi, Ai1) = _ring_points(n, ratio, 0)
        samples = [P, Q, P1, Q1]
        Qn = Q @ rotation(2 * math.pi / k).T
        Pn = P @ rotation(2 * math.pi / k).T
        Ai1n = (A[1 % n][0], A[1 % n][1])
        seq1 = [("s", 0, 0), *[("v", v) for v in _arc_points(Ai, P, Q, m, Ai[0] - (P - Ai[0]))],
                ("s", 1, 0), *[("v", v) for v in _arc_points(Bi, Q, Q1, m, P)],
                ("s", 3, 0), *[("v", v) for v in _arc_points(Ai1, Q1, P1, m, Ai1[0] - (P1 - Ai1[0]))],
                ("s", 2, 0), *[("v", v) for v in _arc_points(Ai1, P1, Pn, m, Q1)]]
        seq2 = [("s", 0, 0), *[("v", v) for v in _arc_points(Bi, P, P1, m, Q)],
                ("s", 2, 0), *[("v", v) for v in _arc_points(Bi, P1, Q1, m, Bi[0] - (P1 - Bi[0]))],
                ("s", 3, 0), *[("v", v) for v in _arc_points(Ai1, Q1, Qn, m, P1)],
                ("s", 1, 1), *[("v", v) for v in _arc_points(
                    (Bi[0] @ rotation(2 * math.pi / k).T, Bi[1]), Qn, Pn, m,
                    Bi[0] @ rotation(2 * math.pi / k).T - (Qn - Bi[0] @ rotation(2 * math.pi / k).T))]]
    else:
        (Pa, Qa, P1a, Q1a), (A0, B0, A1) = _ring_points(n, ratio, 0)
        (Pb, Qb, P1b, Q1b), (_, B1, A2) = _ring_points(n, ratio, 1)
        samples = [Pa, Qa, P1a, Q1a, Pb, Qb, P1b, Q1b]
        rot = rotation(2 * math.pi / k)
        opp = lambda circ, p: circ[0] - (p - circ[0])
        # C1: Pa Qa | P'a Q'a Qb Pb | Q'b P'b | -> Pa(+1)
        seq1 = [("s", 0, 0), *[("v", v) for v in _arc_points(A0, Pa, Qa, m, opp(A0, Pa))],
                ("s", 1, 0), ("v", B0[0]),
                ("s", 2, 0), *[("v", v) for v in _arc_points(A1, P1a, Q1a, m, opp(A1, P1a))],
                ("s", 3, 0), *[("v", v) for v in _arc_points(A1, Q1a, Qb, m, P1a)],
                ("s", 5, 0), *[("v", v) for v in _arc_points(A1, Qb, Pb, m, opp(A1, Qb))],
                ("s", 4, 0), ("v", B1[0]),
                ("s", 7, 0), *[("v", v) for v in _arc_points(A2, Q1b, P1b, m, opp(A2, Q1b))],
                ("s", 6, 0), *[("v", v) for v in _arc_points(A2, P1b, Pa @ rot.T, m, Q1b)]]
        # C2: Qa Pa P'a Q'a | Pb Qb Q'b P'b | -> Qa(+1)
        seq2 = [("s", 1, 0), *[("v", v) for v in _arc_points(B0, Qa, Pa, m, opp(B0, Qa))],
                ("s", 0, 0), *[("v", v) for v in _arc_points(B0, Pa, P1a, m, Qa)],
                ("s", 2, 0), *[("v", v) for v in _arc_points(B0, P1a, Q1a, m, opp(B0, P1a))],
                ("s", 3, 0), ("v", A1[0]),
                ("s", 4, 0), *[("v", v) for v in _arc_points(B1, Pb, Qb, m, opp(B1, Pb))],
                ("s", 5, 0), *[("v", v) for v in _arc_points(B1, Qb, Q1b, m, Pb)],
                ("s", 7, 0), *[("v", v) for v in _arc_points(B1, Q1b, P1b, m, opp(B1, Q1b))],
                ("s", 6, 0), ("v", A2[0])]
    close = rotation(2 * math.pi / k)
    l1, v1, h1 = _build(k, samples, seq1, m, close)
    l2, v2, h2 = _build(k, samples, seq2, m, close)
    return SymCase(k, samples, [l1, l2], [v1, v2], [h1, h2])


def _polyline_crossings(a, b):
    """Crossings of closed polylines a and b (a == b: self-crossings, neighbours skipped):
    (index in a, fraction, index in b, fraction, point)."""
    out = []
    a1, b1 = np.roll(a, -1, axis=0), np.roll(b, -1, axis=0)
    r, s = a1 - a, b1 - b
    for i in range(len(a)):
        den = r[i, 0] * s[:, 1] - r[i, 1] * s[:, 0]
        w = b - a[i]
        with np.errstate(divide="ignore", invalid="ignore"):
            al = (w[:, 0] * s[:, 1] - w[:, 1] * s[:, 0]) / den
            ot = (w[:, 0] * r[i, 1] - w[:, 1] * r[i, 0]) / den
        hit = np.nonzero((al >= 0) & (al < 1) & (ot >= 0) & (ot < 1))[0]
        for j in hit:
            if a is b and min(abs(i - j), len(a) - abs(i - j)) <= 1:
                continue
            out.append((i, al[j], j, ot[j], a[i] + al[j] * r[i]))
    return out


def family_rotfourier(k, rng, m, tries=400):
    """C1(t) = sum c_n e^{i n t}, n = 1 + j k; C2(t) = conj(C1(-t)); S = their crossings."""
    grid = 720 * max(1, k // 4)
    for _ in range(tries):
        js = [j for j in (-2, -1, 1, 2) if 1 + j * k != 0]
        coef = {1: 1.0}
        for j in js:
            mag = rng.uniform(0, 0.5) / abs(1 + j * k) ** 0.5
            coef[1 + j * k] = mag * np.exp(1j * rng.uniform(0, 2 * math.pi))
        f = lambda t: sum(c * np.exp(1j * n * t) for n, c in coef.items())
        t = np.linspace(0, 2 * math.pi, grid, endpoint=False)
        z1 = f(t)
        a = np.stack([z1.real, z1.imag], 1)
        if _polyline_crossings(a, a):
            continue
        z2 = np.conj(f(-t))
        b = np.stack([z2.real, z2.imag], 1)
        cr = _polyline_crossings(a, b)
        if len(cr) < 2 * k:
            continue
        pts = np.array([c[4] for c in cr])
        tau1 = np.array([(c[0] + c[1]) * 2 * math.pi / grid for c in cr])
        tau2 = np.array([(c[2] + c[3]) * 2 * math.pi / grid for c in cr])
        # representatives: crossings with polar angle in [0, 2 pi / k)
        # (the window starts off the mirror lines, at angles j pi / k, where crossings lie)
        ang = (np.arctan2(pts[:, 1], pts[:, 0]) - math.pi / (2 * k)) % (2 * math.pi)
        reps = np.nonzero(ang < 2 * math.pi / k)[0]
        if len(reps) * k != len(pts):
            continue
        base = pts[reps]
        ident = []
        for p, a_ in zip(pts, ang):
            mm = int(a_ // (2 * math.pi / k)) % k
            back = p @ rotation(-2 * math.pi * mm / k).T
            i = int(np.argmin(((base - back) ** 2).sum(1)))
            ident.append((i, mm))
        def order(tau):
            idx = np.argsort(tau)
            return [ident[j][1] * len(base) + ident[j][0] for j in idx], tau[idx]
        o1, t1 = order(tau1)
        o2, t2 = order(tau2)
        if _same_cycle(o1, o2):
            continue
        close = min((np.linalg.norm(p - q) for i, p in enumerate(pts) for q in pts[:i]), default=1.0)
        if close < 2e-3:
            continue
        # per-period layouts: samples met for tau in [0, 2 pi / k)
        seqs = []
        for tau, curve in ((tau1, f), (tau2, lambda s: np.conj(f(-s)))):
            sel = np.argsort(tau)
            sel = [j for j in sel if tau[j] < 2 * math.pi / k]
            taus = [tau[j] for j in sel] + [tau[sel[0]] + 2 * math.pi / k]
            seq, hs = [], []
            for q, j in enumerate(sel):
                seq.append(("s", ident[j][0], ident[j][1]))
                for v in range(1, m + 1):
                    z = curve(taus[q] + (taus[q + 1] - taus[q]) * v / (m + 1))
                    seq.append(("v", np.array([z.real, z.imag])))
                hs += [(taus[q + 1] - taus[q]) / (m + 1)] * (m + 1)
            seqs.append((seq, np.array(hs)))
        layouts, vias, hh = [], [], []
        for seq, hs in seqs:
            l, v, _ = _build(k, base, seq, m, rotation(2 * math.pi / k))
            layouts.append(l), vias.append(v), hh.append(hs / hs.mean())
        return SymCase(k, base, layouts, vias, hh), {"coefficients": {str(n): [float(np.real(c)), float(np.imag(c))]
                                                                        for n, c in coef.items()}}
    return None, None


def _same_cycle(a, b):
    if len(a) != len(b):
        return False
    n = len(a)
    for bb in (b, b[::-1]):
        i = bb.index(a[0])
        if all(a[j] == bb[(i + j) % n] for j in range(n)):
            return True
    return False


# ---- search ----------------------------------------------------------------------------------------

class _OutOfTime(Exception):
    pass


def descend(case, x, powers, per, iterations, verbose=False, deadline=math.inf):
    """L-BFGS-B on the power mean, one stage per exponent; stops at the CPU deadline with the best
    point seen in the current stage."""
    for power in powers:
        seen = [case.objective(x, power, per), x.copy()]

        def f(y):
            if time.process_time() > deadline:
                raise _OutOfTime
            v = case.objective(y, power, per)
            if v < seen[0]:
                seen[0], seen[1] = v, y.copy()
            return v
        try:
            x = minimize(f, x, method="L-BFGS-B", options={"maxiter": iterations, "eps": 1e-7}).x
        except _OutOfTime:
            x = seen[1]
            if verbose:
                print(f"  power {power:g}: out of time, surrogate {case.surrogate(x, per):.4f}", flush=True)
            break
        if verbose:
            print(f"  power {power:g}: surrogate {case.surrogate(x, per):.4f}", flush=True)
    return x


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--family", required=True, choices=["gear", "snake", "rotfourier"])
    parser.add_argument("-k", type=int, required=True, help="rotational symmetry order")
    parser.add_argument("-o", "--out", required=True)
    parser.add_argument("--starts", type=int, default=1)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--vias", type=int, default=1, help="via points per arc between samples")
    parser.add_argument("--per", type=int, default=4)
    parser.add_argument("--powers", default="100,300,1000,3000")
    parser.add_argument("--iterations", type=int, default=150)
    parser.add_argument("--hops", type=int, default=0)
    parser.add_argument("--hop-size", type=float, default=0.003)
    parser.add_argument("--jitter", type=float, default=0.0)
    parser.add_argument("--seconds", type=float, default=math.inf, help="CPU seconds per start")
    parser.add_argument("--ratio", type=float, help="ring s/r (gear, snake); default drawn in [1.3, 1.9]")
    parser.add_argument("--curvebench", default=os.path.join(here, "..", "build", "bench", "curvebench"))
    args = parser.parse_args()
    powers = [float(p) for p in args.powers.split(",")]
    rng = np.random.default_rng(args.seed)
    os.makedirs(args.out, exist_ok=True)
    trial = os.path.join(args.out, "trial")
    best = None
    log = open(os.path.join(args.out, "log.jsonl"), "a")
    clock = time.process_time()
    for start in range(args.starts):
        t0 = time.process_time()
        info = {"family": args.family, "k": args.k, "seed": args.seed, "start": start}
        if args.family == "rotfourier":
            case, extra = family_rotfourier(args.k, rng, args.vias)
            if case is None:
                print(f"start {start}: no admissible Fourier curve", flush=True)
                continue
            info.update(extra)
        else:
            ratio = args.ratio if args.ratio else float(rng.uniform(1.3, 1.9))
            n = args.k if args.family == "gear" else 2 * args.k
            ratio = max(ratio, 1 / math.cos(math.pi / (2 * n)) + 1e-3)
            info["ratio"] = ratio
            case = family_ring(args.family, args.k, ratio, args.vias)
        x = case.x0.copy()
        if args.jitter:
            scale = np.ptp(case.unpack(x)[0], axis=0).max()
            npos = len(x) - sum(len(l) for l in case.layouts)
            x[:npos] += args.jitter * scale / args.k * rng.standard_normal(npos)
        eps0 = case.write(x, trial, args.curvebench, {})
        s0 = case.surrogate(x, args.per)
        x = descend(case, x, powers, args.per, args.iterations, verbose=True, deadline=t0 + args.seconds)
        eps = case.write(x, trial, args.curvebench, {})
        s1 = case.surrogate(x, args.per)
        hop_best = (max(eps), x.copy(), eps)
        for hop in range(args.hops):
            y = hop_best[1] + args.hop_size * rng.standard_normal(len(x))
            if time.process_time() > t0 + args.seconds:
                break
            y = descend(case, y, (300, 3000), args.per, 100, deadline=t0 + args.seconds)
            if case.surrogate(y, args.per) < hop_best[0] * 1.02:
                e = case.write(y, trial, args.curvebench, {})
                if max(e) < hop_best[0]:
                    hop_best = (max(e), y.copy(), e)
        info.update({"samples": case.k * case.ns, "variables": len(x), "start_measured": max(eps0),
                     "start_surrogate": s0, "descent_measured": max(eps), "descent_surrogate": s1,
                     "hops": args.hops, "seconds_cap": args.seconds, "measured": hop_best[2], "max_measured": hop_best[0],
                     "cpu_seconds": round(time.process_time() - t0, 1)})
        print(json.dumps(info), flush=True)
        log.write(json.dumps(info) + "\n")
        log.flush()
        if best is None or hop_best[0] < best[0]:
            best = (hop_best[0], hop_best[1], case, info)
            best[2].write(best[1], os.path.join(args.out, "best"), args.curvebench,
                          {"family": args.family, "start": info, "command": " ".join(sys.argv),
                           "surrogate": best[2].surrogate(best[1], args.per)})
    shutil.rmtree(trial, ignore_errors=True)
    if best:
        print(f"best measured max epsilon {best[0]!r} (start {best[3]['start']}), "
              f"cpu {time.process_time() - clock:.1f} s, written {os.path.join(args.out, 'best')}")


if __name__ == "__main__":
    main()
