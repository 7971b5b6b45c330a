# tests/tool_input_test.sh: the tool against hostile input and a hostile
# environment (issue 26): the reader (a NUL byte, a line past --max-line, a
# failed read, memory that runs out, all under a memory limit where the build
# allows one), standard output that cannot be written, every signal that ends
# the process while it writes, a picture whose samples were cut off, and the
# messages that name the fix. Sourced by tests/tool_test.sh, whose helpers
# and variables it uses: G (the tool), d (a scratch directory), fail,
# expect_error (which adds each message to $d/all_stderr, checked there
# against the error table of docs/tool.md).

# ---- memory limit -------------------------------------------------------------
# limited KB CMD...: CMD under `ulimit -v KB` (and a timeout), where the tool
# can run under one at all: not under a sanitizer (ASan reserves terabytes of
# address space) or valgrind; there `limited` is unavailable (status 77).
can_limit=0
(ulimit -v 100000 && "$G" --version >/dev/null 2>&1) 2>/dev/null && can_limit=1
[ "$can_limit" -eq 1 ] || echo "note: the tool cannot run under ulimit -v here (a sanitizer or valgrind): the memory-limited cases are skipped"
limited() {
    kb=$1
    shift
    [ "$can_limit" -eq 1 ] || return 77
    (ulimit -v "$kb" && exec timeout 20 "$@")
}
# the cases here write their own files: out* in $d, as expect_error checks
K3=$d/in.k3
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0.6 0.8\n2.5 1 1 0 0 0 1 0\n' >"$K3"

# ---- NUL bytes: an error naming line and column, never an early end ---------
printf '0 0 1 0 0 1\000junk\n' >"$d/nul"
expect_error "NUL byte in a line" "nul:1:12: NUL byte: not text" "$G" exp --in "$d/nul" --out "$d/out"
printf '\000\000\000\000' >"$d/nul0"
expect_error "input of NUL bytes only" "<stdin>:1:1: NUL byte" "$G" exp <"$d/nul0"
printf '0 0 0 0 0 0\n# a comment \000\n' >"$d/nulc"
expect_error "NUL byte in a skipped line" "nulc:2:13: NUL byte" "$G" exp --in "$d/nulc" --out "$d/out"
printf 'w\000x,wy\n0,0,0,0,0,0\n' >"$d/nulh"
expect_error "NUL byte in a --header line" "nulh:1:2: NUL byte" "$G" exp --header --in "$d/nulh" --out "$d/out"
printf '0.5\n1\000\n' >"$d/nult"
expect_error "NUL byte in --times" "nult:2:2: NUL byte" "$G" interp --format pose --in "$K3" --times "$d/nult" --out "$d/out"
printf '0 0 0 0 0 0\n0 0 0 0 0 0\n0 0 \000 0 0 0\n' >"$d/nulv"
expect_error "NUL byte in --velocities" "nulv:3:5: NUL byte" \
    "$G" interp --scheme lihao3 --format pose --in "$K3" --velocities "$d/nulv" --samples 3 --out "$d/out"

# ---- lines across reads (of 65536 bytes): split nowhere, counted right -----
# 12000 twists, each padded by 0 to 22 blanks: 7 distinct ones, 12000 lines out
awk 'BEGIN { for (i = 0; i < 12000; i++) { s = ""; for (j = 0; j < i % 23; j++) s = s " "
    print s "0, 0 ,0 0\t0 " (i % 7) } }' >"$d/many"
"$G" exp --in "$d/many" | sort | uniq -c | awk '{ print $1 }' | tr '\n' ' ' >"$d/counts"
[ "$(cat "$d/counts")" = "1715 1715 1714 1714 1714 1714 1714 " ] ||
    fail "12000 twists across reads: counts of the 7 motions $(cat "$d/counts")"
# comment lines of 99 bytes and a newline: the 656th spans byte 65536; then
# a line from byte 65500 with a NUL byte at column 50, past byte 65536
awk 'BEGIN { for (i = 0; i < 656; i++) { s = "#"; while (length(s) < 99) s = s "c"; print s } }' >"$d/span"
"$G" exp --max-line 99 --in "$d/span" >"$d/stdout" 2>"$d/stderr" && [ ! -s "$d/stdout" ] ||
    fail "--max-line 99: lines of 99 bytes across a read refused: $(cat "$d/stderr")"
