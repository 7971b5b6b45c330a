#!/usr/bin/env python3
"""Every relative link of docs/*.md and README.md resolves.

    doc_links_check.py [SOURCE_DIR]

For each Markdown link or image, [text](target) or ![alt](target), outside
code (fenced blocks and `spans`), whose target is not a URL (http:, https:,
mailto:): the file it names exists, relative to the page; and its #anchor,
where it has one and the target is a Markdown page (or the page itself,
"#anchor" alone), is a heading of that page as GitHub makes anchors of
headings (lower case, punctuation but - and _ dropped, spaces to -, a
repeated anchor numbered -1, -2, ...) or an explicit <a id="..."> /
<a name="...">. Links into notebooks (.ipynb) and other files are checked
for the file only.

It also checks the folds of the answers (<details><summary>Answer</summary>
... </details>, folded on GitHub) in the pages of exercises, FOLDED below:
each fold is closed before the next opens, and every fenced block of the
page's exercises (of exercises.md, all; of students.md, those under
"## Exercises") lies inside one, so that no answer shows before the reader
opens it.

Prints each failure with its page and line; exit status 0 when there is
none. Standard library only.
"""

import os
import re
import sys

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^()\s]+(?:\([^()\s]*\)[^()\s]*)*)(?:\s+\"[^\"]*\")?\)")
HTML_ANCHOR = re.compile(r"<a\s+(?:id|name)=\"([^\"]+)\"")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")


def prose_lines(text):
    """(line number, line) of the lines outside fenced code blocks."""
    fenced = False
    for n, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield n, line


def slug(heading):
    s = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text
    s = s.replace("`", "").lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(text):
    seen = {}
    out = set()
    for _, line in prose_lines(text):
        m = HEADING.match(line)
        if m:
            base = slug(m.group(2))
            k = seen.get(base, 0)
            seen[base] = k + 1
            out.add(base if k == 0 else "%s-%d" % (base, k))
        out.update(HTML_ANCHOR.findall(line))
    return out


def links(text):
    for n, line in prose_lines(text):
        line = re.sub(r"`[^`]*`", "", line)
        for m in LINK.finditer(line):
            yield n, m.group(1)


FOLDED = {"exercises.md": None, "students.md": "## Exercises"}


def check_folds(name, text, section):
    """The failures of the answer folds of one page."""
    bad = []
    inside = False
    on = section is None
    opened = 0
    fenced = False
    for n, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            fenced = not fenced
            if fenced and on and not inside:
                bad.append("%s:%d: a fenced block outside an answer fold" % (name, n))
            continue
        if fenced:
            continue
        if section is not None and line.startswith("## "):
            on = line.strip() == section
        if line.startswith("<details>"):
            if inside:
                bad.append("%s:%d: <details> inside another fold" % (name, n))
            inside = True
            opened += 1
        elif line.startswith("</details>"):
            if not inside:
                bad.append("%s:%d: </details> without <details>" % (name, n))
            inside = False
    if inside:
        bad.append("%s: a fold is not closed" % name)
    if opened == 0:
        bad.append("%s: no answer folds" % name)
    return bad


def check(src):
    pages = [os.path.join(src, "README.md")]
    docs = os.path.join(src, "docs")
    pages += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    cache = {}

    def anchors_of(path):
        if path not in cache:
            with open(path, encoding="utf-8") as f:
                cache[path] = anchors(f.read())
        return cache[path]

    bad = []
    count = 0
    for page in pages:
        with open(page, encoding="utf-8") as f:
            text = f.read()
        rel = os.path.relpath(page, src)
        for n, target in links(text):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                continue
            count += 1
            path, _, frag = target.partition("#")
            where = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(where):
                bad.append("%s:%d: %s: no such file" % (rel, n, target))
                continue
            if frag and where.endswith(".md") and frag not in anchors_of(where):
                bad.append("%s:%d: %s: no heading or anchor #%s in %s"
                           % (rel, n, target, frag, os.path.relpath(where, src)))
        if os.path.basename(page) in FOLDED:
            bad += check_folds(rel, text, FOLDED[os.path.basename(page)])
    return count, bad


def self_test():
    text = "# A `b` c\n## Accuracy (measured)\n```sh\n# not a heading\n```\n## ℓ(R), x²\n## A b c\n"
    got = anchors(text)
    want = {"a-b-c", "accuracy-measured", "ℓr-x²", "a-b-c-1"}
    assert got == want, got
    found = list(links("see [x](a.md#b) and ![p](f/g.svg) `[no](c.md)`\n```\n[no](d.md)\n```\n"))
    assert found == [(1, "a.md#b"), (1, "f/g.svg")], found
    page = "Q\n<details><summary>Answer</summary>\n\n```text\n$ a\n```\n</details>\n"
    assert check_folds("p", page, None) == []
    assert len(check_folds("p", page.replace("</details>", ""), None)) == 1
    assert check_folds("p", "```text\n```\n" + page, None) == ["p:1: a fenced block outside an answer fold"]
    assert check_folds("p", "```sh\n```\n## Exercises\n" + page, "## Exercises") == []


def main():
    self_test()
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    count, bad = check(os.path.abspath(src))
    for b in bad:
        print("FAIL: " + b)
    if count == 0:
        print("FAIL: no relative links found")
        return 1
    if not bad:
        print("doc_links_check: %d relative links resolve, the answers of %s are folded"
              % (count, " and ".join(sorted(FOLDED))))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
