#!/usr/bin/python3
"""The report's treatment of an algorithm that simplifies (Optimal Transport): a section of its own,
"n/a (simplifies)" wherever algorithms are ranked by exactness, and no 0 % exact cell for it.

Two runs: a real one (`curvebench run smoke -a optimal-transport,nn-crust`), whose report must have the
section and no exactness share for Optimal Transport; and a synthetic results.csv whose simplifier cells
are computed here by hand (means with Student-t intervals, Wilson shares), with a failed job on an input
with ground truth, which must not count as a miss. Without algorithms.csv the same rows rank it as any
algorithm, which shows the checks can fail.

Usage: simplifiers_test.py PATH/TO/curvebench WORKDIR
"""
import csv
import html.parser
import json
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
MAKE_REPORT = [sys.executable, str(ROOT / "bench" / "report" / "make_report.py")]
NA = "n/a (simplifies)"
OT = "optimal-transport"
FAILURES = []


def check(what, condition, detail=""):
    print(("ok: " if condition else "FAILED: ") + what + (f" ({detail})" if detail and not condition else ""))
    if not condition:
        FAILURES.append(what)


class Tables(html.parser.HTMLParser):
    """Every <table> of a page as {class, header, rows}: the first row of <th> cells is the header, every other row
    a list of cell texts, a rowspan cell repeated in the rows it spans; whitespace collapsed."""

    def __init__(self):
        super().__init__()
        self.tables, self.cell, self.row, self.spans = [], None, None, {}

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "table":
            self.tables.append({"class": attrs.get("class") or "", "header": [], "rows": []})
            self.spans = {}  # column: [text, rows left]
        elif tag == "tr" and self.tables:
            self.row, self.heads = [], 0
        elif tag == "br" and self.cell is not None:
            self.cell["text"] += " "
        elif tag in ("td", "th") and self.row is not None:
            self.cell = {"th": tag == "th", "text": "", "rowspan": int(attrs.get("rowspan") or 1)}

    def handle_data(self, data):
        if self.cell is not None:
            self.cell["text"] += data

    def carry(self):
        while len(self.row) in self.spans:
            column = len(self.row)
            text, left = self.spans[column]
            self.row.append(text)
            if left > 1:
                self.spans[column][1] = left - 1
            else:
                del self.spans[column]

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.cell is not None:
            self.carry()
            text = " ".join(self.cell["text"].split())
            if self.cell["rowspan"] > 1:
                self.spans[len(self.row)] = [text, self.cell["rowspan"] - 1]
            self.heads += self.cell["th"]
            self.row.append(text)
            self.cell = None
        elif tag == "tr" and self.row is not None:
            self.carry()
            table = self.tables[-1]
            if self.heads == len(self.row) and not table["header"]:
                table["header"] = self.row
            else:
                table["rows"].append(self.row)
            self.row = None


def tables_of(path):
    parser = Tables()
    parser.feed(pathlib.Path(path).read_text(encoding="utf-8"))
    return parser.tables


def exactness_cells(tables, algorithm):
    """The cells of `algorithm` that rank by exactness: every cell of its rows in the matrices, and its cells under
    an 'exact' or 'true topology' header elsewhere."""
    cells = []
    for table in tables:
        for row in table["rows"]:
            if algorithm not in row[:1] + row[:2][-1:]:
                continue
            if "matrix" in table["class"]:
                cells += row[1:]
            else:
                cells += [text for head, text in zip(table["header"], row) if head in ("exact", "true topology")]
    return cells


def simplifier_rows(tables, title):
    """{header: cell} per row of the simplifier table whose header holds `title`."""
    for table in tables:
        if title in table["header"]:
            return [dict(zip(table["header"], row)) for row in table["rows"]]
    return []


def real_run(curvebench, work):
    out = work / "smoke"
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run([curvebench, "run", "smoke", "-a", f"{OT},nn-crust", "-o", str(out), "-q"], check=True)
    page = (out / "report.html").read_text(encoding="utf-8")
    tables = tables_of(out / "report.html")
    check("the report has the simplifiers section", 'id=simplifiers>Simplifiers, scored apart</h2>' in page)
    cells = exactness_cells(tables, OT)
    check("Optimal Transport has exactness cells", len(cells) >= 4, str(cells))
    check(f"each of them reads {NA}", cells and all(c == NA for c in cells), str(cells))
    check("no exactness share (0% or other) for Optimal Transport", not any(re.search(r"\d%", c) for c in cells))
    check("NN-Crust is ranked as before", "100% ★ [34–100] of 2" in exactness_cells(tables, "nn-crust"),
          str(exactness_cells(tables, "nn-crust")))
    rows = simplifier_rows(tables, "Hausdorff curve → output")
    check("the section has a row per level of the smoke suite", [r["level"] for r in rows] == ["epsilon=0.1", "epsilon=0.6"],
          str(rows))
    with open(out / "results.csv", newline="") as f:
        results = [r for r in csv.DictReader(f) if r["algorithm"] == OT]
    for row, result in zip(rows, results):
        kept = 100 * int(result["output_points"]) / int(result["n_points"])
        check(f"{row['level']}: its size is the row's output over its input", row["output vertices / input points"]
              == f"{kept:.3g}%, n=1", row["output vertices / input points"])
        for key, title in (("hausdorff_to_curve", "Hausdorff output → curve"),
                           ("hausdorff_from_curve", "Hausdorff curve → output")):
            check(f"{row['level']}: {title} is the row's", row[title] == f"{float(result[key]):.3g}, n=1", row[title])
    with open(out / "summary.csv", newline="") as f:
        summary = [r for r in csv.DictReader(f) if r["algorithm"] == OT]
    check("summary.csv leaves Optimal Transport's exactness empty",
          summary and all(r["exact_n"] == r["exact_pct"] == r["true_topology_pct"] == "" for r in summary))
    data = json.loads((out / "explorer-data.js").read_text().split("=", 1)[1].strip().rstrip(";"))
    check("the explorer's data names the simplifier", data["simplifies"] == [OT], str(data.get("simplifies")))
    check("the explorer's data has the distances each way",
          all(c in data["columns"] for c in ("hausdorff_to_curve", "hausdorff_from_curve", "output_points")))