head -n 655 "$d/span" >"$d/spannul"
printf '0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\000\n' >>"$d/spannul"
expect_error "a NUL byte past the first read" "spannul:656:50: NUL byte" "$G" exp --in "$d/spannul" --out "$d/out"

# ---- --max-line: a line of N bytes is read, of N + 1 an error ----------------
printf '0 0 0 0 0 0\n' >"$d/eleven"
"$G" exp --max-line 11 --in "$d/eleven" >"$d/ml.out" 2>"$d/err" && [ -s "$d/ml.out" ] ||
    fail "--max-line 11: a line of 11 bytes refused: $(cat "$d/err")"
expect_error "--max-line: one byte over" "eleven:1: line longer than 10 bytes (--max-line N reads longer ones)" \
    "$G" exp --max-line 10 --in "$d/eleven" --out "$d/out"
for v in 0 -1 1M 1.5 ''; do
    expect_error "--max-line $v" "garotor exp: --max-line needs a whole number of bytes >= 1, not: $v" \
        "$G" exp --max-line "$v" --in "$d/eleven" --out "$d/out"
done
# every command that reads, and every file interp reads, under the one limit
for c in "log" "versor exp" "versor log" "versor apply"; do
    # shellcheck disable=SC2086 # $c is one or two words
    expect_error "$c --max-line" "eleven:1: line longer than 8 bytes" "$G" $c --max-line 8 --in "$d/eleven" --out "$d/out"
done
expect_error "interp --max-line, keys" "in.k3:2: line longer than 17 bytes" \
    "$G" interp --format pose --max-line 17 --in "$K3" --samples 3 --out "$d/out"
printf '0.5\n1.00000000000000000000000\n' >"$d/longt"
expect_error "interp --max-line, --times" "longt:2: line longer than 20 bytes" \
    "$G" interp --format pose --max-line 20 --in "$K3" --times "$d/longt" --out "$d/out"
printf '0 0 0 0 0 0\n0 0 0 0 0 0.000000000000000\n0 0 0 0 0 0\n' >"$d/longv"
expect_error "interp --max-line, --velocities" "longv:2: line longer than 20 bytes" \
    "$G" interp --scheme lihao3 --format pose --max-line 20 --in "$K3" --velocities "$d/longv" --samples 3 --out "$d/out"

# ---- bounded memory: /dev/zero and an endless line fail fast in 16 MB --------
# (a getline reader grew to 24 GB on /dev/zero; the limit of 16 MB is for
# the whole process: the tool, its libraries, the 1 MiB line and a block)
if limited 16000 "$G" exp --in /dev/zero >"$d/stdout" 2>"$d/stderr"; then rc=0; else rc=$?; fi
if [ "$rc" -ne 77 ]; then
    [ "$rc" -eq 2 ] && grep -q "^garotor: /dev/zero:1:1: NUL byte" "$d/stderr" && [ ! -s "$d/stdout" ] ||
        fail "exp --in /dev/zero in 16 MB: status $rc, $(head -c 300 "$d/stderr")"
    cat "$d/stderr" >>"$d/all_stderr"
    tr '\000' 1 </dev/zero | limited 16000 "$G" exp >"$d/stdout" 2>"$d/stderr"
    [ ! -s "$d/stdout" ] && grep -q "^garotor: <stdin>:1: line longer than 1048576 bytes" "$d/stderr" ||
        fail "an endless line in 16 MB: $(head -c 300 "$d/stderr")"
else
    # no memory limit here: a finite stream, so that a reader that holds it
    # all still ends
    head -c 16777216 /dev/zero | "$G" exp 2>"$d/stderr" >"$d/stdout"
    grep -q "^garotor: <stdin>:1:1: NUL byte" "$d/stderr" && [ ! -s "$d/stdout" ] ||
        fail "16 MiB of NUL bytes: $(head -c 300 "$d/stderr")"
    head -c 16777216 /dev/zero | tr '\000' 1 | "$G" exp 2>"$d/stderr" >"$d/stdout"
    grep -q "^garotor: <stdin>:1: line longer than 1048576 bytes" "$d/stderr" && [ ! -s "$d/stdout" ] ||
        fail "a line of 16 MiB: $(head -c 300 "$d/stderr")"
