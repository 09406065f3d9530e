#!/usr/bin/python3
"""Turns the results.csv of `curvebench run SUITE -o DIR` into DIR/report.html, DIR/charts/*.svg and the
interactive DIR/explorer.html (explorer.py).

Usage: /usr/bin/python3 bench/report/make_report.py DIR

The charts mirror the survey's "Quantitative Evaluation" figures: mean RMS and exact
reconstruction % per algorithm and level, mean runtime (log scale) and a status overview.
An algorithm that simplifies rather than interpolates (DIR/algorithms.csv, from the registry:
Optimal Transport) is scored apart, as the survey does: "n/a (simplifies)" wherever algorithms
are ranked by exactness, and a section of its own with distances both ways, topology and size.
/usr/bin/python3 because Debian's python3-matplotlib is installed for that interpreter only.
"""
import collections
import csv
import datetime
import html
import json
import math
import pathlib
import re
import statistics
import sys
import urllib.parse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

from breakdown import breakdown_intervals, fmt_breakdown  # noqa: E402  (beside this script)
from explorer import write_explorer  # noqa: E402

STATUS_COLOURS = {"ok": "#4c9a2a", "failed": "#f0a030", "invalid-output": "#8c564b", "crashed": "#d62728",
                  "timeout": "#7b4ea3"}
GALLERY_CAP = 48  # pictures per suite, so that the page stays light
NOT_DRAWN = "×"  # marks a bar with no value (no ok job with ground truth)

plt.rcParams.update({"svg.hashsalt": "curvebench", "font.size": 10, "axes.spines.top": False,
                     "axes.spines.right": False})


def esc(value):
    return html.escape(str(value), quote=True)


def number(text):
    """A finite float, or None for empty/unparsable/non-finite cells."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def flag(text):
    return {"1": True, "0": False}.get(text)


def mean(values):
    values = [v for v in values if v is not None]
    return statistics.fmean(values) if values else None


def percent(flags):
    flags = [f for f in flags if f is not None]
    return 100.0 * sum(flags) / len(flags) if flags else None


def wilson(flags, z=1.959964):
    """(successes, n, low %, high %): the Wilson score interval, 95% by default."""
    flags = [f for f in flags if f is not None]
    n, k = len(flags), sum(flags)
    if n == 0:
        return 0, 0, None, None
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return k, n, 100 * max(0.0, centre - half), 100 * min(1.0, centre + half)


# Student's t, 97.5 % quantile, for 1 to 30 degrees of freedom (beyond: the Cornish-Fisher
# expansion around the normal quantile, within 1e-4 of the true value there).
T975 = (12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145, 2.131,
        2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042)


def t975(df):
    if df <= len(T975):
        return T975[df - 1]
    z = 1.959964
    return z + (z ** 3 + z) / (4 * df) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * df * df)


def mean_interval(values):
    """(mean, n, low, high): the mean with its Student-t 95% confidence interval (None bounds below 2 values)."""
    values = [v for v in values if v is not None and math.isfinite(v)]
    n = len(values)
    if n == 0:
        return None, 0, None, None
    m = statistics.fmean(values)
    if n == 1:
        return m, 1, None, None
    half = t975(n - 1) * statistics.stdev(values) / math.sqrt(n)
    return m, n, m - half, m + half


def fmt_mean(interval):
    m, n, low, high = interval
    if n == 0:
        return "–"
    return f"{m:.3g}" + ("" if low is None else f" ±{(high - low) / 2:.2g}")


def fmt_share(interval):
    k, n, low, high = interval
    return "–" if n == 0 else f"{100 * k / n:.0f}% [{low:.0f}–{high:.0f}] of {n}"


def fmt(value, spec=".3g", suffix=""):
    return "–" if value is None else format(value, spec) + suffix


def level_key(level):
    """Levels sort by name, then numerically by value; the empty level last."""
    name, _, value = level.partition("=")
    parsed = number(value)
    return (level == "", name, parsed is None, parsed if parsed is not None else 0.0, value)


def safe_name(text):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text) or "_"


def counted(n, noun):
    return f"<b>{n}</b> {noun}{'' if n == 1 else 's'}"


def ordered(values):
    return list(dict.fromkeys(values))


COLUMNS = ("job suite input level algorithm params n_points epsilon rho uniformity status exact hausdorff rms "
           "hausdorff_to_curve rms_to_curve hausdorff_from_curve rms_from_curve normal_deviation manifold components "
           "open_components closed_components unconnected output_points true_topology runtime_ms startup_ms picture "
           "message").split()
SIMPLIFIES = "n/a (simplifies)"  # an exactness cell of an algorithm that simplifies


def read_rows(path):
    """Every row has every column as a string: missing columns and short rows read as ''."""
    with open(path, newline="", encoding="utf-8") as f:
        return [{c: (row.get(c) or "").strip() for c in COLUMNS} for row in csv.DictReader(f)]


def read_simplifiers(out_dir):
    """The algorithms DIR/algorithms.csv (written by `curvebench run` and `report`) marks as simplifying; none
    without that file."""
    path = pathlib.Path(out_dir) / "algorithms.csv"
    if not path.is_file():
        return frozenset()
    with open(path, newline="", encoding="utf-8") as f:
        return frozenset(r["algorithm"] for r in csv.DictReader(f) if r.get("simplifies") == "1")


class Run:
    """The rows plus derived orderings and per-row facts shared by charts and tables. `simplifiers`: the algorithms
    that simplify (read_simplifiers), whose jobs count in no exactness share."""

    def __init__(self, rows, simplifiers=frozenset()):
        self.rows = rows
        self.suites = ordered(r["suite"] for r in rows)
        self.algorithms = ordered(r["algorithm"] for r in rows)
        self.simplifiers = [a for a in self.algorithms if a in simplifiers]
        # tab20's strong colours first: they equal tab10's, so the first ten algorithms keep
        # their colours when more are added.
        tab20 = plt.get_cmap("tab20").colors
        palette = tab20[0::2] + tab20[1::2]
        self.colour = {a: palette[i % len(palette)] for i, a in enumerate(self.algorithms)}
        # A failed job on an input with ground truth counts as not exact, so that failing
        # cannot raise an algorithm's exact %; on an input without ground truth it does not count.
        truth_inputs = {r["input"] for r in rows if flag(r["exact"]) is not None}
        for r in rows:
            r["_ok"] = r["status"] == "ok"
            r["_exact"] = flag(r["exact"])
            if not r["_ok"] and r["input"] in truth_inputs:
                r["_exact"] = False
            # A failed job on an input with ground truth has the wrong topology, as it is not exact.
            r["_true_topology"] = flag(r["true_topology"]) if r["_ok"] else (False if r["_exact"] is False else None)
            # A simplifier's output is never the input's edge set, by design: it is no miss ("The Benchmark",
            # "Algorithms": the survey leaves Optimal Transport out of every experiment).
            r["_simplifies"] = r["algorithm"] in simplifiers
            if r["_simplifies"]:
                r["_exact"] = r["_true_topology"] = None

    def simplifies(self, algorithm):
        return algorithm in self.simplifiers
    def suite_rows(self, suite):
        return [r for r in self.rows if r["suite"] == suite]


def group_stats(rows):
    ok = [r for r in rows if r["_ok"]]
    failures = collections.Counter(r["status"] or "(empty)" for r in rows if not r["_ok"])
    exact = wilson(r["_exact"] for r in rows)
    rms = mean_interval(number(r["rms"]) for r in ok)
    hausdorff = mean_interval(number(r["hausdorff"]) for r in ok)
    return {
        "jobs": len(rows),
        "exact": 100 * exact[0] / exact[1] if exact[1] else None,
        "exact_interval": exact,
        "rms": rms[0],
        "rms_interval": rms,
        "hausdorff": hausdorff[0],
        "hausdorff_interval": hausdorff,
        "manifold": percent(flag(r["manifold"]) for r in ok),
        "true_topology": wilson(r["_true_topology"] for r in rows),
        "runtime": mean(number(r["runtime_ms"]) for r in ok),
        # An external program's start-up (its wall time on no points), included in its runtime.
        "startup": mean(number(r["startup_ms"]) for r in rows if r["startup_ms"]),
        "failures": failures,
    }


def mcnemar(b, c):
    """Exact two-sided McNemar test: the p-value of b and c discordant pairs (binomial, 1/2)."""
    n = b + c
    if n == 0:
        return 1.0
    tail = sum(math.comb(n, i) for i in range(min(b, c) + 1)) / 2 ** n
    return min(1.0, 2 * tail)


def paired_flags(rows, algorithm, key):
    """{instance: flag} of one algorithm's jobs; an instance is an input at a level."""
    return {(r["input"], r["level"]): r[key] for r in rows if r["algorithm"] == algorithm and r[key] is not None}


