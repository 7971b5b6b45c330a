#!/bin/sh
# The figures of docs/: docs/make-figures.sh, run with the built tool into a
# temporary directory, must reproduce the committed docs/figures/*.svg and
# *.txt byte for byte (every coordinate is written with two decimals, so the
# bytes are stable), and every SVG must be well-formed XML (xmllint, when it
# is installed).
set -u
G=$1
docs=$(cd "$(dirname "$0")/../docs" && pwd)
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

sh "$docs/make-figures.sh" "$G" "$d/figures" >"$d/log" 2>&1 || fail "make-figures.sh: $(cat "$d/log")"
slope=$(sed -n 's/.*fitted slope of log(error) against log(step): //p' "$d/log")
awk -v s="$slope" 'BEGIN { exit !(s != "" && s > 0.9 && s < 1.1) }' ||
    fail "Li-Hao Fig. 5: the Euler error is not O(step): slope '$slope'"
for f in "$d"/figures/*; do
    name=$(basename "$f")
    [ -f "$docs/figures/$name" ] || { fail "$name is generated but not committed"; continue; }
    cmp -s "$f" "$docs/figures/$name" ||
        fail "$name differs from the committed one (rerun: sh docs/make-figures.sh BUILD/garotor)"
done
for f in "$docs"/figures/*.svg "$docs"/figures/*.txt; do
    [ -f "$d/figures/$(basename "$f")" ] || fail "$(basename "$f") is committed but no longer generated"
done
if command -v xmllint >/dev/null 2>&1; then
    for f in "$d"/figures/*.svg; do
        xmllint --noout "$f" || fail "$(basename "$f") is not well-formed XML"
    done
else
    echo "xmllint not installed: well-formedness not checked"
fi
[ "$fails" -eq 0 ] && echo "figures_test: all passed"
exit $((fails > 0))