fi

# ---- a huge line between two keys, under ulimit -v: an error, not the keys
# before it (a reader that took a failed allocation for the end of the input
# wrote the first key's motion and exited 0) ----
huge_input() { # a key, a line of 150 MB, a key
    echo '0 0 0 0 0 0'
    head -c 150000000 /dev/zero | tr '\000' 1
    printf '\n0 0 0 0 0 0\n'
}
if [ "$can_limit" -eq 1 ]; then
    huge_input | limited 100000 "$G" exp >"$d/stdout" 2>"$d/stderr"
    rc=$?
    [ "$rc" -eq 2 ] && [ ! -s "$d/stdout" ] && grep -q "^garotor: <stdin>:2: line longer than 1048576 bytes" "$d/stderr" ||
        fail "a 150 MB line between two keys (100 MB limit): status $rc, $(wc -l <"$d/stdout") lines out, $(head -c 300 "$d/stderr")"
    # the limit raised past the memory: out of memory, naming the line
    huge_input | limited 100000 "$G" exp --max-line 1000000000 >"$d/stdout" 2>"$d/stderr"
    rc=$?
    [ "$rc" -eq 2 ] && [ ! -s "$d/stdout" ] && grep -q "^garotor: <stdin>:2: out of memory$" "$d/stderr" ||
        fail "a 150 MB line with --max-line 1e9 (100 MB limit): status $rc, $(head -c 300 "$d/stderr")"
fi

# ---- standard output that cannot be written: status 2, for every command ----
if [ -w /dev/full ]; then
    printf '0 0 0 0 0 0\n' >"$d/tw"
    printf '0 0 0 0 0 0 0 0 0 0\n' >"$d/biv1"
    "$G" exp --in "$d/tw" >"$d/m1"
    "$G" versor exp --in "$d/biv1" >"$d/r1"
    printf '%s 1 2 3\n' "$(cat "$d/r1")" >"$d/vp1"
    for args in "" "demo" "--help" "--version" "demo --help" "exp --help" "log --help" "interp --help" \
        "versor --help" "exp --in $d/tw" "log --in $d/m1" "versor exp --in $d/biv1" "versor log --in $d/r1" \
        "versor apply --in $d/vp1" "interp --format pose --in $K3 --samples 3" \
        "interp --format pose --in $K3 --samples 3 --with velocity"; do
        # shellcheck disable=SC2086 # $args is several words
        "$G" $args >/dev/full 2>"$d/stderr"
        rc=$?
        cat "$d/stderr" >>"$d/all_stderr"
        [ "$rc" -eq 2 ] && [ "$(cat "$d/stderr")" = "garotor: <stdout>: write error" ] ||
            fail "garotor $args >/dev/full: status $rc, $(cat "$d/stderr")"
    done
    # the picture is not kept when the report or the samples were not written
    for args in "demo --svg $d/full.svg" "demo --html $d/full.svg" \
        "interp --format pose --in $K3 --samples 3 --svg $d/full.svg"; do
        # shellcheck disable=SC2086
        "$G" $args >/dev/full 2>"$d/stderr"
        rc=$?
        [ "$rc" -eq 2 ] && [ ! -e "$d/full.svg" ] || fail "garotor $args >/dev/full: status $rc, picture left: $(ls "$d"/full.svg* 2>&1)"
    done
fi
# a closed standard output is no success either
"$G" --version >&- 2>"$d/stderr"
rc=$?
[ "$rc" -eq 2 ] && grep -q "<stdout>: write error" "$d/stderr" || fail "garotor --version >&-: status $rc"

# ---- --svg and `| head`: samples cut off, so no picture ----------------------
# 20000 samples (3 MB) fill the pipe long after head has left: the tool dies
# of SIGPIPE while it writes them, and the picture, drawn first, is removed
env --default-signal=PIPE "$G" interp --format pose --samples 20000 --in "$K3" --svg "$d/head.svg" |
    head -n 1 >"$d/head.out"