LEADER_ALPHA = 0.05  # McNemar's level: an algorithm with p >= it against the best leads too


def leaders(rows, algorithms, key):
    """The algorithms with the highest share of `key`, and those not significantly below it (McNemar's test on the
    instances both ran). Returns ({algorithm: (share interval, p-value against the best)}, best)."""
    flags = {a: paired_flags(rows, a, key) for a in algorithms}
    shares = {a: wilson(f.values()) for a, f in flags.items()}
    shares = {a: w for a, w in shares.items() if w[1] > 0}
    if not shares:
        return {}, None
    best = max(shares, key=lambda a: (shares[a][0] / shares[a][1], shares[a][1]))
    result = {}
    for a, w in shares.items():
        common = flags[best].keys() & flags[a].keys()
        b = sum(1 for i in common if flags[best][i] and not flags[a][i])
        c = sum(1 for i in common if flags[a][i] and not flags[best][i])
        result[a] = (w, 1.0 if a == best else mcnemar(b, c))
    return result, best


# ---------------------------------------------------------------- charts

def save(fig, path):
    fig.savefig(path, format="svg", bbox_inches="tight", metadata={"Date": None})
    plt.close(fig)


def tick_labels(ax, labels):
    """Long labels are rotated so that neighbours do not overlap."""
    long = max((len(s) for s in labels), default=0) > 8
    ax.set_xticklabels(labels, rotation=30 if long else 0, ha="right" if long else "center")


def log_limits(values):
    """Log scale limits when the positive values span more than two decades, else None."""
    positive = [v for v in values if v is not None and v > 0]
    if not positive or max(positive) / min(positive) <= 100:
        return None
    return 10 ** math.floor(math.log10(min(positive))), 10 ** math.ceil(math.log10(max(positive)) + 0.1)


def mark_undrawn(ax, x, value, colour, bottom):
    """Bars that cannot show (no value, or 0 on any axis) get a small text mark at the base."""
    if value is None or value <= 0:
        ax.text(x, bottom, NOT_DRAWN if value is None else "0", ha="center", va="bottom",
                fontsize=8, color=colour, fontweight="bold")


def grouped_bars(run, rows, metric, title, ylabel, path, percent_axis=False):
    """Levels on the x axis, one bar per algorithm (the survey's RMS figures)."""
    levels = sorted(ordered(r["level"] for r in rows), key=level_key)
    algorithms = [a for a in run.algorithms if any(r["algorithm"] == a for r in rows)]
    stats = {(a, lv): group_stats([r for r in rows if r["algorithm"] == a and r["level"] == lv])
             for a in algorithms for lv in levels}
    value = {key: st[metric] for key, st in stats.items()}
    interval = {key: st[metric + "_interval"] for key, st in stats.items()}
    names = {lv.partition("=")[0] for lv in levels if lv}
    single = len(names) == 1 and "" not in levels
    labels = [lv.partition("=")[2] if single else (lv or "all inputs") for lv in levels]

    width = 0.8 / len(algorithms)
    fig, ax = plt.subplots(figsize=(min(13.0, max(5.0, 1.5 + len(levels) * max(1.3, 0.25 * len(algorithms)))), 4.0))
    limits = None if percent_axis else log_limits(value.values())
    if limits:
        ax.set_yscale("log")
        ax.set_ylim(*limits)
    elif percent_axis:
        ax.set_ylim(0, 105)
    else:
        top = max((v for v in value.values() if v is not None), default=0)
        ax.set_ylim(0, top * 1.1 if top > 0 else 1)
    bottom = ax.get_ylim()[0]
    for i, a in enumerate(algorithms):
        xs = [j + (i - (len(algorithms) - 1) / 2) * width for j in range(len(levels))]
        # On a log axis a bar starts at the lower limit, not at 0.
        heights = [max((value[a, lv] or 0) - bottom, 0) for lv in levels]
        ax.bar(xs, heights, width, bottom=bottom,
               color=run.colour[a], label=a, edgecolor="white", linewidth=0.5)
        # The 95% interval of each bar (Wilson for a share, Student t for a mean).
        for x, lv in zip(xs, levels):
            centre, (_, n, low, high) = value[a, lv], interval[a, lv]
            if centre is None or low is None or n == 0:
                continue
            low, high = max(low, bottom), high
            if high > low:
                ax.plot([x, x], [low, high], color="#333333", linewidth=0.8)
        for x, lv in zip(xs, levels):
            mark_undrawn(ax, x, value[a, lv], run.colour[a], bottom)
    ax.set_xticks(range(len(levels)))
    tick_labels(ax, labels)
    ax.set_xlabel(names.pop() if single else "level" if names else "")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(axis="y", alpha=0.3)
    ax.legend(title="algorithm", loc="upper left", bbox_to_anchor=(1.01, 1), frameon=False)
    save(fig, path)


def runtime_chart(run, path):
    """Mean runtime of ok jobs per algorithm on a log axis (the survey's runtime figure)."""
    stats = [group_stats([r for r in run.rows if r["algorithm"] == a]) for a in run.algorithms]
    values = [st["runtime"] for st in stats]
    startups = [st["startup"] for st in stats]
    positive = [v for v in values + startups if v is not None and v > 0]  # make_charts ensures one
    fig, ax = plt.subplots(figsize=(max(6.0, 1.0 + 0.6 * len(run.algorithms)), 4.0))
    ax.set_yscale("log")
    lo = 10 ** math.floor(math.log10(min(positive)))
    ax.set_ylim(lo, 10 ** math.ceil(math.log10(max(positive)) + 0.3))
    ax.set_xlim(-0.6, len(run.algorithms) - 0.4)  # also when the last algorithms have no bar
    for x, (a, v) in enumerate(zip(run.algorithms, values)):
        if v is not None and v > 0:
            ax.bar(x, v - lo, 0.7, bottom=lo, color=run.colour[a])
            ax.text(x, v, format(v, ".3g"), ha="center", va="bottom", fontsize=8)
        else:
            mark_undrawn(ax, x, v, run.colour[a], lo)
    # A program's start-up, part of its runtime, as a black line across its bar.
    for x, startup in enumerate(startups):
        if startup is not None and startup > 0:
            ax.plot([x - 0.35, x + 0.35], [startup, startup], color="black", linewidth=2)
            ax.text(x + 0.37, startup, f"start-up {startup:.3g}", fontsize=7, va="center")
    ax.set_xticks(range(len(run.algorithms)))
    tick_labels(ax, run.algorithms)
    ax.set_ylabel("mean runtime per job [ms] (log)")
    ax.set_title("Runtime per algorithm (ok jobs, all suites)")
    ax.grid(axis="y", alpha=0.3)
    save(fig, path)


