"""A build folder whose Python package was configured but never built: importing it says how to build it."""

import os
import subprocess
import sys

import pytest


def test_an_unbuilt_package_raises_an_import_error_that_says_how_to_build_it():
    unbuilt = os.environ.get("SKINLAYER_UNBUILT_PYTHON")
    if not unbuilt:
        pytest.skip("SKINLAYER_UNBUILT_PYTHON (set by ctest) names the configured stand-in")
    run = subprocess.run([sys.executable, "-c", "import skinlayer"], capture_output=True, text=True,
                         env={**os.environ, "PYTHONPATH": unbuilt})
    assert run.returncode != 0
    last = run.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: skinlayer's Python package in ")
    assert "--target skinlayer_python" in last and "./setup.sh run" in last