[ "$(wc -l <"$d/head.out")" -eq 1 ] || fail "| head: not one line"
ls "$d"/head.svg* >/dev/null 2>&1 && fail "--svg | head -1 left a picture: $(ls "$d"/head.svg*)"
# with SIGPIPE ignored: a write error, status 2, no picture (nor page)
{
    env --ignore-signal=PIPE "$G" interp --format pose --samples 20000 --in "$K3" --svg "$d/head.svg" \
        --html "$d/head.html" 2>"$d/stderr"
    echo $? >"$d/rc"
} | head -n 1 >/dev/null
[ "$(cat "$d/rc")" -eq 2 ] && grep -q "<stdout>: write error" "$d/stderr" ||
    fail "--svg | head -1, SIGPIPE ignored: status $(cat "$d/rc"), $(cat "$d/stderr")"
ls "$d"/head.svg* "$d"/head.html* >/dev/null 2>&1 && fail "--svg | head -1, SIGPIPE ignored, left $(ls "$d"/head.*)"
# the same run to the end still keeps both
"$G" interp --format pose --samples 20000 --in "$K3" --svg "$d/head.svg" --html "$d/head.html" >/dev/null &&
    [ -s "$d/head.svg" ] && [ -s "$d/head.html" ] || fail "--svg, --html with every sample written: no picture"

# ---- every signal that ends the process removes the temporaries -------------
# The run is stopped where it cannot finish: --out is being written (its
# temporary exists) when the picture is opened, a FIFO no one reads, so
# open() blocks. Then each signal: the run dies of it (status 128 + the
# signal), and neither the temporary nor the output is left. env resets the
# signals a background job starts with ignored (SIGINT, SIGQUIT) to their
# default. A sanitizer handles SIGSEGV, SIGBUS and SIGFPE itself (the tool
# leaves a handled signal alone): those three only where it is not there.
# valgrind (TOOL_WRAPPER) keeps SIGSYS, SIGTRAP, SIGILL and SIGRTMAX (sent
# by kill, they do not reach the tool): not under it.
sigs="HUP INT QUIT TERM ALRM USR1 USR2 PIPE XCPU XFSZ VTALRM PROF IO ABRT PWR RTMIN"
[ -n "${TOOL_WRAPPER:-}" ] || sigs="$sigs SYS TRAP ILL RTMAX"
[ "$can_limit" -eq 1 ] && sigs="$sigs SEGV BUS FPE"
# alive PID: the process runs (not a zombie); without /proc, until waited for
alive() {
    if [ -r "/proc/$1/stat" ]; then
        [ "$(sed 's/.*) \(.\).*/\1/' "/proc/$1/stat")" != Z ]
    else
        kill -0 "$1" 2>/dev/null
    fi
}
mkfifo "$d/sig.fifo"
for sig in $sigs; do
    rm -f "$d"/sig.out*
    (ulimit -c 0 && exec env --default-signal "$G" interp --format pose --in "$K3" --samples 3 \
        --out "$d/sig.out" --svg "$d/sig.fifo") 2>/dev/null &
    pid=$!
    i=0
    while [ $i -lt 600 ] && alive $pid && ! ls "$d"/sig.out.tmp* >/dev/null 2>&1; do
        sleep 0.05
        i=$((i + 1))
    done
    ls "$d"/sig.out.tmp* >/dev/null 2>&1 || fail "SIG$sig: the run never opened its output"
    kill -s "$sig" $pid
    # at most 20 s to die of it (a run that does not is killed, and fails)
    i=0
    while [ $i -lt 400 ] && alive $pid; do
        sleep 0.05
        i=$((i + 1))
    done
    alive $pid && kill -s KILL $pid
    wait $pid 2>/dev/null # not the shell's word for the signal
    rc=$?
    [ "$rc" -gt 128 ] && [ "$(kill -l $((rc - 128)))" = "$sig" ] || fail "SIG$sig: status $rc, not killed by it"
    ls "$d"/sig.out* >/dev/null 2>&1 && fail "killed by SIG$sig, the run left $(ls "$d"/sig.out*)"
done
rm -f "$d/sig.fifo"

# ---- messages that name the fix ---------------------------------------------
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n' >"$d/pose2"
expect_error "a pose file without --format pose" \
    "pose2:1: expected 17 numbers (t, then a 4x4 matrix), found 8: is this a pose file? pass --format pose" \
    "$G" interp --samples 3 --in "$d/pose2" --out "$d/out"
