#!/bin/sh
# The docs against the tool.
#  1. `garotor --help` and `garotor CMD --help` must print exactly the block
#     that follows "$ garotor ... --help" in docs/tool.md.
#  2. Every shell session shown in a ```text block of docs/*.md ("$ command"
#     lines, each followed by what it printed) is run again, from a scratch
#     directory laid out like the repository (build/garotor, docs/, include/,
#     and `garotor` on the PATH), and must print exactly what is shown,
#     character for character, numbers included. The only lines that may
#     differ are the ones named in the list of exceptions below, each with
#     its reason; it is empty now. The tutorial's C programs are written out
#     from its ```c blocks, each to the file its first line names
#     ("/* point.c: ..."), for its sessions to compile; the other pages'
#     sessions compile the programs of docs/examples/ (conformal.md's, say)
#     as they show it. If a program cannot be linked here (a sanitizer build),
#     the blocks that compile one ("cc ...") are skipped with a note.
# The digits shown are those of the default build, and these print the same
# digits: gcc or clang, -O0 to -O3, the sanitizer build, and glibc's maths
# functions on or off their FMA code paths (GLIBC_TUNABLES=glibc.cpu.hwcaps=
# -AVX2,-FMA), all measured on x86-64. A build whose compiler fuses
# multiply-adds into FMA instructions (clang -march=native) prints other last
# digits in 16 lines of docs/tutorial.md and fails here: that is not an
# exception but another build, which docs/tool.md ("Numbers out") describes.
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
for c in "" demo exp log interp versor object eval fit; do
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
ln -s "$G" "$w/bin/garotor"
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

# ---- the exceptions -----------------------------------------------------------
# except PAGE COMMAND LINE WHY: in docs/PAGE, the output of each command that
# contains the text COMMAND, on its shown lines that match the extended regular
# expression LINE, may differ from what is printed in its numbers (the words
# still must not), because WHY; the doc says so next to the block. An exception
# that no shown line matches any more is a failure. Prefer output that is the
# same on every machine (a shell test rather than a message of ls, say) to an
# exception here.
: >"$d/exceptions"
# shellcheck disable=SC2317 # called by the lines of the list, when there are any
except() { printf '%s\t%s\t%s\t%s\n' "$@" >>"$d/exceptions"; }
# (none: no session shown in docs/ prints a timing or anything else that varies
# from run to run, and the builds named at the top of this file all print the
# same digits)

# same PAGE BASE: BASE.want (the shown output, "@@" before each command's)
# against BASE.got (the printed one), line by line and character for
# character, but for the lines an exception covers; prints the shown and
# printed lines that differ, under their command, and adds "used N" to
# $d/used for each exception (by its line in $d/exceptions) that names a
# shown line
same() {
    awk -v page="$1" -v used="$d/used" '
        function masked(s) { gsub(/[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?/, "#", s); return s }
        FILENAME == ARGV[1] { split($0, f, "\t"); if (f[1] == page) { ne++; en[ne] = FNR; ec[ne] = f[2]; el[ne] = f[3] } next }
        FILENAME == ARGV[2] { cmd[++nc] = $0; next }
        FILENAME == ARGV[3] { w[++nw] = $0; next }
        { g[++ng] = $0 }
        END {
            k = 0
            for (i = 1; i <= nw; i++) {
                if (w[i] == "@@") { k++; continue }
                covered[i] = 0
                for (j = 1; j <= ne; j++)
                    if (index(cmd[k], ec[j]) && w[i] ~ el[j]) { covered[i] = 1; print "used " en[j] >>used }
            }
            if (nw != ng) { print "  " nw - nc " lines shown, " ng - nc " printed"; bad = 1 }
            k = 0
            for (i = 1; i <= nw && i <= ng; i++) {
                if (w[i] == "@@") k++
                if (w[i] == g[i] || covered[i] && masked(w[i]) == masked(g[i])) continue
                if (k != shown) { print "  $ " cmd[k]; shown = k }
                print "  shown:   " w[i]; print "  printed: " g[i]
                if (masked(w[i]) == masked(g[i])) numbers++; else words++
                bad = 1
            }
            if (numbers && !words)
                print "  (only numbers differ: show what the tool prints now; or, if this build fuses multiply-adds, see the top of tests/docs_test.sh)"
            exit bad
        }' "$d/exceptions" "$2.cmds" "$2.want" "$2.got"
}

# one .cmds (a command a line) and one .want (@@ before each command's output)
# per block of `$ ` lines, named PAGE.N (the Nth ```text block of PAGE.md)
awk -v dir="$d/blocks" '
    FNR == 1 { page = FILENAME; sub(/.*\//, "", page); sub(/[.]md$/, "", page); n = 0; inblk = 0 }
    /^```text$/ { inblk = 1; n++; has = 0; next }
    inblk && /^```/ { inblk = 0; close(base ".cmds"); close(base ".want"); next }
    inblk && substr($0, 1, 2) == "$ " {
        base = dir "/" page "." n
        print substr($0, 3) > (base ".cmds"); print "@@" > (base ".want"); has = 1; next }
    inblk && has { print > (base ".want") }
' "$src"/docs/*.md
# in page order: a session may use a file an earlier one wrote
: >"$d/used"
for cmds in $(cd "$d/blocks" && ls ./*.cmds 2>/dev/null | sort -t. -k2,2 -k3,3n); do
    base=$d/blocks/${cmds#./}
    base=${base%.cmds}
    name=$(basename "$base")
    if [ "$can_cc" -eq 0 ] && grep -q '^cc ' "$base.cmds"; then
        echo "note: $name (compiles a C program) skipped: cannot link build/libgarotor.a here"
        : >"$base.got"
        same "${name%%.*}.md" "$base" >/dev/null
        continue
    fi
    # each command's status is kept for the next one ("exit status $?")
    echo '__st() { return "$1"; }' >"$base.sh"
    while IFS= read -r c; do
        printf '__s=$?; echo @@; __st $__s; { %s\n} 2>&1\n' "$c" >>"$base.sh"
    done <"$base.cmds"
    (cd "$w" && PATH="$w/bin:$PATH" sh "$base.sh") >"$base.got" 2>&1
    same "${name%%.*}.md" "$base" >"$base.diff" ||
        fail "the session in docs/${name%%.*}.md (block $(echo "$name" | cut -d. -f2)) prints differently now:
$(head -n 20 "$base.diff")"
done
n=0
while IFS= read -r e; do
    n=$((n + 1))
    grep -qx "used $n" "$d/used" ||
        fail "an exception names no shown line any more (page, command, lines, why): $e"
done <"$d/exceptions"
ls "$d"/blocks/*.cmds >/dev/null 2>&1 || fail "no sessions found in the docs"

[ "$fails" -eq 0 ] && echo "docs_test: all passed"
exit $((fails > 0))
