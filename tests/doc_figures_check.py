#!/usr/bin/env python3
"""The figures the docs quote from the test programs, against what they print.

    doc_figures_check.py BUILD_DIR          check (the default suite runs this)
    doc_figures_check.py --fix BUILD_DIR    rewrite the numbers in the docs

A table in docs/*.md or README.md whose numbers a program of the build prints
has a comment right above it (blank lines between are allowed) that names the
program and, per column, where each number comes from:

    <!-- figures: test_versor
         column 2: worst of "exp vs expm(L(B)) 1: {row}"
         column 3: worst of "log(exp B) = B: {row}"
         row "isoclinic t, t, t in (π/4, π)" is "isoclinic t, t, t in (pi/4, pi)"
    -->

- "figures: PROGRAM ARGS..." runs BUILD_DIR/PROGRAM with ARGS (paths relative
  to the source tree) as the default suite would: no argument means the
  default number of cases and the fixed seed.
- "column N: FIELD of "NAME"" (N counts from 1, the row label being column 1):
  in every body row, column N shows FIELD of the line NAME of the output.
  {row} in NAME is the row's label (its first cell, backticks removed), or the
  name a "row "LABEL" is "NAME"" line gives it. "column N of "LABEL": ..."
  does the same for one row only (the other rows of that column are then not
  checked). Several "FIELD of "NAME"" joined by commas are the numbers of the
  cell in their order ("yes (1.8e-15)" holds one number, "jumps 1.1e-14
  (lihao3: 15)" two); the words around them are not checked. A remark in
  parentheses (outside quotes) is for the reader and is skipped.
- The output is read two ways. A check line of tests/testkit.h,
  "ok   NAME   n=1000    worst 1.425e-15  tol 1.0e-13", gives the fields
  worst, tol and n of NAME ("least X  >= Y": least, and tol for Y). A program whose first line is not a check line
  prints a table: its first line names the columns (separated by two spaces
  or more) and each further line is a row named by its first word; FIELD is a
  column's name (soak_c2_keys: "keys", "v jump", ...).
- A number shown must be the printed one, character for character
  (worst: 1.425e-15, as %.3e prints it), but a tolerance may drop the ".0" of
  its printed 1.0e-13 ("held to 1e-13").

A table that quotes figures no program of the default suite prints (a
one-off measurement, a non-default run, a benchmark) says so instead, with
its reason: <!-- figures not checked: WHY -->. A table with a number written
like a test's worst figure (d.ddde-dd) and neither comment is a failure, so
that a new table of test figures does not go unchecked.

The digits are those of the default build (gcc or clang, -ffp-contract=off)
on x86-64 with glibc's maths functions on their FMA code paths, what a CPU
with FMA runs by default and what CI runs: the digits of test_versor depend
on them. Off them (GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA, or a CPU
without FMA) it prints other last digits in three of its lines, two of them
in docs/numerics.md's tables; soak_c2_keys and figures_matrices print the
same either way.
ga_mv_gp's own code paths (SSE2, AVX2, AVX-512F) give the same bits
(tests/test_gp_blocks.c), and so do the two forms of each kernel of
ga/dispatch.c (tests/test_dispatch.c).

Before the docs, the checker runs on a page and an output of its own
(self_test): a figure that differs, a tolerance, a line not printed, a table
without a comment, and what --fix writes.

--fix writes the printed numbers into the cells in place, nothing else (not
the labels, not the prose around the table; a missing check stays a
failure). Exit status 0 when every figure matches (after --fix: when every
one could be written), 1 otherwise.
"""

import os
import re
import subprocess
import sys

