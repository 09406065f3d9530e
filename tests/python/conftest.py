"""Shared fixtures of the Python module's tests: the command line beside the module (the
oracle every function is compared with) and a reproducible Hypothesis profile."""
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

# Reproducible in CI: the same examples on every run, no database of earlier failures.
settings.register_profile("ci", derandomize=True, database=None, deadline=None, max_examples=60,
                          suppress_health_check=[HealthCheck.too_slow])
# A longer, random search for a developer: HYPOTHESIS_PROFILE=search.
settings.register_profile("search", derandomize=False, database=None, deadline=None, max_examples=5000,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))

SOURCE = pathlib.Path(os.environ.get("CURVEBENCH_SOURCE", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def cli():
    """Runs the `curvebench` command: cli("reconstruct", "-a", ...) -> CompletedProcess."""
    program = os.environ.get("CURVEBENCH_CLI") or shutil.which("curvebench")
    if not program:
        pytest.skip("no curvebench command (set CURVEBENCH_CLI)")

    def run(*arguments, check=True):
        done = subprocess.run([program, *map(str, arguments)], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"curvebench {' '.join(map(str, arguments))}: {done.stderr}")
        return done

    return run


@pytest.fixture(scope="session")
def source():
    return SOURCE
