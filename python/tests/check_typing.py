"""Packaging: the stubs (garotor/_garotor.pyi, py.typed) against
`python3 -m mypy --strict` (Debian's python3-mypy): the Python of
docs/python.md (its ```python blocks as one module, the lines of each of its
```pycon sessions as another) and python/tests/typed_example.py, which is run too. dask and
distributed are not analysed (follow_imports = skip: their own sources take
minutes); garotor.dask is. Skipped where mypy is not installed. Run by the
meson test python-packaging (suite packaging), with PYTHONPATH the build's
python/ (MYPYPATH is set from it)."""
import doctest
import os
import pathlib
import subprocess
import sys

import pytest

import docpage

pytest.importorskip("mypy", reason="mypy is not installed (Debian: python3-mypy)")

HERE = pathlib.Path(__file__).resolve().parent


def docs_modules():
    """The Python of docs/python.md as modules' texts: the ```python blocks
    (one script: the later ones use the names of the first, and
    test_docs_python.py runs them so), then each session."""
    mods = ["\n".join(docpage.blocks("python"))]
    parser = doctest.DocTestParser()
    for block in docpage.blocks("pycon"):
        mods.append("".join(ex.source for ex in parser.get_examples(block)))
    assert len(mods) >= 3 and all(mods)
    return mods


def garotor_dir():
    import garotor
    return str(pathlib.Path(garotor.__file__).resolve().parents[1])


def test_mypy_strict(tmp_path):
    files = []
    for k, text in enumerate(docs_modules()):
        files.append(tmp_path / ("docs_python_md_%d.py" % k))
        files[-1].write_text(text)
    (tmp_path / "mypy.ini").write_text("[mypy]\nstrict = True\n[mypy-dask.*,distributed.*]\nfollow_imports = skip\n")
    env = dict(os.environ, MYPYPATH=garotor_dir())
    r = subprocess.run([sys.executable, "-m", "mypy", "--config-file", str(tmp_path / "mypy.ini"),
                        "--cache-dir", str(tmp_path / "cache"), "--no-error-summary",
                        *map(str, files), str(HERE / "typed_example.py")],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr


def test_mypy_finds_errors(tmp_path):
    """The check can fail: a wrong type is reported against the stubs."""
    (tmp_path / "bad.py").write_text("import garotor\nx: int = garotor.exp([0, 0, 0, 0, 0, 1])\n"
                                     "garotor.Path([0, 1], 3, scheme=2)\n")
    env = dict(os.environ, MYPYPATH=garotor_dir())
    r = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--cache-dir", str(tmp_path / "cache"),
                        str(tmp_path / "bad.py")], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 1 and "bad.py:2: error: Incompatible types in assignment" in r.stdout, r.stdout
    assert "bad.py:3: error: Argument \"scheme\" to \"Path\" has incompatible type \"int\"" in r.stdout, r.stdout


def test_typed_example_runs():
    subprocess.run([sys.executable, str(HERE / "typed_example.py")], check=True)
