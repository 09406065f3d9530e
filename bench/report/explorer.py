"""The results explorer: DIR/explorer.html, a copy of bench/report/explorer.html, over
DIR/explorer-data.js, every job's row as columns.

The data is a script, not JSON, because Chromium refuses fetch() of a file:// URL; a
<script src> loads from file:// everywhere. It is columnar and compact, so that a full run's
hundreds of thousands of rows load in one go: text columns are dictionary-coded (each
distinct value once, then a small integer per row), numbers keep 6 significant digits, and
a picture is 1 when it has its default name pictures/JOB.svg, and a number column mostly empty lists only
the rows that have a value (encode_sparse). `simplifies` names the algorithms whose
exactness does not apply (the report's Simplifiers section): the page shows "n/a (simplifies)" for them.
"""
import json
import math
import pathlib
import shutil

PAGE = pathlib.Path(__file__).with_name("explorer.html")
TEXT_COLUMNS = ("suite", "input", "level", "algorithm", "params", "status", "message")
NUMBER_COLUMNS = ("job", "n_points", "epsilon", "rho", "hausdorff", "rms", "normal_deviation", "components",
                  "runtime_ms", "hausdorff_to_curve", "rms_to_curve", "hausdorff_from_curve", "rms_from_curve")
# Shown for a simplifier's rows only, so kept for those alone.
SIMPLIFIER_COLUMNS = ("closed_components", "open_components", "unconnected", "output_points")


def encode_text(values):
    distinct = {}
    codes = [distinct.setdefault(v, len(distinct)) for v in values]
    return {"values": list(distinct), "codes": codes}


def encode_number(text):
    """None for empty, "inf" for an infinite measure (JSON has no infinity), else 6 digits."""
    if not text:
        return None
    try:
        value = float(text)
    except ValueError:
        return None
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if math.isnan(value):
        return None
    return int(value) if value.is_integer() and abs(value) < 2**53 else float(f"{value:.6g}")


def encode_sparse(values):
    """A column mostly empty (the distances each way, measured for a simplifier only; epsilon and rho, for
    noise-free curve samples only) as the rows that have a value and their values: {"at": [...], "values": [...]}."""
    at = [i for i, v in enumerate(values) if v is not None]
    if 2 * len(at) >= len(values):
        return values
    return {"at": at, "values": [values[i] for i in at]}


def encode_flag(value):
    return None if value is None else int(bool(value))


def encode_picture(row):
    picture = row["picture"]
    if not picture:
        return 0
    return 1 if row["job"].isdigit() and picture == f"pictures/{int(row['job']):06d}.svg" else picture


def explorer_data(run):
    """The rows of `run` (make_report.Run) as columns. `exact` is the report's: a job that failed on an
    input with ground truth counts as not exact; null means the input has no ground truth, or the algorithm
    simplifies."""
    rows = run.rows
    columns = {c: encode_text([r[c] for r in rows]) for c in TEXT_COLUMNS}
    columns.update({c: encode_sparse([encode_number(r[c]) for r in rows]) for c in NUMBER_COLUMNS})
    columns.update({c: encode_sparse([encode_number(r[c]) if r["_simplifies"] else None for r in rows])
                    for c in SIMPLIFIER_COLUMNS})
    columns["exact"] = [encode_flag(r["_exact"]) for r in rows]
    columns["true_topology"] = [encode_flag(r["_true_topology"]) for r in rows]
    columns["picture"] = [encode_picture(r) for r in rows]
    return {"rows": len(rows), "columns": columns, "simplifies": list(run.simplifiers)}


def write_explorer(run, out_dir):
    """Writes explorer.html and explorer-data.js into out_dir; returns the page's path."""
    data = json.dumps(explorer_data(run), separators=(",", ":"), allow_nan=False)
    (out_dir / "explorer-data.js").write_text(
        "// The rows of results.csv for explorer.html (bench/report/explorer.py).\n"
        f"window.CURVEBENCH_RESULTS = {data};\n", encoding="utf-8")
    page = out_dir / "explorer.html"
    shutil.copyfile(PAGE, page)
    return page