HEADER = ("job,suite,input,level,algorithm,params,n_points,status,exact,hausdorff,rms,hausdorff_to_curve,rms_to_curve,"
          "hausdorff_from_curve,rms_from_curve,manifold,components,open_components,closed_components,unconnected,"
          "output_points,true_topology,runtime_ms,picture,message").split(",")


def synthetic_run(work, with_table):
    """Three instances at one level, each run by Optimal Transport and Crust; Optimal Transport fails on the
    third. Its two ok jobs keep 20 and 40 of 100 points, and are 1 and 3 from the curve (Hausdorff output →
    curve): means 30 % and 2, each ± t(1) s / sqrt(2) with t(1) = 12.706 and s = 14.14 % and 1.414, so ± 127
    (percentage points, beyond 0 and 100: two jobs say little) and ± 12.7."""
    out = work / ("synthetic" if with_table else "synthetic-without-table")
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    rows, job = [], 0
    ot = [dict(status="ok", output_points="20", hausdorff_to_curve="1", hausdorff_from_curve="0.5", components="1",
               closed_components="1", open_components="0", unconnected="2", manifold="1", true_topology="1"),
          dict(status="ok", output_points="40", hausdorff_to_curve="3", hausdorff_from_curve="inf", components="2",
               closed_components="1", open_components="1", unconnected="0", manifold="1", true_topology="0"),
          dict(status="crashed", message="signal 11")]
    for i in range(3):
        for algorithm in (OT, "crust"):
            row = {c: "" for c in HEADER}
            row.update(job=str(job), suite="sampling", input=f"fourier:seed={i}|epsilon=0.3", level="epsilon=0.3",
                       algorithm=algorithm, n_points="100", runtime_ms="1")
            if algorithm == OT:
                row.update(ot[i])
                if row["status"] == "ok":
                    row.update(exact="0", hausdorff=row["hausdorff_to_curve"], rms="0.1", rms_to_curve="0.1",
                               rms_from_curve="0.1")
            else:
                row.update(status="ok", exact="1" if i < 2 else "0", hausdorff="0.01", rms="0.005", manifold="1",
                           components="1", closed_components="1", open_components="0", unconnected="0",
                           output_points="100", true_topology="1" if i < 2 else "0")
            rows.append(row)
            job += 1
    with open(out / "results.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, HEADER, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    if with_table:
        (out / "algorithms.csv").write_text(f"algorithm,simplifies\n{OT},1\ncrust,0\n")
    subprocess.run(MAKE_REPORT + [str(out)], check=True, stdout=subprocess.DEVNULL)
    return out, tables_of(out / "report.html")


def synthetic(work):
    out, tables = synthetic_run(work, True)
    cells = exactness_cells(tables, OT)
    check("synthetic: Optimal Transport's exactness cells read n/a, its crash no miss",
          cells and all(c == NA for c in cells), str(cells))
    check("synthetic: Crust keeps its share (2 of 3)", "67% ★ [21–94] of 3" in exactness_cells(tables, "crust"),
          str(exactness_cells(tables, "crust")))
    size = simplifier_rows(tables, "output vertices / input points")
    check("synthetic: one row, 3 jobs of which 2 ok", len(size) == 1 and size[0]["jobs"] == "3 (2 ok)", str(size))
    row = size[0] if size else {}
    check("synthetic: the size's mean and interval", row.get("output vertices / input points") == "30% ±127%, n=2",
          row.get("output vertices / input points"))
    check("synthetic: Hausdorff output → curve's", row.get("Hausdorff output → curve") == "2 ±13, n=2",
          row.get("Hausdorff output → curve"))
    check("synthetic: an infinite distance is counted apart", row.get("Hausdorff curve → output") == "0.5, n=1 (+1 ∞)",
          row.get("Hausdorff curve → output"))
    topology = simplifier_rows(tables, "isolated vertices")
    row = topology[0] if topology else {}
    check("synthetic: isolated vertices' mean", row.get("isolated vertices") == "1 ±13, n=2", row.get("isolated vertices"))
    # Wilson 95 % of 1 of 2: [9.5, 90.5] %.
    check("synthetic: the truth's topology as a Wilson share", row.get("the truth's topology") == "50% [9–91] of 2",
          row.get("the truth's topology"))
    with open(out / "simplifiers.csv", newline="") as f:
        table = list(csv.DictReader(f))
    check("synthetic: simplifiers.csv holds the row",
          len(table) == 1 and table[0]["output_share_n"] == "2" and abs(float(table[0]["output_share_mean"]) - 0.3) < 1e-12
          and table[0]["hausdorff_from_curve_infinite"] == "1", str(table))

    _, tables = synthetic_run(work, False)
    cells = exactness_cells(tables, OT)
    check("synthetic without algorithms.csv: ranked, 0 of 3 (the checks above can fail)",
          any(c.startswith("0%") for c in cells), str(cells))


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    work = pathlib.Path(argv[2])
    work.mkdir(parents=True, exist_ok=True)
    real_run(argv[1], work)
    synthetic(work)
    print(f"{'all' if not FAILURES else len(FAILURES)} {'passed' if not FAILURES else 'failed'}")
    sys.exit(1 if FAILURES else 0)


if __name__ == "__main__":
    main(sys.argv)
