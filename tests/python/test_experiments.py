"""run, certify, tightness and hunt against the command line's own runs of them."""
import csv
import json

import numpy as np
import pandas as pd
import pytest

import curvebench

TIMED = {"runtime_ms", "startup_ms", "picture"}


def test_run_gives_the_rows_of_the_command_lines_results_csv(cli, tmp_path):
    cli("run", "smoke", "-a", "nn-crust,crust,stretch-denoise", "-q", "--no-report", "--pictures", "none", "-o",
        tmp_path / "cli")
    with open(tmp_path / "cli" / "results.csv", newline="") as f:
        expected = list(csv.DictReader(f))
    run = curvebench.run("smoke", ["nn-crust", "crust", "stretch-denoise"])
    frame = run.results
    assert list(frame.columns) == list(expected[0].keys())
    assert len(frame) == len(expected) == run.counts["jobs"] == run.counts["ok"]
    for row, want in zip(frame.to_dict("records"), expected):
        for column, text in want.items():
            if column in TIMED:
                continue
            value = row[column]
            if text == "":
                assert value == "" or pd.isna(value), column
            elif isinstance(value, (bool, np.bool_)):
                assert value == (text == "1"), column
            elif isinstance(value, (float, np.floating)):
                assert value == float(text), column
            else:
                assert str(value) == text, column
    assert frame.exact.dtype == "boolean" and frame.n_points.dtype == "Int64" and frame.rms.dtype == float
    assert run.directory is None


def test_run_writes_its_directory_and_summary_with_intervals(tmp_path):
    run = curvebench.run("smoke", ["nn-crust"], out=tmp_path / "run", report=True)
    assert (tmp_path / "run" / "results.csv").exists() and (tmp_path / "run" / "report.html").exists()
    summary = run.summary
    assert len(summary) == 2 and set(summary.algorithm) == {"nn-crust"}
    interval_columns = [c for c in summary.columns if "low" in c or "high" in c]
    assert interval_columns, summary.columns
    exact = summary.set_index("level")
    assert len(exact) == 2


def test_bad_runs_raise_the_command_lines_messages(cli, tmp_path):
    with pytest.raises(KeyError, match="unknown suite 'nope'"):
        curvebench.run("nope", ["nn-crust"])
    with pytest.raises(KeyError, match="unknown algorithm 'nope'"):
        curvebench.run("smoke", ["nope"])
    with pytest.raises(ValueError, match="report=True"):
        curvebench.run("smoke", ["nn-crust"], report=True)
    curvebench.run("smoke", ["nn-crust"], out=tmp_path / "again")
    message = cli("run", "smoke", "-a", "nn-crust", "-q", "-o", tmp_path / "again", check=False).stderr.strip()
    with pytest.raises(ValueError) as raised:
        curvebench.run("smoke", ["nn-crust"], out=tmp_path / "again")
    assert message == "curvebench: " + str(raised.value)
    with pytest.raises(KeyError, match="unknown algorithm"):
        curvebench.certify("nope")
    with pytest.raises(ValueError, match="has no proven epsilon bound"):
        curvebench.certify("emst")


def test_certify_gives_the_command_lines_summary(cli, tmp_path):
    expected = json.loads(cli("certify", "-a", "crust", "--count", 6, "--json", "-q", "-o", tmp_path / "cli").stdout)
    summary = curvebench.certify("crust", count=6, out=tmp_path / "py")
    for key, value in expected.items():
        if key not in ("results", "counterexamples"):
            assert summary[key] == value, key
    assert summary["results"] == str(tmp_path / "py" / "results.csv")
    assert curvebench.certify("crust", count=6)["results"] is None


def test_tightness_gives_the_command_lines_record(cli, tmp_path):
    expected = json.loads(cli("tightness", "-a", "crust", "--curves", 2, "--moves", 5, "--json", "-o",
                              tmp_path / "cli").stdout)[0]
    record = curvebench.tightness("crust", curves=2, moves=5, out=tmp_path / "py")
    for key, value in expected.items():
        if key not in ("seconds", "directory"):
            assert record[key] == value, key
    both = curvebench.tightness(["crust", "nn-crust"], curves=1, moves=2)
    assert [r["algorithm"] for r in both] == ["crust", "nn-crust"]


def test_hunt_gives_the_command_lines_summary_keys(cli, tmp_path):
    expected = json.loads(cli("hunt", "-a", "emst", "--seconds", 2, "--json").stdout)
    summary = curvebench.hunt("emst", seconds=2)
    assert set(summary) == set(expected) and summary["algorithm"] == "emst" and summary["cases"] > 0
