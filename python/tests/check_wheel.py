"""Packaging: `pip wheel --no-build-isolation --no-index .` (meson-python, no
network) builds a wheel of the package garotor (the extension, __init__.py,
dask.py, the stubs and py.typed; not the benchmark's _garotor_bench), which
installs into a fresh virtual environment of /usr/bin/python3
(--system-site-packages, for Debian's numpy) and passes python/tests there,
run from outside the source and build trees with no PYTHONPATH. Skipped
where meson-python or venv is missing. Run by the meson test
python-packaging (suite packaging); it takes a minute or more."""
import os
import pathlib
import subprocess
import sys
import zipfile

import pytest

pytest.importorskip("mesonpy", reason="meson-python is not installed (Debian: python3-mesonpy)")
pytest.importorskip("ensurepip", reason="venv cannot install pip (Debian: python3-venv)")

SRC = pathlib.Path(__file__).resolve().parents[2]


def test_wheel_installs_and_passes(tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "MYPYPATH")}
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True, env=env)
    py = str(venv / "bin" / "python")
    wheels = tmp_path / "wheels"
    r = subprocess.run([py, "-m", "pip", "wheel", "--no-build-isolation", "--no-index", "--no-deps",
                        "-w", str(wheels), str(SRC)], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    (whl,) = wheels.glob("garotor-*.whl")
    names = zipfile.ZipFile(whl).namelist()
    for f in ("garotor/__init__.py", "garotor/dask.py", "garotor/_garotor.pyi", "garotor/py.typed"):
        assert f in names, names
    assert any(n.startswith("garotor/_garotor.") and n.endswith(".so") for n in names), names
    assert not any("_garotor_bench" in n for n in names), names
    subprocess.run([py, "-m", "pip", "install", "--no-index", "--no-deps", str(whl)], check=True, env=env,
                   cwd=tmp_path, capture_output=True)
    code = ("import garotor, numpy, pathlib; assert garotor.exp(numpy.zeros(6)).shape == (4, 4); "
            "print(garotor.__version__, pathlib.Path(garotor.__file__).parent)")
    out = subprocess.run([py, "-c", code], check=True, env=env, cwd=tmp_path, capture_output=True,
                         text=True).stdout.split()
    assert pathlib.Path(out[1]).is_relative_to(venv), out
    r = subprocess.run([py, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(SRC / "python" / "tests")],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 0, r.stdout[-5000:] + r.stderr[-2000:]
    assert " passed" in r.stdout and " failed" not in r.stdout
