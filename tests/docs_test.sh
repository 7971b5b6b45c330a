#!/bin/sh
# The docs against the tool.
#  1. `garotor --help` and `garotor CMD --help` must print exactly the block
#     that follows "$ garotor ... --help" in docs/tool.md.
#  2. Every shell session shown in a ```text block of docs/tool.md,
#     docs/tutorial.md, docs/schemes.md and docs/errors.md ("$ command" lines, each followed
#     by what it printed) is run again, from a scratch directory laid out like
#     the repository (build/garotor, docs/, and `garotor` on the PATH), and
#     must print the same: words exactly, numbers to 1e-12 relative (so a
#     change of the library at rounding level does not fail it), the version
#     in the demo's first line aside. The tutorial's C programs are written
#     out from its ```c blocks, each to the file its first line names
#     ("/* point.c: ..."), for its sessions to compile; if they cannot be
#     linked here (a sanitizer build), the blocks that compile them are
#     skipped with a note.
set -u
G=$1
case $G in /*) ;; *) G=$(pwd)/$G ;; esac
src=$(cd "$(dirname "$0")/.." && pwd)
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
export LC_ALL=C

# ---- 1. the help texts -------------------------------------------------------
doc=$src/docs/tool.md
[ -f "$doc" ] || { echo "FAIL: $doc is missing"; exit 1; }
for c in "" demo exp log interp; do
    cmd="garotor${c:+ $c} --help"
    awk -v want="\$ $cmd" '$0 == want { on = 1; next } on && /^```/ { exit } on' "$doc" >"$d/doc"
    [ -s "$d/doc" ] || { fail "docs/tool.md has no block for '$cmd'"; continue; }
    # shellcheck disable=SC2086 # $c is one word or none
    "$G" $c --help >"$d/help" 2>&1 || fail "'$cmd' exits non-zero"
    cmp -s "$d/help" "$d/doc" || fail "'$cmd' differs from docs/tool.md:
$(diff "$d/doc" "$d/help")"
done

# ---- 2. the sessions shown in the docs -----------------------------------------
w=$d/work
mkdir -p "$w/build" "$w/bin" "$d/blocks"
ln -s "$G" "$w/build/garotor"
ln -s "$(dirname "$G")/libgarotor.a" "$w/build/libgarotor.a"
for f in docs include; do ln -s "$src/$f" "$w/$f"; done
ln -s "$(dirname "$G")/include" "$w/build/include"
printf '#!/bin/sh\nexec "%s" "$@"\n' "$G" >"$w/bin/garotor"
chmod +x "$w/bin/garotor"
awk -v dir="$w" '
    /^```c$/ { on = 1; name = ""; next }
    on && /^```/ { on = 0; next }
    on && name == "" { name = match($0, /^\/\* [a-z_]+\.c:/) ? substr($0, 4, RLENGTH - 4) : "unnamed.c" }
    on { print > (dir "/" name) }
' "$src/docs/tutorial.md"
[ -f "$w/point.c" ] && [ -f "$w/path.c" ] && [ ! -f "$w/unnamed.c" ] ||
    fail "docs/tutorial.md: its C blocks should be point.c and path.c, each named in its first line"
can_cc=0
(cd "$w" && cc -std=c11 -Iinclude -Ibuild/include point.c build/libgarotor.a -lm -o point) \
    >/dev/null 2>&1 && can_cc=1
rm -f "$w/point"

# same WANT GOT: the same lines; tokens (split at blanks, commas, parentheses) equal, or
# both numbers within 1e-12 relative, or, for a number shown with d decimals
# and no exponent (%.2f), within one unit of its last decimal: a change of the
# library at rounding level can move a value across a rounding tie
# (0.375 against 0.37499999999999994 prints 0.38 or 0.37); the demo's version
# line aside
same() {
    awk 'function num(s) { return s ~ /^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/ }
         function abs(x) { return x < 0 ? -x : x }
         function last_decimal(s) { return s ~ /[.][0-9]+$/ ? 1.000001 * 10 ^ -(length(s) - index(s, ".")) : 0 }
         NR == FNR { w[++nw] = $0; next }
         { g[++ng] = $0 }
         END {
             if (nw != ng) { print "  " nw " lines shown, " ng " printed"; bad = 1 }
             for (i = 1; i <= nw && i <= ng; i++) {
                 if (w[i] ~ /^garotor [0-9.]+: / && g[i] ~ /^garotor [0-9.]+: /) continue
                 na = split(w[i], a, /[ ,()]+/); nb = split(g[i], b, /[ ,()]+/)
                 ok = na == nb
                 for (k = 1; ok && k <= na; k++)
                     if (a[k] != b[k] && !(num(a[k]) && num(b[k]) &&
                         (abs(a[k] - b[k]) <= 1e-12 * (abs(a[k]) > 1 ? abs(a[k]) : 1) ||
                          abs(a[k] - b[k]) <= last_decimal(a[k])))) ok = 0
                 if (!ok) { print "  shown:   " w[i]; print "  printed: " g[i]; bad = 1 }
             }
             exit bad
         }' "$1" "$2"
}

for page in tool tutorial schemes errors; do
    # one .cmds (a command a line) and one .want (@@ before each command's
    # output) per block of `$ ` lines
    awk -v dir="$d/blocks" -v page="$page" '
        /^```text$/ { inblk = 1; n++; next }
        inblk && /^```/ { inblk = 0; next }
        inblk && substr($0, 1, 2) == "$ " {
            base = dir "/" page "." n
            print substr($0, 3) > (base ".cmds"); print "@@" > (base ".want"); has[n] = 1; next }
        inblk && has[n] { print > (dir "/" page "." n ".want") }
    ' "$src/docs/$page.md"
done
# in page order: a session may use a file an earlier one wrote
for cmds in $(cd "$d/blocks" && ls ./*.cmds 2>/dev/null | sort -t. -k2,2 -k3,3n); do
    base=$d/blocks/${cmds#./}
    base=${base%.cmds}
    name=$(basename "$base")
    if [ "$can_cc" -eq 0 ] && grep -q '^cc ' "$base.cmds"; then
        echo "note: $name (compiles the tutorial's C program) skipped: cannot link build/libgarotor.a here"
        continue
    fi
    # each command's status is kept for the next one ("exit status $?")
    : >"$base.sh"
    while IFS= read -r c; do
        printf '__s=$?; echo @@; (exit $__s); { %s\n} 2>&1\n' "$c" >>"$base.sh"
    done <"$base.cmds"
    (cd "$w" && PATH="$w/bin:$PATH" sh "$base.sh") >"$base.got" 2>&1
    same "$base.want" "$base.got" >"$base.diff" || fail "the session in docs/${name%%.*}.md (block $(echo "$name" | cut -d. -f2)) prints differently now:
$(head -n 20 "$base.diff")"
done
ls "$d"/blocks/*.cmds >/dev/null 2>&1 || fail "no sessions found in the docs"

[ "$fails" -eq 0 ] && echo "docs_test: all passed"
exit $((fails > 0))
