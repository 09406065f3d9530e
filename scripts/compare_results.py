#!/usr/bin/python3
"""Checks that runs gave the same rows: each results.csv against the first, byte for byte
once the columns no two runs share are blanked (runtime_ms, startup_ms: time, not
results).

    scripts/compare_results.py A/results.csv B/results.csv [C/results.csv ...]

Prints every row that differs (its job, algorithm and input, and each field that differs
with both values), every job one file has and another lacks, and a last line with the
count; exits 1 if anything differs, 2 if a file cannot be read as a results table.
--ignore COLUMN blanks another column too (given once or more).
Used by tests/cli/curvebench_determinism_test.sh and scripts/glyph_sweep_twice.sh.
"""
import argparse
import csv
import io
import sys

TIMING = ("runtime_ms", "startup_ms")


def unreadable(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def blanked_lines(path, ignored):
    """The header and {job: line} of a results.csv, each line written anew by the csv module
    with the ignored columns emptied, so that the rest compares as the file's own text."""
    try:
        with open(path, newline="") as f:
            reader = csv.reader(f)
            header = next(reader)
            rows = list(reader)
    except (OSError, StopIteration, csv.Error) as error:
        unreadable(f"{path}: not a results table ({error or 'empty'})")
    if "job" not in header:
        unreadable(f"{path}: no job column")
    blank = [header.index(c) for c in ignored if c in header]
    lines = {}
    for row in rows:
        if len(row) != len(header):
            unreadable(f"{path}: a row of {len(row)} fields under a header of {len(header)}: {row}")
        for k in blank:
            row[k] = ""
        text = io.StringIO()
        csv.writer(text, lineterminator="\n").writerow(row)
        lines.setdefault(row[header.index("job")], []).append(text.getvalue())
    return header, lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+", help="results.csv files; each is compared with the first")
    parser.add_argument("--ignore", action="append", default=[], help="another column to blank")
    args = parser.parse_args()
    if len(args.files) < 2:
        parser.error("give two results.csv files or more")
    ignored = list(TIMING) + args.ignore
    reference_header, reference = blanked_lines(args.files[0], ignored)
    differences = 0
    for other_file in args.files[1:]:
        header, other = blanked_lines(other_file, ignored)
        if header != reference_header:
            print(f"{other_file}: another header than {args.files[0]}'s")
            differences += 1
            continue
        column = {name: k for k, name in enumerate(header)}
        for job in sorted(set(reference) | set(other), key=lambda j: (len(j), j)):
            a, b = reference.get(job), other.get(job)
            if a == b:
                continue
            differences += 1
            if a is None or b is None:
                where = other_file if a is None else args.files[0]
                print(f"job {job}: only in {where}")
                continue
            if len(a) != 1 or len(b) != 1:
                print(f"job {job}: {len(a)} rows in {args.files[0]}, {len(b)} in {other_file}")
                continue
            x, y = next(csv.reader([a[0]])), next(csv.reader([b[0]]))
            fields = "; ".join(f"{name}: {x[k]!r} / {y[k]!r}" for name, k in column.items() if x[k] != y[k])
            print(f"job {job} ({x[column['algorithm']]} on {x[column['input']]}) differs in {other_file}: {fields}")
    files = " and ".join(args.files)
    print(f"{differences} rows differ" if differences else f"the same rows ({len(reference)} jobs, "
          f"{', '.join(ignored)} aside): {files}")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())
