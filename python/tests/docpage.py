"""docs/python.md's code, as the tests read it: its ```python blocks (meant
to run in order as one script, test_docs_python.py; one module for mypy,
check_typing.py) and its ```pycon sessions (replayed by doctest in
test_objects.py, test_trajectory.py and test_dask.py). Not a test file:
imported by them (python/tests is on sys.path under pytest)."""
import pathlib
import re

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"


def section(name=None):
    """The page's text, or that of its section `## name` (up to the next
    `## `); a ValueError where there is no such section."""
    text = DOC.read_text()
    if name is None:
        return text
    sec = text[text.index("\n## %s\n" % name):]
    end = sec.find("\n## ", 1)
    return sec if end < 0 else sec[:end]


def blocks(lang, name=None):
    """The fenced blocks of language lang (```python, ```pycon) in the page
    or its section name, in order, each its text without the fences."""
    return re.findall(r"^```%s\n(.*?)^```" % re.escape(lang), section(name), flags=re.S | re.M)


def python_blocks():
    """The ```python blocks with the line in the page each starts on (the
    line after its fence), in order."""
    text = DOC.read_text()
    return [(text.count("\n", 0, m.start(1)) + 1, m.group(1))
            for m in re.finditer(r"^```python\n(.*?)^```", text, flags=re.S | re.M)]