def status_chart(run, path):
    """Stacked job counts per status and algorithm."""
    statuses = ordered(list(STATUS_COLOURS) + [r["status"] for r in run.rows])
    counts = {a: collections.Counter(r["status"] for r in run.rows if r["algorithm"] == a) for a in run.algorithms}
    fig, ax = plt.subplots(figsize=(max(6.0, 1.0 + 0.6 * len(run.algorithms)), 4.0))
    base = [0] * len(run.algorithms)
    for s in statuses:
        heights = [counts[a][s] for a in run.algorithms]
        if any(heights):
            ax.bar(range(len(run.algorithms)), heights, 0.7, bottom=base, label=s or "(empty)",
                   color=STATUS_COLOURS.get(s, "#999999"))
            base = [b + h for b, h in zip(base, heights)]
    ax.set_xticks(range(len(run.algorithms)))
    tick_labels(ax, run.algorithms)
    ax.set_ylabel("jobs")
    ax.set_title("Job status per algorithm (all suites)")
    ax.yaxis.get_major_locator().set_params(integer=True)
    ax.legend(title="status", loc="upper left", bbox_to_anchor=(1.01, 1), frameon=False)
    save(fig, path)


def read_theorems(path):
    """{algorithm: proven epsilon bound} from DIR/theorems.csv (written by `curvebench run`), or {}."""
    if not path.is_file():
        return {}
    with open(path, newline="", encoding="utf-8") as f:
        return {r["algorithm"]: float(r["epsilon_below"]) for r in csv.DictReader(f)}


BIN = 0.05  # width of the measured-epsilon and rho bins of the breakdown
BREAKDOWN_UP_TO = 1.0  # sparser samplings (or lfs near 0 at an unsampled corner) are left out


def breakdown(run, rows, measure, theorems):
    """{algorithm: [(bin start, cases, exact)]} over rows with a measured value, for algorithms with a theorem."""
    table = {}
    for algorithm in (a for a in run.algorithms if a in theorems):
        bins = collections.defaultdict(lambda: [0, 0])
        for r in rows:
            value = number(r[measure])
            if r["algorithm"] != algorithm or value is None or not value <= BREAKDOWN_UP_TO or r["_exact"] is None:
                continue
            b = bins[math.floor(value / BIN + 1e-9) * BIN]
            b[0] += 1
            b[1] += bool(r["_exact"])
        table[algorithm] = sorted((start, n, exact) for start, (n, exact) in bins.items())
    return table


def breakdown_chart(run, table, theorems, measure, path):
    """Exact-reconstruction rate per bin of the measured value, a line per algorithm, its bound dashed."""
    fig, ax = plt.subplots(figsize=(9, 4.2))
    for algorithm, bins in table.items():
        colour = run.colour[algorithm]
        ax.plot([s + BIN / 2 for s, _, _ in bins], [100 * e / n for _, n, e in bins], marker="o", ms=3,
                color=colour, label=algorithm)
        if measure == "epsilon":
            ax.axvline(theorems[algorithm], color=colour, ls="--", lw=1)
    ax.set_xlabel(f"measured {measure} (bins of {BIN})" + ("; dashed: the proven bound" if measure == "epsilon" else ""))
    ax.set_ylabel("exact reconstructions [%]")
    ax.set_ylim(-3, 103)
    ax.set_title(f"certify: exact reconstruction against the measured {measure}")
    ax.grid(alpha=0.3)
    ax.legend(title="algorithm", loc="upper left", bbox_to_anchor=(1.01, 1), frameon=False)
    save(fig, path)


