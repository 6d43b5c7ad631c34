"""Shared helpers of the Python package's tests: the command line to compare with, and its CSV output.

ctest sets SKINLAYER_EXECUTABLE (build/skinlayer) and PYTHONPATH (build/python) for every test here.
"""

import csv
import io
import os
import subprocess

import numpy as np
import pytest


def _executable():
    path = os.environ.get("SKINLAYER_EXECUTABLE")
    if not path:
        pytest.fail("SKINLAYER_EXECUTABLE is not set; run these tests through ctest")
    return path


def run_cli(arguments, stdin=""):
    """Runs `skinlayer ARGUMENTS`; returns (exit status, stdout, stderr)."""
    done = subprocess.run([_executable()] + list(arguments), input=stdin, capture_output=True, text=True,
                          timeout=300)
    return done.returncode, done.stdout, done.stderr


def cli_table(arguments, stdin=""):
    """The CSV that `skinlayer ARGUMENTS` writes, as a dict of column name -> float array."""
    status, out, err = run_cli(arguments, stdin)
    assert status == 0, err
    rows = list(csv.reader(io.StringIO(out)))
    header, data = rows[0], rows[1:]
    return {name: np.array([float(row[k]) for row in data]) for k, name in enumerate(header)}


def cli_error(arguments, stdin=""):
    """The one-line message of a command that fails with status 2, without its 'skinlayer: error: ' prefix."""
    status, _, err = run_cli(arguments, stdin)
    assert status == 2, err
    line = err.strip().splitlines()[0]
    prefix = "skinlayer: error: "
    assert line.startswith(prefix), line
    return line[len(prefix):]


def assert_close(python, cli, tolerance=1e-12):
    """Equal to `tolerance` relative to the larger magnitude (absolutely below 1)."""
    python, cli = np.asarray(python, dtype=float), np.asarray(cli, dtype=float)
    assert python.shape == cli.shape
    scale = np.maximum(1.0, np.maximum(np.abs(python), np.abs(cli)))
    worst = np.max(np.abs(python - cli) / scale) if python.size else 0.0
    assert worst <= tolerance, f"differs by {worst:.3g} (tolerance {tolerance:g})"
