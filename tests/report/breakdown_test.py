#!/usr/bin/python3
"""Checks bench/report/breakdown.py against independent oracles:
- the fit solves the likelihood equations: fitted rates sum to the exact cases, overall and
  weighted by epsilon (what a maximum-likelihood logistic fit must satisfy), on random inputs;
- a step (exact exactly below t): the breakdown is the geometric mean of the last exact and the
  first inexact epsilon, and every interval end is near t (the gap a resample leaves);
- censoring: all exact is inf ('> largest'), none exact 0 ('< smallest');
- a rate logistic in ln epsilon with a closed-form breakdown, m (1/q - 1)^s: estimates near it, and
  the 95 % interval covering it in at least 16 of 20 seeded repeats at both levels.
"""
import math
import pathlib
import random
import sys

import numpy

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "bench" / "report"))
from breakdown import breakdown_intervals, logistic_fits  # noqa: E402

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


draw = random.Random(7)
for trial in range(200):
    n = draw.randint(20, 200)
    x = numpy.array([draw.uniform(-2, 2) for _ in range(n)])
    slope = draw.uniform(-3, -0.5)
    y = numpy.array([float(draw.random() < 1 / (1 + math.exp(-slope * v))) for v in x])
    if y.min() == y.max():
        continue
    a, b = logistic_fits(x, y, numpy.ones((1, n)))[0]
    p = 1 / (1 + numpy.exp(-(a + b * x)))
    check(abs((y - p).sum()) < 1e-3 and abs((x * (y - p)).sum()) < 1e-3 + 1e-6 * n * abs(b),
          f"trial {trial}: the fit does not solve the likelihood equations")

for t in (0.2, 0.33, 0.71):
    cases = [(i / 100, i / 100 < t) for i in range(5, 101)]
    for q, interval in breakdown_intervals(cases, levels=(0.95, 0.5, 0.05), resamples=50).items():
        check(abs(interval[0] - math.sqrt((t - 0.01) * t)) < 1e-12, f"step at {t}, q {q}: estimate {interval[0]}")
        check(all(t - 0.05 < v < t + 0.04 for v in interval), f"step at {t}, q {q}: {interval}")
everywhere = [(e / 10, True) for e in range(1, 11)]
check(breakdown_intervals(everywhere, resamples=20)[0.5] == (math.inf,) * 3, "all exact is not '> largest'")
nowhere = [(e / 10, False) for e in range(1, 11)]
check(breakdown_intervals(nowhere, resamples=20)[0.95] == (0.0,) * 3, "none exact is not '< smallest'")

# p(e) = 1 / (1 + exp((ln e - ln m) / s)) drops below q at e = m (1/q - 1)^s.
m, s = 0.5, 0.08
covered = {0.95: 0, 0.5: 0}
for repeat in range(20):
    rng = random.Random(100 + repeat)
    cases = []
    for _ in range(1000):
        e = rng.uniform(0.05, 1.0)
        cases.append((e, rng.random() < 1 / (1 + math.exp((math.log(e) - math.log(m)) / s))))
    for q, (estimate, low, high) in breakdown_intervals(cases, resamples=200, seed=repeat).items():
        truth = m * (1 / q - 1) ** s
        check(abs(estimate - truth) < 0.03, f"logistic, q {q}: estimate {estimate:.3f}, truth {truth:.3f}")
        check(low <= estimate <= high, f"logistic, q {q}: estimate {estimate} outside [{low}, {high}]")
        covered[q] += low <= truth <= high
for q, n in covered.items():
    check(n >= 16, f"logistic, q {q}: the interval covered the truth in {n} of 20 repeats")

for message in failures[:20]:
    print("FAIL:", message)
print(f"breakdown_test: {len(failures)} failures; coverage of the true breakdown in 20 repeats: {covered}")
sys.exit(1 if failures else 0)
