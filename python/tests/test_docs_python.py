"""docs/python.md's ```python blocks run in order as one script, in one
namespace, as a reader pasting the page top to bottom runs them (each
statement reported at its line of the page), in a scratch directory. Where a
line of a block is an expression whose comment is a Python expression (`#
True`, `# (5, 4, 4)`, `# array([0.01])`), the comment is the value the page
quotes: it must be the value's repr, exactly. A comment that is prose (`#
past the last key at its velocity`) is not checked. The ```pycon sessions
are doctests elsewhere (docpage.py says where); the same blocks go through
mypy --strict in check_typing.py."""
import ast
import io
import tokenize

import pytest

import docpage

pytest.importorskip("dask.array", reason="the page's ufunc block uses dask (Debian: python3-dask)")


def comments(src):
    """{line: the text of the comment on it, without '#' and the spaces around}"""
    out = {}
    for tok in tokenize.generate_tokens(io.StringIO(src).readline):
        if tok.type == tokenize.COMMENT:
            out[tok.start[0]] = tok.string[1:].strip()
    return out


def quoted(comment):
    """Whether a comment quotes a value: it parses as one Python expression"""
    try:
        ast.parse(comment, mode="eval")
    except SyntaxError:
        return False
    return True


def run_page(tmp_path, monkeypatch):
    """Run every block; return the list of (page line, quoted, repr) of the
    lines whose comment quotes their value."""
    monkeypatch.chdir(tmp_path)
    ns = {"__name__": "docs_python_md"}
    checked = []
    for start, src in docpage.python_blocks():
        tree = ast.parse(src)
        notes = comments(src)
        for stmt in tree.body:
            line = start + stmt.lineno - 1
            ast.increment_lineno(stmt, start - 1)  # tracebacks name the page's lines
            note = notes.get(stmt.end_lineno - start + 1)
            if isinstance(stmt, ast.Expr) and note is not None and quoted(note):
                value = eval(compile(ast.Expression(stmt.value), str(docpage.DOC), "eval"), ns)
                checked.append((line, note, repr(value)))
            else:
                exec(compile(ast.Module([stmt], type_ignores=[]), str(docpage.DOC), "exec"), ns)
    return checked


def test_python_blocks_run_as_one_script(tmp_path, monkeypatch):
    checked = run_page(tmp_path, monkeypatch)
    wrong = ["docs/python.md:%d: the page quotes %s, the line gives %s" % c for c in checked if c[1] != c[2]]
    assert not wrong, "\n".join(wrong)
    # the page quotes values (a change of this count is a change of the page
    # or of what counts as a quoted value)
    assert len(checked) >= 5, checked


def test_quoted_values_are_checked(tmp_path, monkeypatch):
    """The check can fail: a page whose block quotes a wrong value, or whose
    later block uses a name an earlier one rebound, is reported"""
    page = tmp_path / "page.md"
    page.write_text("```python\nx = [1, 2]\nlen(x)   # 3\nlen(x)   # the length\n```\n")
    monkeypatch.setattr(docpage, "DOC", page)
    assert run_page(tmp_path, monkeypatch) == [(3, "3", "2")]
    page.write_text("```python\nimport numpy as np, garotor\n"
                    "p = garotor.Path([0, 1, 2], garotor.exp(np.zeros((3, 6))))\n```\n"
                    "```python\np = garotor.Path([0, 0.5], garotor.exp(np.zeros((2, 6))))\n```\n"
                    "```python\np.sample([2.0])   # p: the first Path\n```\n")
    with pytest.raises(Exception, match="outside the path's range") as e:
        run_page(tmp_path, monkeypatch)
    assert e.traceback[-1].lineno + 1 == 9  # the page's line (traceback's lineno is 0-based)
