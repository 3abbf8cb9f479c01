"""Shared fixtures: the command line (an independent path to the same numbers) and the data.

ctest sets FRICTIONLAB_CLI (the frictionlab command) and FRICTIONLAB_DATA_DIR (data/), and puts
the build's package first on PYTHONPATH (python/tests/CMakeLists.txt).
"""

import csv
import os
import subprocess

import numpy as np
import pytest


def _env(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run these tests through ctest (python/tests/CMakeLists.txt)")
    return value


@pytest.fixture(scope="session")
def cli():
    return _env("FRICTIONLAB_CLI")


@pytest.fixture(scope="session")
def scenarios():
    return os.path.join(_env("FRICTIONLAB_DATA_DIR"), "scenarios")


def run_cli(cli, *args, check=True):
    """Runs the command line; returns the CompletedProcess (text)."""
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"{cli} {' '.join(map(str, args))} failed ({done.returncode}): {done.stderr}")
    return done


def read_csv_columns(path, text_columns=("law",)):
    """A CSV file as {column: float64 array}, every number read by Python's float() (exact for
    the command line's shortest / 17-digit output); the columns named in text_columns (the law
    of `frictionlab friction`) as lists of strings."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [r[i] for r in body] if name in text_columns else np.array([float(r[i]) for r in body])
            for i, name in enumerate(header)}


def bits(x):
    """The bit patterns of a float64 array (distinguishes -0.0 from 0.0 and NaN payloads)."""
    return np.ascontiguousarray(np.asarray(x, dtype=np.float64)).view(np.uint64)
