"""Shared fixtures: the built tool, and a runner that parses its output."""
import os
import shutil
import subprocess

import numpy as np
import pytest


def _tool():
    path = os.environ.get("GAROTOR_TOOL") or shutil.which("garotor")
    return path if path and os.access(path, os.X_OK) else None


@pytest.fixture(scope="session")
def tool():
    """Run the garotor tool with args on rows of numbers (written with %.17g,
    which reads back as the same double); return its output as an array."""
    path = _tool()
    if path is None:
        pytest.skip("the garotor tool is not found (set GAROTOR_TOOL)")

    def run(args, rows):
        text = "\n".join(" ".join("%.17g" % v for v in row) for row in np.asarray(rows, dtype=float))
        r = subprocess.run([path] + list(args), input=text + "\n", capture_output=True, text=True, check=True)
        return np.array([[float(x) for x in line.split()] for line in r.stdout.splitlines() if line.strip()])

    return run


@pytest.fixture
def rng():
    return np.random.default_rng(20240518)