printf '0 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n1 1 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1\n' >"$d/mat2"
expect_error "a matrix file with --format pose" \
    "mat2:1: expected 8 numbers (t, then x y z qx qy qz qw), found 17: is this a file of 4x4 matrices? drop --format pose" \
    "$G" interp --format pose --samples 3 --in "$d/mat2" --out "$d/out"
cut -d' ' -f2- "$d/mat2" >"$d/mat2nt"
expect_error "keys without their times" \
    "mat2nt:1: expected 17 numbers (t, then a 4x4 matrix), found 16: is t missing? a key is its time, then the pose" \
    "$G" interp --samples 3 --in "$d/mat2nt" --out "$d/out"
cut -d' ' -f2- "$d/pose2" >"$d/pose2nt"
expect_error "poses without their times" "pose2nt:1: expected 8 numbers (t, then x y z qx qy qz qw), found 7: is t missing?" \
    "$G" interp --format pose --samples 3 --in "$d/pose2nt" --out "$d/out"
expect_error "affine: 8 numbers, no pose hint" "pose2:1: expected 17 numbers (t, then a 4x4 matrix), found 8$" \
    "$G" interp --group affine --samples 3 --in "$d/pose2" --out "$d/out"
printf 'time,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n' >"$d/hdr.csv"
expect_error "a CSV header without --header" "hdr.csv:1: 'time' is not a number: is this a header line? pass --header" \
    "$G" interp --format pose --samples 3 --in "$d/hdr.csv" --out "$d/out"
printf '0.5\ntime\n' >"$d/hdrt"
printf '0 0 x 0 0 0\n' >"$d/word1"
expect_error "a word on line 1 after a number: no --header hint" "word1:1: 'x' is not a number$" \
    "$G" exp --in "$d/word1" --out "$d/out"
expect_error "a word in --times: no --header hint" "hdrt:2: 'time' is not a number$" \
    "$G" interp --format pose --in "$K3" --times "$d/hdrt" --out "$d/out"
printf 'time\n0.5\n' >"$d/hdrt1"
expect_error "a --times header: no --header hint (it applies to --in)" "hdrt1:1: 'time' is not a number$" \
    "$G" interp --format pose --in "$K3" --times "$d/hdrt1" --out "$d/out"
expect_error "a matrix given to exp" "m1:1: expected 6 numbers (a twist), found 16: is this a matrix? garotor log reads those" \
    "$G" exp --in "$d/m1" --out "$d/out"
expect_error "a twist given to log" "tw:1: expected 16 numbers (a 4x4 matrix), found 6: is this a twist? garotor exp reads those" \
    "$G" log --in "$d/tw" --out "$d/out"
expect_error "a file without --in" "garotor exp: unknown option: $d/tw: a file to read? pass --in $d/tw" \
    "$G" exp "$d/tw" --out "$d/out"
expect_error "a word without --in" "garotor interp: unknown option: keys.txt: a file to read? pass --in keys.txt" \
    "$G" interp --samples 3 keys.txt
expect_error "a stray word beside --in" "garotor exp: unknown option: extra$" "$G" exp --in "$d/tw" extra
expect_error "--verison" "garotor: unknown option: --verison: did you mean --version?" "$G" --verison
expect_error "--hepl" "garotor exp: unknown option: --hepl: did you mean --help?" "$G" exp --hepl
expect_error "--sample" "garotor interp: unknown option: --sample: did you mean --samples?" \
    "$G" interp --sample 3 --in "$K3"
expect_error "--fromat" "garotor interp: unknown option: --fromat=pose: did you mean --format?" \
    "$G" interp --fromat=pose --samples 3 --in "$K3"
expect_error "--ot: two as near" "unknown option: --ot: did you mean --out or --at?" "$G" interp --ot x
expect_error "--norm: the start of one" "unknown option: --norm: did you mean --normalize?" "$G" interp --norm
expect_error "--in to the demo" "garotor: unknown option: --in: an option of garotor exp, log, interp, versor and object: name the command first" \
    "$G" --in "$d/tw"
expect_error "--samples to exp" "garotor exp: unknown option: --samples: an option of garotor interp, not of exp" \
    "$G" exp --samples 3
expect_error "intrep" "garotor: unknown command 'intrep': did you mean interp?" "$G" intrep
expect_error "a file for a command" "garotor: unknown command '$d/tw': a file to read? name the command first: garotor COMMAND --in $d/tw" \
    "$G" "$d/tw"
