"""Imported by an interpreter it was not built for, the package says which one it was built for and what to do.

Debian's python3 started with -S has no site-packages, so numpy is out of its reach: the same as a pyenv or virtual
environment python3 without numpy first on PATH, which a CI machine does not have.
"""

import os
import subprocess
import sys

import skinlayer
from skinlayer import _interpreter


def test_the_package_names_the_interpreter_it_was_built_for():
    assert os.path.samefile(_interpreter.EXECUTABLE, sys.executable)
    assert _interpreter.VERSION == f"{sys.version_info.major}.{sys.version_info.minor}"
    assert skinlayer.solve is not None


def test_an_interpreter_without_numpy_gets_one_clear_import_error():
    done = subprocess.run([sys.executable, "-S", "-c", "import skinlayer"], capture_output=True, text=True,
                          env=os.environ.copy())
    assert done.returncode != 0
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: skinlayer cannot import numpy under "), done.stderr
    assert f"it was built for {_interpreter.EXECUTABLE} (Python {_interpreter.VERSION}" in last, last
    assert f"run it with {_interpreter.EXECUTABLE}" in last, last