# a number as a table shows it: not part of a word ("lihao3", "e12", "C²")
NUMBER = re.compile(r"(?<![\w.+-])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
# how tests/testkit.h prints a check that has a measured figure
CHECK = re.compile(r"^(ok|FAIL)\s+(.*?)\s+n=(\d+)\s+(.*)$")
WORST = re.compile(r"(worst|least) (\S+)\s+(?:tol|>=) (\S+)")
LOOKS_MEASURED = re.compile(r"\b\d\.\d{3}e[-+]\d{2}\b")
COMMENT = re.compile(r"^<!-- figures(?: not checked)?:")
SPEC = re.compile(r'([A-Za-z][\w-]*(?: [\w-]+)*) of "([^"]*)"')


class Fail(Exception):
    pass


def cells(line):
    """The cells of a table line "| a | b |" (escaped \\| kept in the cell)."""
    s = line.strip()
    s = s[1:] if s.startswith("|") else s
    s = s[:-1] if s.endswith("|") and not s.endswith("\\|") else s
    return [c.strip() for c in re.split(r"(?<!\\)\|", s)]


def label(cell):
    return cell.replace("`", "").strip()


def read_output(text):
    """{name: {field: printed}} of one program's output; names printed twice
    map to None (ambiguous)."""
    out = {}

    def put(name, fields):
        out[name] = None if name in out else fields

    lines = text.splitlines()
    for ln in lines:
        m = CHECK.match(ln)
        if not m:
            continue
        fields = {"n": m.group(3)}
        w = WORST.match(m.group(4))
        if w:
            fields[w.group(1)], fields["tol"] = w.group(2), w.group(3)
        put(m.group(2), fields)
    if lines and not CHECK.match(lines[0]):
        head = re.split(r"\s{2,}", lines[0].strip())
        for ln in lines[1:]:
            row = ln.split()
            if len(row) == len(head):
                put(row[0], dict(zip(head[1:], row[1:])))
    return out


def same(field, shown, printed):
    if shown == printed:
        return True
    # a tolerance: 1e-13 for the printed 1.0e-13
    return field == "tol" and shown == re.sub(r"\.0(?=e)", "", printed)


def written(field, shown, printed):
    """What --fix writes: the printed number, a tolerance in the doc's form."""
    if field == "tol" and "." not in shown:
        return re.sub(r"\.0(?=e)", "", printed)
    return printed


def unremarked(text):
    """text without its remarks: "(...)" outside double quotes."""
    out, depth, quoted = "", 0, False
    for ch in text:
        if ch == '"' and depth == 0:
            quoted = not quoted
        elif not quoted and ch == "(":
            depth += 1
        elif not quoted and ch == ")" and depth:
            depth -= 1
            continue
        if depth == 0:
            out += ch
    return re.sub(r"\s+", " ", out).strip()


class Table:
    def __init__(self, path, at, comment, lines):
        self.path, self.at, self.lines = path, at, lines  # at: index of the comment's first line
        text = " ".join(x.strip() for x in comment)
        text = re.sub(r"^<!--\s*", "", text)
        text = re.sub(r"\s*-->$", "", text)
        text = unremarked(text)
        self.where = "%s:%d" % (path, at + 1)
        m = re.match(r'figures:\s*(.*?)(?=\s+(?:column \d|row ")|$)', text)
        if not m or not m.group(1).strip():
            raise Fail("%s: the figures comment names no program" % self.where)
        self.command = m.group(1).split()
        rest = text[m.end():]
        self.columns = []  # (column index, row label or None, [(field, name)])
        self.rename = {}
        rest = rest.strip()
        starts = [m.start(1) for m in re.finditer(r'(?:^|\s)(column \d|row ")', rest)
                  if rest[:m.start(1)].count('"') % 2 == 0]
        for a, b in zip(starts, starts[1:] + [len(rest)]):
            part = rest[a:b].strip()
            c = re.match(r'column (\d+)(?: of "([^"]*)")?:\s*(.*)$', part)
            r = re.match(r'row "([^"]*)" is "([^"]*)"$', part)
            if c:
                specs = SPEC.findall(c.group(3))
                if not specs or SPEC.sub("", c.group(3)).strip(" ,"):
                    raise Fail('%s: cannot read "%s" (want: FIELD of "NAME", ...)' % (self.where, part))
                self.columns.append((int(c.group(1)) - 1, c.group(2), specs))
            elif r:
                self.rename[r.group(1)] = r.group(2)
            else:
                raise Fail('%s: cannot read "%s" (want: column N: FIELD of "NAME", or row "LABEL" is "NAME")'
                           % (self.where, part))
        if not self.columns:
            raise Fail("%s: the figures comment names no column" % self.where)


def find_tables(path, lines):
    """(figures comments with their tables, unchecked tables that look measured, notes)."""
    found, bare, notes = [], [], []
    i = 0
    fence = False
    while i < len(lines):
        ln = lines[i]
        if ln.startswith("```"):
            fence = not fence
        if fence:
            i += 1
            continue
        if COMMENT.match(ln):
            j = i
            while "-->" not in lines[j]:
                j += 1
                if j == len(lines):
                    raise Fail("%s:%d: the figures comment is not closed" % (path, i + 1))
            comment = lines[i:j + 1]
            k = j + 1
            while k < len(lines) and not lines[k].strip():
                k += 1
            t0 = k
            while k < len(lines) and lines[k].lstrip().startswith("|"):
                k += 1
            if k - t0 < 3:
                raise Fail("%s:%d: no table (header, --- line, rows) follows the figures comment" % (path, i + 1))
            if ln.startswith("<!-- figures not checked:"):
                notes.append("%s:%d: not checked: %s" % (path, t0 + 1,
                                                          re.sub(r"^<!-- figures not checked:\s*|\s*-->$", "",
                                                                 " ".join(x.strip() for x in comment))))
            else:
                found.append((Table(path, i, comment, lines), t0, k))
            i = k
            continue
        if ln.lstrip().startswith("|"):
            k = i
            while k < len(lines) and lines[k].lstrip().startswith("|"):
                k += 1
            for n in range(i, k):
                if LOOKS_MEASURED.search(lines[n]):
                    bare.append("%s:%d: a table with a figure written like a test's (%s) and no figures comment "
                                "above it: name the program that prints it (<!-- figures: ... -->, see %s) or say "
                                "why it is not checked (<!-- figures not checked: WHY -->)"
                                % (path, n + 1, LOOKS_MEASURED.search(lines[n]).group(0),
                                   "tests/doc_figures_check.py"))
                    break
            i = k
            continue
        i += 1
    return found, bare, notes


def run(build, src, command, cache):
    key = tuple(command)
    if key not in cache:
        exe = os.path.join(build, command[0])
        if not os.access(exe, os.X_OK):
            raise Fail("%s is not built (the figures comment names %s)" % (exe, command[0]))
        args = [a if os.path.isabs(a) or not os.path.exists(os.path.join(src, a)) else os.path.join(src, a)
                for a in command[1:]]
        p = subprocess.run([exe] + args, cwd=src, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           env=dict(os.environ, LC_ALL="C"), timeout=600)
        text = p.stdout.decode("utf-8", "replace")
        if p.returncode != 0:
            raise Fail("%s exits with status %d:\n%s" % (" ".join(command), p.returncode, text[-2000:]))
        cache[key] = read_output(text)
    return cache[key]


def check_table(t, t0, t1, out, fix, fails, differ):
    lines = t.lines
    prog = " ".join(t.command)
    head = cells(lines[t0])
    labels = [label(cells(lines[n])[0]) for n in range(t0 + 2, t1)]
    for lab in list(t.rename) + [label(c[1]) for c in t.columns if c[1] is not None]:
        if lab not in labels:
            fails.append('%s: the figures comment names a row "%s" the table does not have' % (t.where, lab))
    for n in range(t0 + 2, t1):
        row = cells(lines[n])
        lab = label(row[0])
        name_of_row = t.rename.get(lab, lab)
        new = list(row)
        for col, only, specs in t.columns:
            if only is not None and label(only) != lab:
                continue
            where = '%s:%d: row "%s", column %d ("%s")' % (t.path, n + 1, lab, col + 1,
                                                          head[col] if col < len(head) else "?")
            if col >= len(row):
                fails.append("%s: the row has only %d cells" % (where, len(row)))
                continue
            shown = NUMBER.findall(row[col])
            if len(shown) != len(specs):
                fails.append('%s: the cell "%s" shows %d numbers, the figures comment names %d'
                             % (where, row[col], len(shown), len(specs)))
                continue
            want = []
            for (field, name), s in zip(specs, shown):
                name = name.replace("{row}", name_of_row)
                got = out.get(name, {})
                if got is None:
                    fails.append('%s: %s prints "%s" more than once' % (where, prog, name))
                elif field not in got:
                    fails.append('%s: %s prints no %s of "%s"%s' % (
                        where, prog, field, name, "" if got else " (no such line: renamed or removed? "
                        "name it in the figures comment above the table)"))
                elif not same(field, s, got[field]):
                    differ.append('%s: shows %s, %s prints %s %s for "%s"' % (where, s, prog, field, got[field], name))
                    want.append(written(field, s, got[field]))
                    continue
                want.append(s)
            if fix and want != shown and len(want) == len(shown):
                parts = NUMBER.split(row[col])
                new[col] = "".join(p + (want[i] if i < len(want) else "") for i, p in enumerate(parts))
        if fix and new != row:
            lines[n] = replace_cells(lines[n], row, new)


def replace_cells(line, old, new):
    """line with its cells old[i] replaced by new[i], spacing and pipes kept."""
    pos = 0
    out = ""
    for o, w in zip(old, new):
        k = line.index(o, pos) if o else line.index("|", pos) + 1
        out += line[pos:k] + w
        pos = k + len(o)
    return out + line[pos:]


def check_doc(doc, text, build, src, cache, fix):
    """(text, after --fix), differences, other failures, notes, tables checked) of one page."""
    fails, differ, checked = [], [], 0
    lines = text.split("\n")
    try:
        found, bare, notes = find_tables(doc, lines)
    except Fail as e:
        return text, [], [str(e)], [], 0
    fails += bare
    for t, t0, t1 in found:
        try:
            out = run(build, src, t.command, cache)
        except Fail as e:
            fails.append("%s: %s" % (t.where, e))
            continue
        check_table(t, t0, t1, out, fix, fails, differ)
        checked += 1
    return "\n".join(lines), differ, fails, notes, checked


SELF_DOC = """Some prose with 1.000e-15 in it, not in a table.

<!-- figures: prog (a remark, "quoted" too)
     column 2: worst of "a: {row}"
     column 3: tol of "a: {row}", worst of "b"
     row "Alpha β" is "alpha"
-->

| family | x | y |
| --- | --- | --- |
| Alpha β |  1.000e-15 | held to 1e-13 (and 2.000e-16) |
| `gamma` | 3.000e-15 | 1e-9, 2.000e-16 |
| delta | 0 | 1e-13 and 2.000e-16 |

| bare | 4.000e-15 |
| --- | --- |
| x | 1 |
"""
SELF_OUT = """ok   a: alpha   n=10    worst 1.000e-15  tol 1.0e-13
ok   a: gamma   n=10    worst 3.001e-15  tol 1.0e-13
ok   b          n=1     worst 2.000e-16  tol 1.0e-13
"""


def self_test():
    """The checker on a page of its own, against an output of its own: the
    failures it must report, and what --fix must write."""
    cache = {("prog",): read_output(SELF_OUT)}
    text, differ, fails, _, n = check_doc("self.md", SELF_DOC, "", "", cache, False)
    want_differ = ['self.md:12: row "gamma", column 2 ("x"): shows 3.000e-15, prog prints worst 3.001e-15 for "a: gamma"',
                   'self.md:12: row "gamma", column 3 ("y"): shows 1e-9, prog prints tol 1.0e-13 for "a: gamma"']
    ok = text == SELF_DOC and n == 1 and differ == want_differ and len(fails) == 3 and \
        fails[0].startswith("self.md:15: a table with a figure written like a test's (4.000e-15)") and \
        'row "delta", column 2 ("x"): prog prints no worst of "a: delta"' in fails[1] and \
        'row "delta", column 3 ("y"): prog prints no tol of "a: delta"' in fails[2]
    text, differ, fails, _, _ = check_doc("self.md", SELF_DOC, "", "", cache, True)
    ok = ok and differ == want_differ and text == SELF_DOC.replace(
        "| `gamma` | 3.000e-15 | 1e-9, 2.000e-16 |", "| `gamma` | 3.001e-15 | 1e-13, 2.000e-16 |")
    text, differ, _, _, _ = check_doc("self.md", text, "", "", cache, False)
    if not ok or differ:
        raise Fail("the checker does not find on a page of its own what it should (tests/doc_figures_check.py, "
                   "self_test)")


def main(argv):
    fix = "--fix" in argv
    args = [a for a in argv[1:] if a != "--fix"]
    if len(args) != 1:
        sys.stderr.write(__doc__.split("\n\n")[1] + "\n")
        return 2
    try:
        self_test()
    except Fail as e:
        print("FAIL: %s" % e)
        return 1
    build = os.path.abspath(args[0])
    src = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    docs = [os.path.join("docs", f) for f in sorted(os.listdir(os.path.join(src, "docs"))) if f.endswith(".md")]
    docs.append("README.md")
    fails, differ, notes, cache, checked = [], [], [], {}, 0
    for doc in docs:
        with open(os.path.join(src, doc), encoding="utf-8") as f:
            text = f.read()
        new, d, fl, ns, n = check_doc(doc, text, build, src, cache, fix)
        differ, fails, notes, checked = differ + d, fails + fl, notes + ns, checked + n
        if fix and new != text:
            with open(os.path.join(src, doc), "w", encoding="utf-8") as f:
                f.write(new)
    for n in notes:
        print("note: " + n)
    if fix:
        for f in differ:
            print("fixed: " + f)
        for f in fails:
            print("FAIL: " + f)
        print("doc_figures_check --fix: %d tables, %d numbers rewritten, %d failures --fix cannot mend"
              % (checked, len(differ), len(fails)))
        return 1 if fails else 0
    for f in differ + fails:
        print("FAIL: " + f)
    if differ or fails:
        print("\n%d figures of the docs differ from what the programs print now, %d other failures." % (
            len(differ), len(fails)))
        if differ:
            print("If the new figures are right, refresh the tables (only their numbers change, in place):\n"
                  "    /usr/bin/python3 tests/doc_figures_check.py --fix %s\n"
                  "then read the prose around them again. (Different here although nothing "
                  "changed? The figures are those of glibc's FMA code paths: the top of tests/doc_figures_check.py.)" % (os.path.relpath(build, src) if build.startswith(src + os.sep) else build))
        if fails:
            print("The other failures say what is wrong and where; --fix does not mend them. A line the program "
                  "no longer prints is a check renamed or removed: name the new one in the figures comment above "
                  "the table (its syntax: the top of tests/doc_figures_check.py).")
        return 1
    print("doc_figures_check: %d tables, all figures as printed" % checked)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