def write_breakdown_csv(path, tables):
    with open(path, "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f)
        out.writerow(["measure", "algorithm", "bin_start", "bin_end", "cases", "exact", "exact_percent"])
        for measure, table in tables.items():
            for algorithm, bins in table.items():
                for start, n, exact in bins:
                    out.writerow([measure, algorithm, f"{start:.2f}", f"{start + BIN:.2f}", n, exact,
                                  f"{100 * exact / n:.1f}"])


BREAKDOWN_SUITES = ("breakdown", "certify")  # smooth closed curves over a range of measured epsilons
# Beyond this measured epsilon a curve keeps a handful of samples, whose polygon is often easy
# again (measured on the breakdown suite: NN-Crust exact on 63 % at 1.1-1.6, 37 % at 1.6-2.3,
# 61 % at 2.3-3.2), so the rate is no longer a breakdown; and a measure far above the sampler's
# level comes from lfs below its floor at a tiny feature.
BREAKDOWN_TABLE_UP_TO = 2.0


def breakdown_table(run, theorems, csv_path):
    """The empirical breakdown of every algorithm with ground truth (breakdown.py), as an HTML section;
    also written to csv_path. Empty without a breakdown suite."""
    rows = [r for r in run.rows if r["suite"] in BREAKDOWN_SUITES]
    out = []
    for algorithm in run.algorithms:
        cases = [(number(r["epsilon"]), bool(r["_exact"])) for r in rows if r["algorithm"] == algorithm
                 and r["_exact"] is not None and 0 < (number(r["epsilon"]) or math.inf) <= BREAKDOWN_TABLE_UP_TO]
        if len(cases) >= 10:
            out.append((algorithm, cases, breakdown_intervals(cases)))
    apart = [a for a in run.simplifiers if any(r["algorithm"] == a for r in rows)]
    if not out:
        return ""
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        table = csv.writer(f)
        table.writerow(["algorithm", "cases", "exact", "smallest_epsilon", "largest_epsilon", "proven_bound"]
                       + [f"{name}_{int(100 * q)}" for q in (0.95, 0.5) for name in ("breakdown", "low", "high")])
        for algorithm, cases, found in out:
            table.writerow([algorithm, len(cases), sum(e for _, e in cases), min(e for e, _ in cases),
                            max(e for e, _ in cases), theorems.get(algorithm, "")]
                           + [v for q in (0.95, 0.5) for v in found[q]])
    html_rows = []
    for algorithm, cases, found in out:
        smallest, largest = min(e for e, _ in cases), max(e for e, _ in cases)
        bound = theorems.get(algorithm)
        html_rows.append(f"<tr><td>{esc(algorithm)}</td><td class=n>{len(cases)}</td>"
                         f"<td class=n>{esc(fmt_share(wilson([e for _, e in cases])))}</td>"
                         + "".join(f"<td class=n>{esc(fmt_breakdown(found[q], smallest, largest))}</td>"
                                   for q in (0.95, 0.5))
                         + f"<td class=n>{esc(fmt(bound, '.3g')) if bound else '–'}</td></tr>")
    for algorithm in apart:
        cases = sum(1 for r in rows if r["algorithm"] == algorithm)
        html_rows.append(f"<tr><td>{esc(algorithm)}</td><td class=n>{cases}</td>"
                         + f"<td class=na>{SIMPLIFIES}</td>" * 3 + "<td class=n>–</td></tr>")
    suites = ", ".join(s for s in BREAKDOWN_SUITES if s in run.suites)
    return ("<h2 id=breakdown>Empirical breakdown</h2><table><tr><th>algorithm</th><th>cases</th><th>exact</th>"
            "<th>exact rate below 95 % from epsilon</th><th>below 50 % from epsilon</th><th>proven bound</th></tr>"
            + "".join(html_rows) + "</table>"
            f"<p class=note>Over the smooth closed curves of suite {esc(suites)} with a measured epsilon up to "
            f"{BREAKDOWN_TABLE_UP_TO} (sparser, a handful of samples make an easy polygon again): the measured epsilon "
            "at which the exact-reconstruction rate, fitted as a logistic function of ln epsilon, drops below 95 % and "
            "below 50 %, with its percentile-bootstrap 95 % interval over the cases; '&gt;' or '&lt;' where the fitted rate crosses beyond the epsilons measured. The proven bound is "
            "the theorem's (survey: Guarantees as Sampling Conditions). Written as breakdown-thresholds.csv.</p>")


# ---------------------------------------------------------------- simplifiers

# A simplifier's cells: (key, header, what per job). Distances are fractions of the true curve's
# bounding-box diagonal, as results.csv writes them; "share" is the output's vertices over the input's points.
SIMPLIFIER_MEANS = [
    ("output_share", "output vertices / input points", lambda r: output_share(r)),
    ("hausdorff_to_curve", "Hausdorff output → curve", lambda r: measure(r["hausdorff_to_curve"])),
    ("rms_to_curve", "RMS output → curve", lambda r: measure(r["rms_to_curve"])),
    ("hausdorff_from_curve", "Hausdorff curve → output", lambda r: measure(r["hausdorff_from_curve"])),
    ("rms_from_curve", "RMS curve → output", lambda r: measure(r["rms_from_curve"])),
    ("components", "components", lambda r: measure(r["components"])),
    ("closed_components", "closed", lambda r: measure(r["closed_components"])),
    ("open_components", "open", lambda r: measure(r["open_components"])),
    ("isolated", "isolated vertices", lambda r: measure(r["unconnected"])),
]
SIMPLIFIER_SHARES = [
    ("manifold", "manifold", lambda r: flag(r["manifold"])),
    ("true_topology", "the truth's topology", lambda r: flag(r["true_topology"])),
]


def measure(text):
    """A float, infinity included (a curve far from an empty output), or None."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return None if math.isnan(value) else value


def output_share(r):
    kept, of = measure(r["output_points"]), measure(r["n_points"])
    return kept / of if kept is not None and of else None


def mean_of(values):
    """(mean interval of the finite values, number of infinite ones)."""
    values = [v for v in values if v is not None]
    return mean_interval(values), sum(1 for v in values if math.isinf(v))


def fmt_mean_of(interval, infinite=0, scale=1.0, suffix=""):
    """'0.0123 ±0.0021, n=30': the mean, the half-width of its Student-t 95% interval and the sample size."""
    m, n, low, high = interval
    if n == 0 and not infinite:
        return "–"
    def short(value, digits):  # no exponent for a share above 100 % or a large count
        return f"{value:.0f}" if abs(value) >= 10 ** digits else f"{value:.{digits}g}"

    text = "–" if n == 0 else (short(scale * m, 3) + suffix
                               + ("" if low is None else f" ±{short(scale * (high - low) / 2, 2)}{suffix}"))
    return text + f", n={n}" + (f" (+{infinite} ∞)" if infinite else "")


def simplifier_cells(rows):
    """The section's statistics of one group of a simplifier's jobs: {key: (mean interval, infinite)} and
    {key: Wilson share}, over ok jobs (a job that failed has no output to measure; the jobs column counts it)."""
    ok = [r for r in rows if r["_ok"]]
    means = {key: mean_of(f(r) for r in ok) for key, _, f in SIMPLIFIER_MEANS}
    shares = {key: wilson(f(r) for r in ok) for key, _, f in SIMPLIFIER_SHARES}
    return means, shares


def simplifier_section(run, csv_path):
    """The section of the algorithms that simplify (Optimal Transport), by suite and level: their size, their
    distance to the true curve each way and their topology, with intervals; also written to csv_path. Empty
    without such an algorithm."""
    groups = []
    for a in run.simplifiers:
        for suite in run.suites:
            rows = [r for r in run.suite_rows(suite) if r["algorithm"] == a]
            for level in sorted(ordered(r["level"] for r in rows), key=level_key):
                group = [r for r in rows if r["level"] == level]
                groups.append((a, suite, level, group, *simplifier_cells(group)))
    if not groups:
        return ""
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(["algorithm", "suite", "level", "jobs", "ok"]
                     + [f"{key}_{x}" for key, _, _ in SIMPLIFIER_MEANS for x in ("n", "mean", "low", "high", "infinite")]
                     + [f"{key}_{x}" for key, _, _ in SIMPLIFIER_SHARES for x in ("k", "n", "pct", "low", "high")])
        for a, suite, level, group, means, shares in groups:
            line = [a, suite, level, len(group), sum(r["_ok"] for r in group)]
            for key, _, _ in SIMPLIFIER_MEANS:
                (m, n, low, high), infinite = means[key]
                line += [n] + ["" if v is None else v for v in (m, low, high)] + [infinite]
            for key, _, _ in SIMPLIFIER_SHARES:
                k, n, low, high = shares[key]
                line += [k, n, "" if n == 0 else 100 * k / n, "" if low is None else low, "" if high is None else high]
            out.writerow(line)

    def table(columns, cell):
        head = "".join(f"<th>{esc(title)}</th>" for _, title, _ in columns)
        lines = [f"<table><tr><th>algorithm</th><th>suite</th><th>level</th><th>jobs</th>{head}</tr>"]
        for a, suite, level, group, means, shares in groups:
            ok = sum(r["_ok"] for r in group)
            jobs = f"{len(group)}" + ("" if ok == len(group) else f" ({ok} ok)")
            lines.append(f"<tr><td>{esc(a)}</td><td>{esc(suite or '(unnamed)')}</td><td>{esc(level or '–')}</td>"
                         f"<td class=n>{esc(jobs)}</td>"
                         + "".join(f"<td class=n>{esc(cell(key, means, shares))}</td>" for key, _, _ in columns) + "</tr>")
        return "".join(lines) + "</table>"

    def mean_cell(key, means, shares):
        interval, infinite = means[key]
        return fmt_mean_of(interval, infinite, 100, "%") if key == "output_share" else fmt_mean_of(interval, infinite)

    names = ", ".join(run.simplifiers)
    return ("<h2 id=simplifiers>Simplifiers, scored apart</h2>"
            f"<p>{esc(names)} simplif{'ies' if len(run.simplifiers) == 1 else 'y'}: the output's vertices are a few of "
            "the input points, joined where the curve is found, and a vertex with no edge is an output point too. The "
            "survey leaves such a method out of its experiments (\"The Benchmark\", \"Algorithms\": Optimal Transport "
            "\"focuses on simplified reconstruction and hence, for a fair comparison, we have not included it\"), so "
            f"here its exactness cells read {SIMPLIFIES} and it is measured by what it is for: how far its output "
            "lies from the true curve, and the curve from it, how many points it keeps, and its topology.</p>"
            "<h3>Size and distance, each way</h3>" + table(SIMPLIFIER_MEANS[:5], mean_cell)
            + "<h3>Topology</h3>" + table(SIMPLIFIER_MEANS[5:] + SIMPLIFIER_SHARES,
                                          lambda key, means, shares: fmt_share(shares[key]) if key in shares
                                          else mean_cell(key, means, shares))
            + "<p class=note>Over the ok jobs of each suite and level (the jobs column counts every job): means ± the "
            "half-width of their Student-t 95% interval, and n, the number of jobs measured; shares with their Wilson "
            "95% interval and the number of jobs. Output → curve and curve → output are the survey's two closest-point mappings "
            "(\"Evaluation Criteria\": D and D') taken one at a time, in units of the true curve's bounding-box "
            "diagonal: output → curve says whether the output strays from the curve, curve → output whether part of "
            "the curve is left without output nearby; an isolated vertex counts in both Hausdorff distances, while "
            "each RMS weighs by length, so a vertex beside edges weighs nothing in it. ∞: a curve with no output at "
            "all, counted apart from the mean. Components, closed and open count the connected pieces with edges; "
            "the truth's topology: a manifold with the true curve's closed and open components, isolated vertices "
            "aside. Written as simplifiers.csv.</p>")


def make_charts(run, charts_dir):
    """Writes every chart; returns {section: [(file name, caption)]} with section None for the overall ones."""
    charts_dir.mkdir(parents=True, exist_ok=True)
    made = collections.defaultdict(list)
    if not run.rows:
        return made
    status_chart(run, charts_dir / "status.svg")
    made[None].append(("status.svg", "Jobs per status; the messages are under Non-ok jobs."))
    if any((number(r["runtime_ms"]) or 0) > 0 for r in run.rows if r["_ok"]):
        runtime_chart(run, charts_dir / "runtime.svg")
        made[None].append(("runtime.svg", f"Mean runtime of ok jobs; {NOT_DRAWN} = no ok job; a black line across a bar is "
                                          "an external program's start-up (its wall time on no points), part of its runtime."))
    for suite in run.suites:
        rows = run.suite_rows(suite)
        if any(number(r["rms"]) is not None for r in rows):
            name = f"rms-{safe_name(suite)}.svg"
            grouped_bars(run, rows, "rms", f"{suite}: mean RMS distance to the true curve", "mean RMS [x bounding-box diagonal]",
                         charts_dir / name)
            made[suite].append((name, f"Mean RMS over ok jobs; {NOT_DRAWN} = no ok job with ground truth."))
        if any(r["_exact"] is not None for r in rows):
            name = f"exact-{safe_name(suite)}.svg"
            grouped_bars(run, [r for r in rows if not r["_simplifies"]], "exact", f"{suite}: exactly reconstructed",
                         "exact reconstructions [%]", charts_dir / name, percent_axis=True)
            apart = [a for a in run.simplifiers if any(r["algorithm"] == a for r in rows)]
            made[suite].append((name, "Share of jobs whose edge set equals the ground truth; "
                                      f"failed jobs count as not exact; {NOT_DRAWN} = no ground truth"
                                      + (f"; not drawn, as they simplify: {', '.join(apart)}." if apart else ".")))
    # The empirical breakdown of the theorems: suite `certify`, measured epsilon and rho.
    theorems = read_theorems(charts_dir.parent / "theorems.csv")
    certify_rows = run.suite_rows("certify") if "certify" in run.suites else []
    tables = {m: breakdown(run, certify_rows, m, theorems) for m in ("epsilon", "rho")}
    for measure, table in tables.items():
        if any(table.values()):
            name = f"breakdown-{measure}.svg"
            breakdown_chart(run, table, theorems, measure, charts_dir / name)
            made["certify"].append((name, f"Share of samplings reconstructed exactly per bin of their measured {measure} "
                                          f"(up to {BREAKDOWN_UP_TO}), for every algorithm with a proven condition; "
                                          "written as breakdown.csv."))
    if any(any(t.values()) for t in tables.values()):
        write_breakdown_csv(charts_dir.parent / "breakdown.csv", tables)
    return made


# ---------------------------------------------------------------- HTML

CSS = """
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em auto; max-width: 1300px; padding: 0 1em; color: #222; }
h1 { margin-bottom: 0.2em; } h2 { border-bottom: 1px solid #ccc; margin-top: 2em; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #ddd; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f3f3f3; } td.n { text-align: right; font-variant-numeric: tabular-nums; }
td.bad, .why { color: #c00; font-weight: bold; }
table.matrix td { text-align: center; } table.matrix td.lead { font-weight: bold; }
td.na { color: #777; font-style: italic; text-align: center; }
.swatch { display: inline-block; width: 0.8em; height: 0.8em; margin-right: 0.4em; vertical-align: baseline; }
.charts { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; }
.charts figure { margin: 0; } .charts img { max-width: 100%; }
figcaption, .note { font-size: 12px; color: #555; }
.msg { white-space: pre-wrap; font-family: monospace; font-size: 12px; max-width: 50em; }
.gallery { display: grid; grid-template-columns: repeat(auto-fill, minmax(230px, 1fr)); gap: 10px; }
.shot { margin: 0; border: 1px solid #ccc; padding: 4px; background: #fff; }
.shot img { width: 100%; height: 200px; object-fit: contain; }
.shot.fail { border: 3px solid #d62728; }
.shot figcaption { overflow-wrap: anywhere; }
#image-check { margin-top: 2em; font-size: 12px; color: #777; }
"""

# Counts images that did not load, for scripts/check_report.sh (headless Chromium --dump-dom).
IMAGE_CHECK_JS = """
window.addEventListener('load', function () {
  var images = Array.prototype.slice.call(document.images);
  var broken = images.filter(function (i) { return !i.complete || i.naturalWidth === 0; });
  var charts = images.filter(function (i) { return i.classList.contains('chart'); });
  var el = document.getElementById('image-check');
  el.dataset.total = images.length;
  el.dataset.broken = broken.length;
  el.dataset.charts = charts.length;
  el.dataset.brokenSrc = broken.map(function (i) { return i.getAttribute('src'); }).join(' ');
  el.dataset.state = 'done';
  el.textContent = 'Image check: ' + images.length + ' images, ' + broken.length + ' broken.';
});
"""


def chart_figures(charts):
    if not charts:
        return ""
    items = "".join(f'<figure><img class="chart" src="charts/{esc(urllib.parse.quote(name))}" alt="{esc(name)}">'
                    f"<figcaption>{esc(caption)}</figcaption></figure>" for name, caption in charts)
    return f'<div class="charts">{items}</div>'


def failures_text(counter):
    total = sum(counter.values())
    return f"{total} ({', '.join(f'{s} {n}' for s, n in sorted(counter.items()))})" if total else "0"


def summary_table(run, suite, rows):
    levels = sorted(ordered(r["level"] for r in rows), key=level_key)
    out = ["<table><tr><th>algorithm</th><th>level</th><th>jobs</th><th>exact</th><th>mean RMS</th>"
           "<th>mean Hausdorff</th><th>manifold</th><th>true topology</th><th>failures</th></tr>"]
    for a in run.algorithms:
        groups = [(lv, [r for r in rows if r["algorithm"] == a and r["level"] == lv]) for lv in levels]
        groups = [(lv, g) for lv, g in groups if g]
        for i, (lv, group) in enumerate(groups):
            s = group_stats(group)
            head = ""
            if i == 0:
                r, g, b = (round(255 * c) for c in run.colour[a][:3])
                head = (f'<td rowspan="{len(groups)}"><span class="swatch" style="background:rgb({r},{g},{b})">'
                        f"</span>{esc(a)}</td>")
            bad = ' bad' if s["failures"] else ''
            apart = run.simplifies(a)
            out.append(f"<tr>{head}<td>{esc(lv or '–')}</td><td class=n>{s['jobs']}</td>"
                       f"<td class=n>{SIMPLIFIES if apart else esc(fmt_share(s['exact_interval']))}</td>"
                       f"<td class=n>{esc(fmt_mean(s['rms_interval']))}</td>"
                       f"<td class=n>{esc(fmt_mean(s['hausdorff_interval']))}</td>"
                       f"<td class=n>{fmt(s['manifold'], '.0f', '%')}</td>"
                       f"<td class=n>{SIMPLIFIES if apart else esc(fmt_share(s['true_topology']))}</td>"
                       f"<td class='n{bad}'>{esc(failures_text(s['failures']))}</td></tr>")
    out.append("</table><p class=note>exact: share of jobs reconstructed exactly, where a failed job on an input "
               "with ground truth counts as not exact, with its Wilson 95% interval and the number of jobs; RMS, "
               "Hausdorff and manifold: over ok jobs, the means ± the half-width of their Student-t 95% interval "
               "(the bars' whiskers are the same intervals); RMS and Hausdorff "
               "are distances to the true curve in units of its bounding-box diagonal; true topology: share of jobs "
               "with ground truth whose output is a manifold with the truth's closed and open components (points "
               "may be dropped or moved), with its Wilson 95% interval and the number of jobs.</p>")
    return "".join(out)


def failure_reason(r):
    """Why a gallery picture is highlighted, or '' when it is not a failure."""
    if not r["_ok"]:
        message = r["message"] if len(r["message"]) <= 160 else r["message"][:157] + "…"
        return f"{r['status'] or 'no status'}: {message}" if message else (r["status"] or "no status")
    if r["_exact"] is False:
        components = r["components"]
        topology = [f"{components} component{'' if components == '1' else 's'}" if components else "",
                    "non-manifold" if flag(r["manifold"]) is False else ""]
        details = ", ".join(t for t in topology if t)
        return "not exact" + (f" ({details})" if details else "")
    return ""


def gallery(rows):
    pictured = [r for r in rows if r["picture"]]
    pictured.sort(key=lambda r: (r["_ok"], r["_exact"] is not False))  # stable: job order within
    shown = pictured[:GALLERY_CAP]
    if not shown:
        return "<p>No pictures.</p>"
    out = [f"<p>Showing {len(shown)} of {len(pictured)} pictures, failures first.</p><div class=gallery>"]
    for r in shown:
        why = failure_reason(r)
        metrics = [f"{r['n_points']} points" if r["n_points"] else "",
                   f"RMS {fmt(number(r['rms']))}" if r["rms"] else "",
                   f"Hausdorff {fmt(number(r['hausdorff']))}" if r["hausdorff"] else "",
                   f"{fmt(number(r['runtime_ms']))} ms" if r["runtime_ms"] else "",
                   "exact" if r["_exact"] else "",
                   f"kept {r['output_points']} of {r['n_points']} points" if r["_simplifies"] and r["output_points"] else ""]
        title = " · ".join(t for t in [f"#{r['job']}", r["algorithm"], r["level"], r["params"]] if t)
        out.append(f'<figure class="shot{" fail" if why else ""}" id="job-{esc(r["job"])}">'
                   f'<img src="{esc(urllib.parse.quote(r["picture"]))}" alt="job {esc(r["job"])}"><figcaption>'
                   f"<b>{esc(title)}</b><br>{esc(r['input'])}<br>{esc(' · '.join(m for m in metrics if m))}"
                   + (f'<br><span class="why">{esc(why)}</span>' if why else "") + "</figcaption></figure>")
    out.append("</div>")
    return "".join(out)


def nonok_table(rows):
    nonok = [r for r in rows if not r["_ok"]]
    if not nonok:
        return "<p>Every job finished with status ok.</p>"
    out = ["<table><tr><th>job</th><th>suite</th><th>input</th><th>level</th><th>algorithm</th><th>params</th>"
           "<th>points</th><th>status</th><th>message</th></tr>"]
    for r in nonok:
        out.append('<tr class="nonok">' + "".join(
            f"<td>{esc(r[c])}</td>" for c in ("job", "suite", "input", "level", "algorithm", "params", "n_points"))
            + f"<td class=bad>{esc(r['status'] or '(empty)')}</td><td class=msg>{esc(r['message'])}</td></tr>")
    out.append("</table>")
    return "".join(out)


SUMMARY_COLUMNS = ("suite level algorithm jobs exact_k exact_n exact_pct exact_low exact_high "
                   "true_topology_k true_topology_n true_topology_pct true_topology_low true_topology_high "
                   "rms_n rms_mean rms_low rms_high hausdorff_n hausdorff_mean hausdorff_low hausdorff_high "
                   "runtime_ms_mean startup_ms").split()


def write_summary(run, path):
    """One row per suite, level and algorithm: shares with Wilson 95% intervals (in %), means with Student-t 95%
    intervals; empty where there is nothing to count. `path` (summary.csv) and, beside it, summary.json: the same
    cells typed, null for empty (results.json has one row per job; a cell is not a job)."""
    def cells(share):
        k, n, low, high = share
        return [k, n, "" if n == 0 else 100 * k / n, "" if low is None else low, "" if high is None else high]

    def means(m):
        mean_, n, low, high = m
        return [n, "" if mean_ is None else mean_, "" if low is None else low, "" if high is None else high]

    table = []
    for suite in run.suites:
        rows = run.suite_rows(suite)
        for level in sorted(ordered(r["level"] for r in rows), key=level_key):
            for a in run.algorithms:
                group = [r for r in rows if r["algorithm"] == a and r["level"] == level]
                if not group:
                    continue
                st = group_stats(group)
                # Empty, not 0 of 0: exactness does not apply to a simplifier (its rows are in simplifiers.csv).
                shares = [""] * 10 if run.simplifies(a) else cells(st["exact_interval"]) + cells(st["true_topology"])
                table.append([suite, level, a, st["jobs"]] + shares
                             + means(st["rms_interval"]) + means(st["hausdorff_interval"])
                             + ["" if st["runtime"] is None else st["runtime"]]
                             + ["" if st["startup"] is None else st["startup"]])
    with open(path, "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(SUMMARY_COLUMNS)
        out.writerows(table)
    with open(path.with_suffix(".json"), "w", encoding="utf-8") as f:
        f.write("[\n" + ",\n".join(json.dumps({c: (None if v == "" else v) for c, v in zip(SUMMARY_COLUMNS, row)})
                                     for row in table) + "\n]\n")


# Timing experiments: one curve per level, so their exact share is no rate; the runtime chart shows them.
TIMING_SUITES = ("runtime", "runtime-large")


def matrix_table(run, key, what):
    """Algorithm x suite: the share of `key` over all levels, with its Wilson interval, as a heat map; the best of
    each suite and those McNemar's test cannot tell from it (p >= 0.05, paired on the same instances) are marked."""
    suites = [s for s in run.suites
              if s not in TIMING_SUITES and any(r[key] is not None for r in run.suite_rows(s))]
    if not suites:
        return ""
    columns = {s: leaders(run.suite_rows(s), run.algorithms, key) for s in suites}
    out = [f"<table class=matrix><tr><th>{esc(what)}</th>" + "".join(f"<th>{esc(s)}</th>" for s in suites) + "</tr>"]
    for a in run.algorithms:
        cells = []
        for s in suites:
            result, best = columns[s]
            if run.simplifies(a) and any(r["algorithm"] == a for r in run.suite_rows(s)):
                cells.append(f'<td class=na title="scored apart: see Simplifiers">{SIMPLIFIES}</td>')
                continue
            if a not in result:
                cells.append("<td>–</td>")
                continue
            (k, n, low, high), p = result[a]
            share = 100 * k / n
            lead = p >= LEADER_ALPHA
            shade = f"hsl(120, 55%, {97 - 0.45 * share:.0f}%)"
            mark = " ★" if lead else ""
            title = f"{k} of {n}; McNemar p = {p:.3g} against {best}"
            cells.append(f'<td class="n{" lead" if lead else ""}" style="background:{shade}" title="{esc(title)}">'
                         f"{share:.0f}%{mark}<br><small>[{low:.0f}–{high:.0f}] of {n}</small></td>")
        out.append(f"<tr><td>{esc(a)}</td>" + "".join(cells) + "</tr>")
    out.append("</table>")
    return "".join(out)


MATRIX_NOTE = ("<p class=note>Each cell: the share over all the suite's levels, its Wilson 95% interval and the number "
               "of jobs (a failed job counts as a miss). ★: the best of the column, and every algorithm McNemar's exact "
               "test on the same instances cannot tell from it (p ≥ 0.05); hover a cell for its p-value. "
               f"{SIMPLIFIES}: an algorithm that simplifies (keeps a few of the points) is not ranked by exactness, as "
               'the survey leaves it out of its experiments; <a href="#simplifiers">Simplifiers</a> scores it.</p>')


# The survey's own reported results (its figures hold no readable data here, so these are the
# figures its text and tables state), each beside the experiment of ours that corresponds.
# `best`: the algorithms it names best; `rates`: exact % it states per algorithm; `metric`:
# what it ranks by ("_exact": exact %, "rms": mean RMS, "runtime": mean ms).
SURVEY_ROWS = [
    {"experiment": "Manifold curves", "where": "Manifold Curves, Fig. 16 (fig:eval-exact)", "suite": "manifold",
     "metric": "_exact", "claim": "2183 noise-free manifold sets: Connect2D best, 52.13% exact; most 22.6–45%; Lenz 1.7%",
     "best": ["connect2d"], "rates": {"connect2d": 52.13, "lenz": 1.7}},
    {"experiment": "Sharp corners", "where": "Sharp Corners, Fig. 18 (fig:eval-sharp-corners)", "suite": "sharp-corners",
     "metric": "_exact", "claim": "47 curves: GatHanG 80.85%, Connect2D 65.95%, GatHan 44.68%, all others 0–23.4%",
     "best": ["gathang"], "rates": {"gathang": 80.85, "connect2d": 65.95, "gathan": 44.68}},
    {"experiment": "Sharp corners (the survey's convex family)", "where": "Sharp Corners, Fig. 18",
     "suite": "corner-family", "metric": "_exact", "claim": "as above, on its own and classic curves",
     "best": ["gathang"], "rates": {"gathang": 80.85, "connect2d": 65.95, "gathan": 44.68}},
    {"experiment": "Open curves", "where": "Open Curves, Fig. 19 (fig:eval-open-curves)", "suite": "open-curves",
     "metric": "_exact", "claim": "23 classic open sets: VICUR best at 52.2%; HNN-Crust, Crust, Peel, DISCUR reasonable",
     "best": ["vicur"], "rates": {"vicur": 52.2}},
    {"experiment": "Multiple curves", "where": "Multiple Curves, Fig. 20 (fig:eval-multi-curves)",
     "suite": "multiple-curves", "metric": "_exact", "claim": "54 sets: Peel and HNN-Crust comparatively good (no rates)",
     "best": ["peel", "hnn-crust"], "rates": {}},
    {"experiment": "Self-intersections", "where": "Non-manifold Point Sets, Fig. 17 (fig:eval-non-manifold)",
     "suite": "intersecting", "metric": "_exact", "claim": "26 sets, 5 non-manifold algorithms: the best about 11% exact "
     "(3 of 26, Wilson [4–29]%)", "best": [], "rates": {}, "best_count": (3, 26)},
    {"experiment": "Uniform noise", "where": "Robustness to Noise, Fig. 10 (fig:eval-noisy)", "suite": "noisy",
     "metric": "rms", "claim": "RMS: Crawl, Peel and the Crust family best", "best": ["crawl", "peel", "crust", "nn-crust",
                                                                                     "hnn-crust", "conservative-crust"],
     "rates": {}},
    {"experiment": "LFS noise", "where": "Robustness to Noise, Fig. 11 (fig:eval-lfsnoise)", "suite": "lfsnoise",
     "metric": "rms", "claim": "RMS: Connect2D, FitConnect and StretchDenoise superior",
     "best": ["connect2d", "fit-connect", "stretch-denoise"], "rates": {}},
    {"experiment": "Outliers", "where": "Outliers, Fig. 13 (fig:eval-outliers)", "suite": "outliers", "metric": "rms",
     "claim": "RMS: Crust and HNN-Crust very good; StretchDenoise and FitConnect sensitive",
     "best": ["crust", "hnn-crust"], "rates": {}},
    {"experiment": "Runtime", "where": "Computational Time, Table 3 (table:run-time)", "suite": "runtime",
     "level": "n=1000", "metric": "runtime", "claim": "about 284 points: NN-Crust fastest (0.4 ms), VICUR slowest (1.70 s); FitConnect "
     "0.51 s, StretchDenoise 0.62 s, DISCUR 1.53 s", "best": ["nn-crust"], "rates": {}},
]


# The 14 algorithms the survey ranks ("Evaluation & Results", Table 2 without Optimal
# Transport, which it leaves out of every experiment): ours are ranked among these alone,
# since an algorithm it never ran cannot disagree with it.
SURVEY_ALGORITHMS = ["crust", "nn-crust", "conservative-crust", "gathan", "gathang", "lenz", "connect2d", "crawl",
                     "hnn-crust", "fit-connect", "stretch-denoise", "peel", "discur", "vicur"]


def survey_ours(run, row):
    """Our side of a survey row: (text, agrees or None) from the run's rows of that suite, among the survey's
    algorithms."""
    algorithms = [a for a in run.algorithms if a in SURVEY_ALGORITHMS]
    rows = [r for r in run.suite_rows(row["suite"])
            if r["level"] == row.get("level", r["level"]) and r["algorithm"] in algorithms]
    if not rows:
        return None
    metric = row["metric"]
    if metric == "_exact":
        result, best = leaders(rows, algorithms, "_exact")
        if not result:
            return None
        lead = [a for a in algorithms if a in result and result[a][1] >= LEADER_ALPHA]
        def share(a):
            k, n, low, high = result[a][0]
            return f"{esc(a)} {100 * k / n:.0f}% [{low:.0f}–{high:.0f}] of {n}"
        if len(lead) > 4:  # many tied: name them, give the best's share
            text = f"{len(lead)} leaders ({esc(', '.join(lead))}); best " + share(best)
        else:
            text = "leaders: " + ", ".join(share(a) for a in lead)
        named = [a for a in row["rates"] if a in result and a not in lead]
        if named:
            text += "; " + ", ".join(share(a) for a in named)
        if row.get("best_count") is not None:  # a rate: do the two Wilson intervals overlap?
            k, n = row["best_count"]
            _, _, survey_low, survey_high = wilson([True] * k + [False] * (n - k))
            _, _, low, high = result[best][0]
            return text, low <= survey_high and survey_low <= high
        if len(lead) > len(result) / 2:
            return text, None  # most algorithms tie: the experiment ranks nothing here
        return text, any(a in lead for a in row["best"])
    key = "rms" if metric == "rms" else "runtime_ms"
    means = {}
    for a in algorithms:
        values = [number(r[key]) for r in rows if r["algorithm"] == a and r["_ok"] and number(r[key]) is not None]
        if values:
            means[a] = (mean(values), len(values))
    if not means:
        return None
    top = sorted(means, key=lambda a: means[a][0])[:3]
    unit = (lambda v: f"{v:.4f}") if metric == "rms" else (lambda v: f"{v:.3g} ms")
    text = "lowest mean " + ("RMS" if metric == "rms" else "runtime") + ": " + ", ".join(
        f"{esc(a)} {unit(means[a][0])} (n={means[a][1]})" for a in top)
    return text, any(a in top for a in row["best"])


def survey_table(run):
    lines = []
    for row in SURVEY_ROWS:
        ours = survey_ours(run, row)
        if ours is None:
            continue
        text, agrees = ours
        verdict = "cannot rank: most tie" if agrees is None else "agrees" if agrees else "<b>differs</b>"
        lines.append(f"<tr><td>{esc(row['experiment'])}</td><td>{esc(row['where'])}</td><td>{esc(row['claim'])}</td>"
                     f"<td>{esc(row['suite'])}: {text}</td><td>{verdict}</td></tr>")
    if not lines:
        return ""
    return ("<h2>Beside the survey</h2><table><tr><th>experiment</th><th>survey section, figure</th>"
            "<th>the survey reports</th><th>ours</th><th></th></tr>" + "".join(lines) + "</table>"
            "<p class=note>Ours are ranked among the 14 algorithms the survey ranks. The survey's inputs are mostly "
            "classic and image-derived point sets; ours are generated curves with exact ground truth, so rates "
            "differ in level. \"agrees\": an algorithm the survey names best "
            "is among our leaders (exact %: McNemar, as in the matrix, and \"cannot rank\" where more than half "
            "lead; RMS and runtime: our three lowest means), or "
            "the Wilson intervals of the survey's best rate and ours overlap. The suite <code>drawings</code> holds the "
            "real drawings (SVG animals, glyphs): they have corners and junctions, so they lie outside every "
            "sampling theorem.</p>")


SUITE_NOTES = {
    "drawings": "<p class=note>Real drawings (SVG animals, multi-curve and crossing SVGs, glyphs): they have sharp "
                "corners, T-junctions and touching strokes, so their measured epsilon is infinite and they lie outside "
                "every sampling theorem. A share here says how an algorithm copes with such input, not whether it "
                "keeps its guarantee.</p>",
}


def report_html(run, charts, out_dir, csv_path):
    title = f"curvebench report: {out_dir.resolve().name}"
    finished = datetime.datetime.fromtimestamp(csv_path.stat().st_mtime).strftime("%Y-%m-%d %H:%M")
    now = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    status_counts = collections.Counter(r["status"] for r in run.rows)
    parts = [f"<!DOCTYPE html><html lang=en><head><meta charset=utf-8><title>{esc(title)}</title>"
             f"<style>{CSS}</style></head><body><h1>{esc(title)}</h1>",
             f"<p>results.csv written {esc(finished)}, report made {esc(now)}, directory "
             f"<code>{esc(out_dir.resolve())}</code>.</p>"]
    if not run.rows:
        parts.append("<p>No jobs in results.csv.</p>")
    else:
        suites = ", ".join(f'<a href="#suite-{esc(safe_name(s))}">{esc(s or "(unnamed)")}</a> '
                           f"({len(run.suite_rows(s))})" for s in run.suites)
        parts.append(
            f"<p>{counted(len(run.rows), 'job')} in {counted(len(run.suites), 'suite')}: {suites}.<br>"
            f"{counted(len(run.algorithms), 'algorithm')}: {esc(', '.join(run.algorithms))}.<br>Status: "
            + esc(", ".join(f"{s or '(empty)'} {n}" for s, n in status_counts.most_common()))
            + '. <a href="#nonok">Non-ok jobs</a>. <a href="explorer.html">Explore the results</a>: filter, '
            'sort, compare two algorithms on the same input, replay a job.'
            + (f' Scored apart, as they simplify: <a href="#simplifiers">{esc(", ".join(run.simplifiers))}</a>.'
               if run.simplifiers else "") + "</p>")
        exact_matrix = matrix_table(run, "_exact", "exact")
        topology_matrix = matrix_table(run, "_true_topology", "true topology")
        if exact_matrix:
            parts.append("<h2>Algorithms × experiments</h2><h3>Exact reconstruction</h3>" + exact_matrix
                         + "<h3>True topology (one manifold per true curve, whatever points are kept)</h3>"
                         + topology_matrix + MATRIX_NOTE)
        parts.append(survey_table(run))
        parts.append(breakdown_table(run, read_theorems(out_dir / "theorems.csv"), out_dir / "breakdown-thresholds.csv"))
        parts.append(simplifier_section(run, out_dir / "simplifiers.csv"))
        parts.append("<h2>Overview</h2>" + chart_figures(charts[None]))
        for suite in run.suites:
            rows = run.suite_rows(suite)
            parts.append(f'<h2 id="suite-{esc(safe_name(suite))}">Suite {esc(suite or "(unnamed)")}</h2>'
                         + SUITE_NOTES.get(suite, "") + summary_table(run, suite, rows) + chart_figures(charts[suite])
                         + "<h3>Reconstructions</h3>" + gallery(rows))
        parts.append('<h2 id="nonok">Non-ok jobs</h2>' + nonok_table(run.rows))
    parts.append('<div id="image-check" data-state="pending">Image check did not run.</div>'
                 f"<script>{IMAGE_CHECK_JS}</script></body></html>\n")
    return "".join(parts)


def main(argv):
    if len(argv) != 2:
        sys.exit("usage: make_report.py DIR   (DIR holds results.csv from `curvebench run`)")
    out_dir = pathlib.Path(argv[1])
    csv_path = out_dir / "results.csv"
    if not csv_path.is_file():
        sys.exit(f"make_report: {csv_path} not found")
    run = Run(read_rows(csv_path), read_simplifiers(out_dir))
    charts = make_charts(run, out_dir / "charts")
    write_summary(run, out_dir / "summary.csv")
    write_explorer(run, out_dir)
    (out_dir / "report.html").write_text(report_html(run, charts, out_dir, csv_path), encoding="utf-8")
    print(f"make_report: {out_dir / 'report.html'} ({len(run.rows)} jobs, "
          f"{sum(len(c) for c in charts.values())} charts)")


if __name__ == "__main__":
    main(sys.argv)
