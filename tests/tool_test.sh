#!/bin/sh
# The garotor tool from outside: round trips through files, pictures, and
# every error case of docs/tool.md: exit status 2, a message naming the file
# and line, and no output file left behind. At the end, every message of the
# error table in docs/tool.md must have been produced by one of the cases.
set -u
G=$1
doc=$(cd "$(dirname "$0")/../docs" && pwd)/tool.md
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
# TOOL_WRAPPER (the soak suite: valgrind and its options) runs every call of
# the tool under that command, through a wrapper script standing in for it.
if [ -n "${TOOL_WRAPPER:-}" ]; then
    printf '#!/bin/sh\nexec %s "%s" "$@"\n' "$TOOL_WRAPPER" "$(cd "$(dirname "$G")" && pwd)/$(basename "$G")" >"$d/wrapped-tool"
    chmod +x "$d/wrapped-tool"
    G=$d/wrapped-tool
fi
fails=0
pass() { :; }
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# expect_error NAME PATTERN CMD...: exit 2, stderr matches PATTERN, no $d/out*
expect_error() {
    name=$1 pattern=$2
    shift 2
    rm -f "$d"/out*
    "$@" >"$d/stdout" 2>"$d/stderr"
    rc=$?
    cat "$d/stderr" >>"$d/all_stderr"
    [ "$rc" -eq 2 ] || fail "$name: exit status $rc, want 2"
    grep -q -- "$pattern" "$d/stderr" || fail "$name: message '$(cat "$d/stderr")' lacks '$pattern'"
    [ -s "$d/stdout" ] && fail "$name: wrote to standard output"
    ls "$d"/out* >/dev/null 2>&1 && fail "$name: left an output file: $(ls "$d"/out*)"
}

# ---- round trips through files: twists -> exp -> log -> the same twists ----
cat >"$d/twists" <<'T'
# wx wy wz vx vy vz
0 0 0 0 0 0
0 0 0 1e-12 0 0
0 0 0 1e6 -2e6 3
0.3 -0.2 0.9 1 2 3
1e-9 0 0 1000 0 0
0 0 3.141592653589793 0 0 1
1.2,0.4,-0.7,0.5,-3,2
T
for group in cga matrix; do
    "$G" exp --group "$group" --in "$d/twists" --out "$d/m.$group" || fail "exp --group $group"
    "$G" log --group "$group" --in "$d/m.$group" --out "$d/t.$group" || fail "log --group $group"
    # compare with the input: |difference| <= 1e-13 * max(1, |v|)
    grep -v '^#' "$d/twists" | tr ',' ' ' | paste -d ' ' - "$d/t.$group" | awk -v g="$group" '
        { s = 1; for (i = 4; i <= 6; i++) if ($i > s || -$i > s) s = ($i > 0 ? $i : -$i)
          for (i = 1; i <= 6; i++) { e = $i - $(i + 6); if (e < 0) e = -e
            if (e > 1e-13 * s) { printf "round trip %s line %d: %g\n", g, NR, e; bad = 1 } } }
        END { exit bad }' || fail "exp/log round trip, group $group"
done
# --group cga and --group matrix: the same numbers to 1e-13 relative to
# max(1, the line's largest entry), for exp and for log
same_numbers() { # same_numbers WHAT FILE1 FILE2
    awk -v what="$1" '
        NR == FNR { for (i = 1; i <= NF; i++) a[FNR, i] = $i; next }
        { s = 1; for (i = 1; i <= NF; i++) { x = $i < 0 ? -$i : $i; if (x > s) s = x }
          for (i = 1; i <= NF; i++) { e = a[FNR, i] - $i; if (e < 0) e = -e
            if (e > 1e-13 * s) { printf "%s: cga and matrix differ by %g on line %d\n", what, e, FNR; bad = 1 } } }
        END { exit bad }' "$2" "$3" || fail "$1: cga and matrix agree to 1e-13"
}
same_numbers exp "$d/m.cga" "$d/m.matrix"
same_numbers log "$d/t.cga" "$d/t.matrix"
# a rotation angle beyond ~1e154, whose square overflows: both groups answer
# with the same rotation, exact for the double angle (cga said "outside the
# domain"; matrix wrote cos th I + sin th [n]x, no rotation, or failed)
printf '1e300 0 0 0 0 0\n3e200 -4e200 1e200 1 2 3\n0 0 1e155 5 -7 1e3\n1e155 1e155 0 0 0 1\n1.7e308 1.7e308 0 0 0 0\n' >"$d/hugeangle"
for group in cga matrix; do
    "$G" exp --group "$group" --in "$d/hugeangle" --out "$d/ha.$group" || fail "exp --group $group of a huge angle"
    "$G" log --group "$group" --in "$d/ha.$group" --out "$d/hal.$group" || fail "exp --group $group of a huge angle: not rigid"
done
same_numbers "exp of a huge angle" "$d/ha.cga" "$d/ha.matrix"
[ "$(wc -l <"$d/m.cga")" -eq 7 ] || fail "exp writes one line per twist"

# affine: exp of a general generator, log back
printf '0.1 0.2 0 1\n0 -0.3 0.1 2\n0.05 0 0.2 3\n0 0 0 0\n' | tr '\n' ' ' >"$d/affine"
echo >>"$d/affine"
"$G" exp --group affine --in "$d/affine" --out "$d/am" || fail "exp --group affine"
"$G" log --group affine --in "$d/am" --out "$d/al" || fail "log --group affine"
paste -d ' ' "$d/affine" "$d/al" | awk '{ for (i = 1; i <= 16; i++) { e = $i - $(i + 16)
    if (e < 0) e = -e; if (e > 1e-13) bad = 1 } } END { exit bad }' || fail "affine round trip"

# CSV with a header, as a spreadsheet exports it
printf 'wx,wy,wz,vx,vy,vz\n0,0,1.5,1,0,0\n' >"$d/csv"
"$G" exp --header --in "$d/csv" >/dev/null || fail "exp --header reads CSV"

# ---- interp: keys in both formats -----------------------------------------
cat >"$d/keys" <<'K'
0  0 0 0  0 0 0 1
1  1 0 0  0 0 0.7071067811865476 0.7071067811865476
3  2 1 0  0 0 1 0
K
for s in screw bivector quadratic smooth lihao2 lihao3 c2; do
    for group in cga matrix; do
        "$G" interp --scheme "$s" --group "$group" --format pose --samples 7 --in "$d/keys" \
            --out "$d/s.$s.$group" || fail "interp $s $group"
    done
    [ "$(wc -l <"$d/s.$s.cga")" -eq 7 ] || fail "interp $s writes 7 samples"
    # docs/tool.md: cga and matrix must agree (the quaternion's sign is free)
    paste -d ' ' "$d/s.$s.cga" "$d/s.$s.matrix" | awk -v s="$s" '
        { e = 0; for (i = 1; i <= 4; i++) { x = $i - $(i + 8); if (x < 0) x = -x; if (x > e) e = x }
          p = 0; m = 0; for (i = 5; i <= 8; i++) { x = $i - $(i + 8); y = $i + $(i + 8)
              if (x < 0) x = -x; if (y < 0) y = -y; if (x > p) p = x; if (y > m) m = y }
          if (m < p) p = m; if (p > e) e = p
          if (e > 1e-12) { printf "interp %s: cga and matrix differ by %g on line %d\n", s, e, NR; bad = 1 } }
        END { exit bad }' || fail "interp $s: cga and matrix agree"
done

# ---- the growth rule of lihao2 (docs/schemes.md, "lihao2: growth") on a
# TUM-like file (tests/tum_like.awk, seeded): lihao2 gets a warning naming
# two consecutive keys by their times as written and their lines, and
# writes its samples (exit 0); lihao3 and c2 on the same file no warning ----
awk -v n=300 -v seed=7 -f "$(dirname "$0")/tum_like.awk" >"$d/tum300"
[ "$(wc -l <"$d/tum300")" -eq 300 ] || fail "tum_like.awk: not 300 keys"
"$G" interp --format pose --normalize --scheme lihao2 --samples 50 --in "$d/tum300" >"$d/g.out" 2>"$d/g.err" ||
    fail "lihao2 growth: exit status $? (a warning must not fail the run)"
[ "$(wc -l <"$d/g.out")" -eq 50 ] || fail "lihao2 growth: samples not written"
sed -n 's/.*on the segment t = \([0-9.]*\) to \([0-9.]*\) (lines \([0-9]*\) to \([0-9]*\)).*/\1 \2 \3 \4/p' "$d/g.err" >"$d/g.seg"
grep -q "warning: .*tum300: the lihao2 path's velocity grows past 3 times the fastest chord" "$d/g.err" &&
    [ -s "$d/g.seg" ] || fail "lihao2 growth: no warning: $(cat "$d/g.err")"
read -r ta tb la lb <"$d/g.seg" || :
# the segment's keys: lines la and la + 1 of the file, stamped as written
[ "$lb" = $((la + 1)) ] && [ "$(sed -n "${la}p" "$d/tum300" | cut -d ' ' -f 1)" = "$ta" ] &&
    [ "$(sed -n "${lb}p" "$d/tum300" | cut -d ' ' -f 1)" = "$tb" ] || fail "lihao2 growth: the segment named is not two keys: $(cat "$d/g.seg")"
for s in lihao3 c2; do
    "$G" interp --format pose --normalize --scheme "$s" --samples 50 --in "$d/tum300" >"$d/g.out" 2>"$d/g.err" ||
        fail "$s on the TUM-like file: $(cat "$d/g.err")"
    [ -s "$d/g.err" ] && fail "$s on the TUM-like file: a warning: $(cat "$d/g.err")"
done

# ---- the error table ------------------------------------------------------
printf '0 0 0 0 0\n' >"$d/short"
expect_error "exp: wrong count" "short:1: expected 6 numbers" "$G" exp --in "$d/short" --out "$d/out"
printf '0 0 0 0 0 0\n0 0 x 0 0 0\n' >"$d/word"
expect_error "exp: not a number" "word:2: 'x' is not a number" "$G" exp --in "$d/word" --out "$d/out"
# an empty CSV field is an error, not skipped: 1,,2,3,4,5,6 must not read as
# six numbers with the 2 in the second column
printf '0,0,0,0,0,0\n1,,2,3,4,5,6\n' >"$d/empty"
expect_error "exp: empty field" "empty:2: empty field after number 1" "$G" exp --in "$d/empty" --out "$d/out"
printf ' , 0,0,0,0,0,0\n' >"$d/empty0"
expect_error "exp: leading comma" "empty0:1: empty field before number 1" "$G" exp --in "$d/empty0" --out "$d/out"
printf '0, 0, 0, 0, 0, 0 ,\r\n' >"$d/empty6"
expect_error "exp: trailing comma" "empty6:1: empty field after number 6" "$G" exp --in "$d/empty6" --out "$d/out"
printf '0 , 0,\t0 ,0\t0 0\r\n' >"$d/seps"
"$G" exp --in "$d/seps" >/dev/null || fail "one comma with blanks around it, or blanks alone, separate numbers"
printf '0 0 0 0 0 0\n\n# c\n0 0 nan 0 0 0\n' >"$d/nan"
expect_error "exp: NaN" "nan:4: number 3 is not finite" "$G" exp --in "$d/nan" --out "$d/out"
printf '0 0 0 inf 0 0\n' >"$d/inf"
expect_error "exp: Inf" "inf:1: number 4 is not finite" "$G" exp --in "$d/inf" --out "$d/out"
printf '1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n1 0 0 0 0 1 0 0 0 0 2 0 0 0 0 1\n' >"$d/scaled"
expect_error "log: not orthonormal" "scaled:2: not a rigid motion" "$G" log --in "$d/scaled" --out "$d/out"
expect_error "log matrix: not orthonormal" "scaled:2: not a rigid motion" "$G" log --group matrix --in "$d/scaled" --out "$d/out"
printf '1 0 0 0 0 1 0 0 0 0 1 0 0 0 1 1\n' >"$d/lastrow"
expect_error "log: last row" "lastrow:1: .*last row" "$G" log --in "$d/lastrow" --out "$d/out"
printf -- '-1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n' >"$d/reflect"
expect_error "log: reflection" "reflect:1: .*reflection" "$G" log --in "$d/reflect" --out "$d/out"
expect_error "log affine: det < 0" "reflect:1: .*determinant" "$G" log --group affine --in "$d/reflect" --out "$d/out"
printf -- '-1 0 0 0 0 -2 0 0 0 0 1 0 0 0 0 1\n' >"$d/negeig"
expect_error "log affine: no real log" "negeig:1:" "$G" log --group affine --in "$d/negeig" --out "$d/out"
printf '0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1\n' >"$d/agen"
expect_error "exp affine: last row" "agen:1: .*last row" "$G" exp --group affine --in "$d/agen" --out "$d/out"
expect_error "exp: missing file" "nofile: cannot open" "$G" exp --in "$d/nofile" --out "$d/out"
expect_error "unknown group" "--group must be" "$G" exp --group quat --in "$d/twists" --out "$d/out"
expect_error "unknown option" "unknown option" "$G" exp --frobnicate
expect_error "unknown command" "unknown command" "$G" frobnicate

printf '0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n' >"$d/same_t"
expect_error "interp: times not increasing" "same_t:3: key times must increase" \
    "$G" interp --format pose --samples 3 --in "$d/same_t" --out "$d/out"
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n' >"$d/two"
# ---- real pose files: --normalize, a byte-order mark, one key, --with ----
printf '\357\273\2770 0 0 0 0 0 0 1\n1 1 0 0 0 0 0.7071 0.7071\n2 1 1 0 0 0 1 0.0001\n' >"$d/tum"
expect_error "interp: 4-decimal quaternion" "tum:2: .*--normalize accepts up to 1e-3" \
    "$G" interp --format pose --in "$d/tum" --samples 3 --out "$d/out"
"$G" interp --format pose --normalize --in "$d/tum" --samples 3 --out "$d/tum.out" 2>"$d/err" ||
    fail "interp --normalize: $(cat "$d/err")"
# keys hit: the normalised quaternion of line 2 (0.7071/|q|) at t = 1
awk 'NR == 2 { q = 0.7071 / sqrt(2 * 0.7071 * 0.7071); e = $7 - q; if (e < 0) e = -e
     if ($1 != 1 || e > 1e-15 || $2 != 1 && ($2 - 1 > 1e-15 || 1 - $2 > 1e-15)) exit 1 }' "$d/tum.out" ||
    fail "interp --normalize: the key at t = 1 is not the normalised key: $(sed -n 2p "$d/tum.out")"
printf '0 0 0 0 0 0 0 1.01\n' >"$d/far"
expect_error "interp: --normalize, too far" "far:1: .*farther from 1 than --normalize accepts" \
    "$G" interp --format pose --normalize --in "$d/far" --samples 2 --out "$d/out"
# a matrix 1e-6 off a rotation: refused naming --normalize, accepted with it
printf '0 1.000001 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n1 1 0 0 1  0 1 0 0  0 0 1 0  0 0 0 1\n' >"$d/matoff"
expect_error "interp: matrix 1e-6 off" "matoff:1: not a rigid motion to 1e-9 .*--normalize" \
    "$G" interp --in "$d/matoff" --samples 2 --out "$d/out"
"$G" interp --normalize --group matrix --in "$d/matoff" --samples 2 --out "$d/matoff.out" 2>"$d/err" ||
    fail "interp --normalize (matrix): $(cat "$d/err")"
awk 'NR == 1 && ($2 != 1 || $3 != 0) { exit 1 }' "$d/matoff.out" || fail "--normalize: not projected: $(head -1 "$d/matoff.out")"
expect_error "interp: --normalize on affine" "--normalize applies to --group cga or matrix" \
    "$G" interp --group affine --normalize --in "$d/matoff" --samples 2 --out "$d/out"
# one key: the constant path, velocity and acceleration zero
printf '5 1 2 3 0 0 0 1\n' | "$G" interp --format pose --samples 2 --with velocity,acceleration >"$d/one" 2>"$d/err" ||
    fail "interp one key: $(cat "$d/err")"
[ "$(cat "$d/one")" = "5 1 2 3 0 0 0 1 0 0 0 0 0 0 0 0 0 0 0 0
5 1 2 3 0 0 0 1 0 0 0 0 0 0 0 0 0 0 0 0" ] || fail "interp one key: $(cat "$d/one")"
# --with: 8 + 6 + 6 numbers a line in pose format; 17 + 16 on affine with velocity
"$G" interp --format pose --normalize --scheme lihao3 --in "$d/tum" --samples 5 --with velocity,acceleration --frame spatial |
    awk 'NF != 20 { exit 1 }' || fail "--with velocity,acceleration: not 20 numbers a line"
printf '0 1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n1 2 0 0 1  0 1 0 0  0 0 1 0  0 0 0 1\n' |
    "$G" interp --group affine --samples 3 --with velocity | awk 'NF != 33 { exit 1 }' ||
    fail "--with velocity on affine: not 33 numbers a line"
expect_error "interp: --with" "--with must list velocity, acceleration or jerk (each once, joined by commas), not 'acc'" \
    "$G" interp --in "$d/tum" --normalize --format pose --samples 2 --with acc --out "$d/out"
expect_error "interp: --with twice" "not 'velocity,jerk,velocity'" \
    "$G" interp --in "$d/tum" --normalize --format pose --samples 2 --with velocity,jerk,velocity --out "$d/out"
expect_error "interp: --frame" "--frame must be body, spatial or world, not 'up'" \
    "$G" interp --in "$d/tum" --normalize --format pose --samples 2 --with velocity --frame up --out "$d/out"
printf '0 1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n1 2 0 0 1  0 1 0 0  0 0 1 0  0 0 0 1\n' >"$d/aff2"
expect_error "interp: --frame world on affine" "--frame world needs a rigid group" \
    "$G" interp --group affine --in "$d/aff2" --samples 2 --with velocity --frame world --out "$d/out"
# --with any of the three, in the order velocity, acceleration, jerk: each
# column the same as when all three are asked (only what is asked is computed)
for fr in body spatial world; do
    "$G" interp --format pose --normalize --scheme c2 --in "$d/tum" --samples 7 --frame $fr \
        --with velocity,acceleration,jerk >"$d/vaj" || fail "--with velocity,acceleration,jerk --frame $fr"
    "$G" interp --format pose --normalize --scheme c2 --in "$d/tum" --samples 7 --frame $fr \
        --with jerk,velocity >"$d/jv" || fail "--with jerk,velocity --frame $fr"
    "$G" interp --format pose --normalize --scheme c2 --in "$d/tum" --samples 7 --frame $fr \
        --with acceleration >"$d/a" || fail "--with acceleration --frame $fr"
    [ "$(cut -d' ' -f1-14,21-26 "$d/vaj")" = "$(cat "$d/jv")" ] || fail "--with jerk,velocity --frame $fr: columns"
    [ "$(cut -d' ' -f1-8,15-20 "$d/vaj")" = "$(cat "$d/a")" ] || fail "--with acceleration --frame $fr: columns"
done
expect_error "interp: --frame alone" "--frame applies only with --with" \
    "$G" interp --in "$d/tum" --normalize --format pose --samples 2 --frame spatial --out "$d/out"
# ---- timing: --rate, --times, --extrapolate ----
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0.6 0.8\n2.5 1 1 0 0 0 1 0\n' >"$d/k3"
[ "$("$G" interp --format pose --in "$d/k3" --rate 2 | awk '{ printf "%s ", $1 }')" = "0 0.5 1 1.5 2 2.5 " ] ||
    fail "--rate 2: times"
[ "$("$G" interp --format pose --in "$d/k3" --rate 3 | awk 'END { print NR, $1 }')" = "8 2.3333333333333335" ] ||
    fail "--rate 3: 8 samples up to 7/3"
printf -- '-1\n3\n# a comment\n1\n' >"$d/tt"
expect_error "interp: --times outside" "--times time -1 is outside the keys' range \\[0, 2.5\\] (see --extrapolate)" \
    "$G" interp --format pose --in "$d/k3" --times "$d/tt" --out "$d/out"
"$G" interp --format pose --in "$d/k3" --times "$d/tt" --extrapolate hold --with velocity >"$d/hold" ||
    fail "--extrapolate hold"
[ "$(sed -n 1p "$d/hold")" = "-1 0 0 0 0 0 0 1 0 0 0 0 0 0" ] || fail "--extrapolate hold: $(sed -n 1p "$d/hold")"
[ "$(sed -n 3p "$d/hold")" = "1 1 0 0 0 0 0.6 0.8 0 0 1.2363936240021496 0.6181968120010748 -0.46364760900080615 0" ] ||
    fail "--extrapolate hold, at a key: $(sed -n 3p "$d/hold")"
# extend: the first segment continued to t = -1 is that screw at u = -1
"$G" interp --format pose --in "$d/k3" --at -1 --extrapolate extend >"$d/ext" || fail "--extrapolate extend"
[ "$(cut -d' ' -f1-4 "$d/ext")" = "-1 -0.28 0.96 0" ] ||
    fail "--extrapolate extend: $(cat "$d/ext")"
# constant-velocity: the end pose moved on by the end's body velocity. On a
# screw path that is the end segment continued (extend), to rounding
near() { # near FILE1 FILE2 TOL: the same numbers, to TOL
    paste -d' ' "$1" "$2" | awk -v tol="$3" '{ h = NF / 2; for (i = 1; i <= h; i++) { e = $i - $(i + h)
        if (e < 0) e = -e; if (e > w) w = e } } END { exit !(NR > 0 && w <= tol) }'
}
"$G" interp --format pose --in "$d/k3" --at -1,3.5,6 --extrapolate extend >"$d/ext.e" || fail "extend"
"$G" interp --format pose --in "$d/k3" --at -1,3.5,6 --extrapolate constant-velocity >"$d/ext.cv" ||
    fail "--extrapolate constant-velocity"
near "$d/ext.e" "$d/ext.cv" 1e-14 || fail "constant-velocity on a screw path is not extend: $(cat "$d/ext.cv")"
# on c2 (velocity varies along a segment): past the end the body velocity is
# the end's, exactly, and the acceleration zero; the poses lie on one screw
# motion from the end key, so the screw through the end key and the sample at
# t = 3.1 gives the sample at t = 2.8 (an independent construction)
"$G" interp --scheme c2 --format pose --in "$d/k3" --at 2.5,2.8,3.1 --extrapolate constant-velocity \
    --with velocity,acceleration >"$d/cv.c2" || fail "c2 constant-velocity"
[ "$(cut -d' ' -f9-14 "$d/cv.c2" | sort -u | wc -l)" -eq 1 ] || fail "c2 constant-velocity: velocity not constant: $(cat "$d/cv.c2")"
[ "$(sed -n 2,3p "$d/cv.c2" | cut -d' ' -f15-20 | sort -u)" = "0 0 0 0 0 0" ] || fail "c2 constant-velocity: acceleration"
sed -n '1p;3p' "$d/cv.c2" | cut -d' ' -f1-8 >"$d/cv.keys"
"$G" interp --format pose --in "$d/cv.keys" --at 2.5,2.8 | sed -n 2p >"$d/cv.screw" || fail "screw through the constant-velocity samples"
sed -n 2p "$d/cv.c2" | cut -d' ' -f1-8 >"$d/cv.4"
near "$d/cv.screw" "$d/cv.4" 1e-14 || fail "c2 constant-velocity: not the end's screw: $(cat "$d/cv.4") against $(cat "$d/cv.screw")"
# --clip: the given times outside the keys dropped
"$G" interp --format pose --in "$d/k3" --times "$d/tt" --clip >"$d/clip" || fail "--clip"
[ "$(cut -d' ' -f1 "$d/clip" | tr '\n' ' ')" = "1 " ] || fail "--clip: $(cat "$d/clip")"
expect_error "interp: --clip and --extrapolate" "--clip drops the times --extrapolate hold would sample: give one" \
    "$G" interp --format pose --in "$d/k3" --times "$d/tt" --clip --extrapolate hold --out "$d/out"
# ---- layouts: --quat-order, --output-format, --format kitti, --twist-order ----
awk '{ print $1, $2, $3, $4, $8, $5, $6, $7 }' "$d/k3" >"$d/k3.wxyz"
"$G" interp --format pose --in "$d/k3" --samples 7 >"$d/k3.xyzw.out" || fail "k3 samples"
"$G" interp --format pose --quat-order wxyz --in "$d/k3.wxyz" --samples 7 --output-format tum >"$d/k3.tum" ||
    fail "--quat-order wxyz --output-format tum"
cmp -s "$d/k3.xyzw.out" "$d/k3.tum" || fail "--quat-order wxyz read, tum written: not the xyzw samples"
"$G" interp --format pose --quat-order wxyz --in "$d/k3.wxyz" --samples 7 >"$d/k3.wxyz.out" || fail "--quat-order wxyz"
awk '{ print $1, $2, $3, $4, $6, $7, $8, $5 }' "$d/k3.wxyz.out" | cmp -s - "$d/k3.xyzw.out" ||
    fail "--quat-order wxyz: not written w first"
"$G" interp --format pose --in "$d/k3" --samples 7 --output-format csv --with velocity --twist-order vw >"$d/k3.csv" ||
    fail "--output-format csv"
[ "$(sed -n 1p "$d/k3.csv")" = "t,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz" ] || fail "csv header: $(sed -n 1p "$d/k3.csv")"
"$G" interp --format pose --in "$d/k3" --samples 7 --with velocity >"$d/k3.v" || fail "--with velocity"
sed 1d "$d/k3.csv" | tr ',' ' ' | awk '{ print $1, $2, $3, $4, $5, $6, $7, $8, $12, $13, $14, $9, $10, $11 }' |
    cmp -s - "$d/k3.v" || fail "csv --twist-order vw: not the samples with v first"
# KITTI: 12 numbers a key, key k at t = k; written back as KITTI the keys
# come back as they were read
"$G" interp --format pose --in "$d/k3" --at 0,1,2.5 --output-format kitti >"$d/k3.kitti" || fail "--output-format kitti"
[ "$(awk '{ print NF }' "$d/k3.kitti" | sort -u)" = 12 ] || fail "kitti: not 12 numbers a line"
"$G" interp --format kitti --in "$d/k3.kitti" --samples 3 >"$d/k3.kitti2" || fail "--format kitti"
cmp -s "$d/k3.kitti" "$d/k3.kitti2" || fail "kitti round trip: $(cat "$d/k3.kitti2")"
"$G" interp --format kitti --in "$d/k3.kitti" --samples 3 --output-format pose | cut -d' ' -f1 | tr '\n' ' ' >"$d/kt"
[ "$(cat "$d/kt")" = "0 1 2 " ] || fail "kitti keys at t = 0, 1, 2: $(cat "$d/kt")"
expect_error "interp: kitti count" "k3:1: expected 12 numbers (a KITTI pose: the 3x4 \\[R t\\] row by row), found 8: is this a pose file? pass --format pose" \
    "$G" interp --format kitti --in "$d/k3" --samples 3 --out "$d/out"
expect_error "interp: kitti read as pose" "k3.kitti:1: expected 8 numbers (t, then x y z qx qy qz qw), found 12: is this a KITTI file (3x4, no t)? pass --format kitti" \
    "$G" interp --format pose --in "$d/k3.kitti" --samples 3 --out "$d/out"
expect_error "interp: kitti with --time-unit" "--format kitti has no times (key k is at t = k): drop --time-unit, or give the times with --stamps FILE" \
    "$G" interp --format kitti --in "$d/k3.kitti" --samples 3 --time-unit ns --out "$d/out"
# --stamps FILE (KITTI's times.txt): the keys at those times, the same
# samples as the pose file they came from (written as times.txt writes them,
# 0.000000e+00, and in nanoseconds with --time-unit ns)
printf '0.000000e+00\n1.000000e+00\n2.500000e+00\n' >"$d/k3.times"
"$G" interp --format kitti --stamps "$d/k3.times" --in "$d/k3.kitti" --at 0.5,1.75,2.5 --output-format pose \
    --with velocity >"$d/kst" || fail "--format kitti --stamps"
"$G" interp --format pose --in "$d/k3" --at 0.5,1.75,2.5 --with velocity | sed 's/^2.5 /2.500000e+00 /' | cmp -s - "$d/kst" ||
    fail "--format kitti --stamps: not the samples of the pose keys: $(cat "$d/kst")"
printf '1305031102000000000\n1305031103000000000\n1305031104500000000\n' >"$d/k3.ns"
"$G" interp --format kitti --stamps "$d/k3.ns" --time-unit ns --in "$d/k3.kitti" --samples 3 --output-format pose \
    --with velocity | cut -d' ' -f2- >"$d/kns" || fail "--format kitti --stamps --time-unit ns"
"$G" interp --format pose --in "$d/k3" --samples 3 --with velocity | cut -d' ' -f2- | cmp -s - "$d/kns" ||
    fail "--stamps in nanoseconds: not the samples of the pose keys in seconds"
[ "$("$G" interp --format kitti --stamps "$d/k3.times" --in "$d/k3.kitti" --samples 2 --output-format pose | cut -d' ' -f1 | tr '\n' ' ')" = "0.000000e+00 2.500000e+00 " ] ||
    fail "--stamps: samples at the keys not stamped as times.txt writes them"
head -n 2 "$d/k3.times" >"$d/k2.times"
expect_error "interp: --stamps too few" "k3.kitti:3: pose 3 has no stamp: .*k2.times has 2 stamps, .*k3.kitti 3 poses (one a pose, in order)" \
    "$G" interp --format kitti --stamps "$d/k2.times" --in "$d/k3.kitti" --samples 3 --out "$d/out"
printf '0\n1\n2.5\n3\n' >"$d/k4.times"
expect_error "interp: --stamps too many" "k4.times:4: stamp 4 has no pose: .*k3.kitti has 3 poses, .*k4.times 4 stamps (one a pose, in order)" \
    "$G" interp --format kitti --stamps "$d/k4.times" --in "$d/k3.kitti" --samples 3 --out "$d/out"
: >"$d/k0.times"
expect_error "interp: --stamps empty" "k0.times: no stamps (--stamps: one a pose of .*k3.kitti, in order)" \
    "$G" interp --format kitti --stamps "$d/k0.times" --in "$d/k3.kitti" --samples 3 --out "$d/out"
printf '0\n1 2\n2.5\n' >"$d/kx.times"
expect_error "interp: --stamps two numbers" "kx.times:2: expected 1 number (a stamp of --stamps: KITTI's times.txt), found 2" \
    "$G" interp --format kitti --stamps "$d/kx.times" --in "$d/k3.kitti" --samples 3 --out "$d/out"
printf '0\n2.5\n1\n' >"$d/kd.times"
expect_error "interp: --stamps decreasing" "kd.times:3: stamps must increase strictly: 1 after 2.5" \
    "$G" interp --format kitti --stamps "$d/kd.times" --in "$d/k3.kitti" --samples 3 --out "$d/out"
expect_error "interp: --stamps in ns unflagged" "k3.ns:1: the time 1305031102000000000 looks like nanoseconds (a whole number of 19 digits): pass --time-unit ns" \
    "$G" interp --format kitti --stamps "$d/k3.ns" --in "$d/k3.kitti" --samples 3 --out "$d/out"
expect_error "interp: --stamps ns not whole" "k3.times:3: --time-unit ns takes whole nanoseconds, not '2.500000e+00'" \
    "$G" interp --format kitti --stamps "$d/k3.times" --time-unit ns --in "$d/k3.kitti" --samples 3 --out "$d/out"
expect_error "interp: --stamps without kitti" "--stamps gives KITTI poses their times: it needs --format kitti" \
    "$G" interp --format pose --stamps "$d/k3.times" --in "$d/k3" --samples 3 --out "$d/out"
# --twist-order vw reads --velocities v first too
printf '0 0 0.5 1 0 0\n0 0 0.3 0.5 0.5 0\n0 0 0.1 0 1 0\n' >"$d/vel.wv"
awk '{ print $4, $5, $6, $1, $2, $3 }' "$d/vel.wv" >"$d/vel.vw"
"$G" interp --scheme lihao3 --format pose --in "$d/k3" --velocities "$d/vel.wv" --samples 9 >"$d/l3.wv" || fail "lihao3 wv"
"$G" interp --scheme lihao3 --format pose --in "$d/k3" --velocities "$d/vel.vw" --twist-order vw --samples 9 >"$d/l3.vw" ||
    fail "lihao3 --twist-order vw"
cmp -s "$d/l3.wv" "$d/l3.vw" || fail "--twist-order vw: --velocities not read v first"
"$G" interp --format pose --in "$d/k3" --at 0,1,2.5 --output-format mat >"$d/k3.mat" || fail "--output-format mat"
expect_error "interp: --output-format" "--output-format must be mat, pose, tum, kitti or csv, not 'json'" \
    "$G" interp --format pose --in "$d/k3" --samples 3 --output-format json --out "$d/out"
expect_error "interp: --format" "--format must be mat, pose or kitti, not 'tum'" \
    "$G" interp --format tum --in "$d/k3" --samples 3 --out "$d/out"
expect_error "interp: tum with velocity" "--output-format tum has no room for --with: use pose, mat or csv" \
    "$G" interp --format pose --in "$d/k3" --samples 3 --output-format tum --with velocity --out "$d/out"
expect_error "interp: --quat-order" "--quat-order must be xyzw or wxyz, not 'wzyx'" \
    "$G" interp --format pose --in "$d/k3" --samples 3 --quat-order wzyx --out "$d/out"
expect_error "interp: --quat-order on matrices" "--quat-order applies to --format pose, --output-format pose or csv" \
    "$G" interp --in "$d/k3.mat" --samples 3 --quat-order wxyz --out "$d/out"
expect_error "interp: --twist-order" "--twist-order must be wv or vw, not 'ww'" \
    "$G" interp --format pose --in "$d/k3" --samples 3 --twist-order ww --out "$d/out"
expect_error "interp: affine csv" "--group affine writes matrices (--output-format mat or kitti)" \
    "$G" interp --group affine --in "$d/k3.mat" --samples 3 --output-format csv --out "$d/out"
expect_error "interp: affine --twist-order" "--twist-order applies to --group cga or matrix" \
    "$G" interp --group affine --in "$d/k3.mat" --samples 3 --twist-order vw --out "$d/out"
# the quaternion written before the position: its norm fails, the first four pass
awk '{ print $1, $5, $6, $7, $8, $2, $3, $4 }' "$d/k3" >"$d/k3.qfirst"
expect_error "interp: quaternion first" "k3.qfirst:2: not a rigid motion: the quaternion has norm 1.2806248474865698, not 1 (to 1e-9; --normalize accepts up to 1e-3); the four numbers after t have norm 1: is the quaternion written before the position? the tool reads t x y z, then the quaternion" \
    "$G" interp --format pose --in "$d/k3.qfirst" --samples 3 --out "$d/out"
# ---- --columns: any layout, a header read by name (a rostopic echo -p CSV
# with a frame id column and two time columns), the same samples as the file
# cut to t x y z qx qy qz qw ----
ros=$(dirname "$doc")/figures/ros-pose.csv
"$G" interp --columns header,t=field.header.stamp --time-unit ns --samples 5 --in "$ros" >"$d/ros.out" ||
    fail "--columns header on a rostopic CSV"
sed 1d "$ros" | cut -d, -f3,5- | tr ',' ' ' >"$d/ros.cut"
"$G" interp --format pose --time-unit ns --samples 5 --in "$d/ros.cut" | cmp -s - "$d/ros.out" ||
    fail "--columns header: not the samples of the cut file"
"$G" interp --columns t=3,x=5,y=6,z=7,qx=8,qy=9,qz=10,qw=11 --header --time-unit ns --samples 5 --in "$ros" |
    cmp -s - "$d/ros.out" || fail "--columns by number: not the same samples"
awk '{ print $8, $1, $2, $3, $4, $5, $6, $7, "extra" }' "$d/k3" >"$d/k3.perm"
"$G" interp --columns qw,t,x,y,z,qx,qy,qz --in "$d/k3.perm" --samples 7 | cmp -s - "$d/k3.xyzw.out" ||
    fail "--columns in another order (an extra column after them)"
expect_error "interp: --columns two time columns" "ros-pose.csv:1: columns 1 (%time) and 3 (field.header.stamp) both look like t: pick one with --columns header,t=NAME" \
    "$G" interp --columns header --samples 3 --in "$ros" --out "$d/out"
expect_error "interp: --columns no such name" "ros-pose.csv:1: no column named 'stamp' in the header (--columns t=stamp)" \
    "$G" interp --columns header,t=stamp --samples 3 --in "$ros" --out "$d/out"
printf 'time,a,b,c,d,e,f,g\n0,0,0,0,0,0,0,1\n' >"$d/nohdr.csv"
expect_error "interp: --columns nothing like x" "nohdr.csv:1: no column of the header looks like x: name it, --columns header,x=NAME (or a column number)" \
    "$G" interp --columns header --samples 3 --in "$d/nohdr.csv" --out "$d/out"
: >"$d/empty"
expect_error "interp: --columns no header row" "empty: no header row (--columns header reads one)" \
    "$G" interp --columns header --samples 3 --in "$d/empty" --out "$d/out"
expect_error "interp: --columns short line" "k3:1: 8 columns, but --columns reads column 9 (qw)" \
    "$G" interp --columns t,x,y,z,qx,qy,qz,-,qw --samples 3 --in "$d/k3" --out "$d/out"
printf '0,0,0,0,0,0,0,1\n1,zz,0,0,0,0,0,1\n' >"$d/zz.csv"
expect_error "interp: --columns not a number" "zz.csv:2: column 2 (x): 'zz' is not a number" \
    "$G" interp --columns t,x,y,z,qx,qy,qz,qw --samples 3 --in "$d/zz.csv" --out "$d/out"
printf '0,0,0,0,0,0,0,1\n1,inf,0,0,0,0,0,1\n' >"$d/inf.csv"
expect_error "interp: --columns not finite" "inf.csv:2: column 2 (x): 'inf' is not finite" \
    "$G" interp --columns t,x,y,z,qx,qy,qz,qw --samples 3 --in "$d/inf.csv" --out "$d/out"
printf '0 2 0 0 0 0 0 1\n1 3 0 0 0 0 0 1\n' >"$d/x2"
expect_error "interp: --columns qw beyond 1" "x2:1: column 2 (qw) is 2: beyond 1, not a unit quaternion's; is that column the quaternion's? (--columns t,qw,qx,qy,qz,x,y,z)" \
    "$G" interp --columns t,qw,qx,qy,qz,x,y,z --samples 3 --in "$d/x2" --out "$d/out"
expect_error "interp: --columns bad word" "--columns: 'w' is not a column: name t x y z qx qy qz qw (or - to skip one) in the file's order, or ROLE=COLUMN (a number from 1, or a name in the header row), or header" \
    "$G" interp --columns t,x,y,z,qx,qy,qz,w --samples 3 --in "$d/k3" --out "$d/out"
expect_error "interp: --columns twice" "--columns: a role given twice: 'x'" \
    "$G" interp --columns t,x,x,z,qx,qy,qz,qw --samples 3 --in "$d/k3" --out "$d/out"
expect_error "interp: --columns mixed" "--columns: either the columns in order (t,x,...) or ROLE=COLUMN pairs and header, not both" \
    "$G" interp --columns t,x,y,z,qx,qy,qz,qw=8 --samples 3 --in "$d/k3" --out "$d/out"
expect_error "interp: --columns missing" "--columns gives no column for qw" \
    "$G" interp --columns t,x,y,z,qx,qy,qz --samples 3 --in "$d/k3" --out "$d/out"
expect_error "interp: --columns with --format mat" "--columns reads poses: drop --format mat" \
    "$G" interp --columns header --format mat --samples 3 --in "$d/k3" --out "$d/out"
expect_error "interp: --columns with --quat-order" "--columns names the quaternion's columns: drop --quat-order" \
    "$G" interp --columns header --quat-order wxyz --samples 3 --in "$d/k3" --out "$d/out"
# quoted CSV fields (RFC 4180, as pandas and ROS 2 bag exports write them):
# a quoted header, a quoted frame id holding a comma and a quote, a quoted
# number, spaces around a field; the same samples as the plain file
awk -F, 'NR == 1 { gsub(/[^,]+/, "\"&\""); print; next }
         { $4 = "\"map, \"\"base\"\"\""; $5 = "\"" $5 "\""; $6 = " " $6 " "; print }' OFS=, "$ros" >"$d/rosq.csv"
"$G" interp --columns header,t=field.header.stamp --time-unit ns --samples 5 --in "$d/rosq.csv" | cmp -s - "$d/ros.out" ||
    fail "--columns: quoted fields not read as the plain file: $(head -n 2 "$d/rosq.csv")"
printf '"t" "x" y z qx qy qz qw\n"0" 0 0 0 0 0 0 "1"\n1 "1"  0 0 0 0 0 1\n' >"$d/q.ws"
[ "$("$G" interp --columns header --at 0.5 --in "$d/q.ws")" = "0.5 0.5 0 0 0 0 0 1" ] ||
    fail "--columns: quoted fields separated by spaces"
printf 't,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,"1,0,0,0,0,0,1\n' >"$d/q1.csv"
expect_error "interp: --columns unclosed quote" "q1.csv:3: column 2: a quoted field with no closing quote (a field is quoted on one line)" \
    "$G" interp --columns header --samples 3 --in "$d/q1.csv" --out "$d/out"
printf 't,x,y,z,"qx"x,qy,qz,qw\n0,0,0,0,0,0,0,1\n' >"$d/q2.csv"
expect_error "interp: --columns text after quote" "q2.csv:1: column 5: text after the closing quote of a quoted field (a '\"' inside one is written '\"\"')" \
    "$G" interp --columns header --samples 3 --in "$d/q2.csv" --out "$d/out"
printf 't,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,1,0,0,0,0,0 "x",1\n' >"$d/q3.csv"
expect_error "interp: --columns quote in a field" "q3.csv:3: column 7: a '\"' inside a field that is not quoted (quote the whole field: \"a\"\"b\")" \
    "$G" interp --columns header --samples 3 --in "$d/q3.csv" --out "$d/out"
# a TUM header "# timestamp tx ty ..." read by name: the '#' is no column
printf '# t x y z qx qy qz qw\n0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n' >"$d/hash.tum"
[ "$("$G" interp --columns header --at 0.5 --in "$d/hash.tum")" = "0.5 0.5 0 0 0 0 0 1" ] ||
    fail "--columns header: a '# t x y ...' header read one column off"
# ---- eval --columns (--ref-columns, --est-columns): the parser of interp's
# --columns; the same report as the TUM files, byte for byte ----
er=$(dirname "$doc")/examples/eval_ref.tum
ee=$(dirname "$doc")/examples/eval_est.tum
"$G" eval --ref "$er" --est "$ee" --normalize --align sim3 >"$d/ev.plain" || fail "eval on the TUM files"
{ echo '"time","frame","qw","qx","qy","qz","x","y","z"'
  awk '!/^#/ { printf "%s,\"map, base\",%s,%s,%s,%s,%s,%s,%s\n", $1, $8, $5, $6, $7, $2, $3, $4 }' "$er"; } >"$d/evref.csv"
"$G" eval --ref "$d/evref.csv" --est "$ee" --normalize --align sim3 --ref-columns header,t=time |
    cmp -s - "$d/ev.plain" || fail "eval --ref-columns header: not the TUM file's report"
"$G" eval --ref "$d/evref.csv" --est "$ee" --normalize --align sim3 --header \
    --columns t,-,qw,qx,qy,qz,x,y,z --est-columns t,x,y,z,qx,qy,qz,qw | cmp -s - "$d/ev.plain" ||
    fail "eval --columns in order, --est-columns over it"
"$G" eval --ref "$er" --est "$ee" --normalize --align sim3 --columns header | cmp -s - "$d/ev.plain" ||
    fail "eval --columns header on TUM files (the '# timestamp tx ...' line names the columns)"
"$G" eval --ref "$ros" --est "$ros" --columns header,t=field.header.stamp --time-unit ns >"$d/ev.ros" ||
    fail "eval --columns on a rostopic CSV"
"$G" eval --ref "$d/ros.cut" --est "$d/ros.cut" --time-unit ns | cmp -s - "$d/ev.ros" ||
    fail "eval --columns on a rostopic CSV: not the cut file's report"
expect_error "eval: --columns bad word" "^garotor eval: --columns: 'w' is not a column: name t x y z qx qy qz qw" \
    "$G" eval --ref "$er" --est "$ee" --columns t,x,y,z,qx,qy,qz,w --out "$d/out"
expect_error "eval: --columns missing role" "^garotor eval: --columns gives no column for z" \
    "$G" eval --ref "$er" --est "$ee" --est-columns t,x,y --out "$d/out"
expect_error "eval: --ref-columns no such name" "evref.csv:1: no column named 'stamp' in the header (--columns t=stamp)" \
    "$G" eval --ref "$d/evref.csv" --est "$ee" --ref-columns header,t=stamp --out "$d/out"
expect_error "eval: --columns short line" "eval_est.tum:2: 8 columns, but --columns reads column 9 (z)" \
    "$G" eval --ref "$d/evref.csv" --est "$ee" --header --columns t,-,qw,qx,qy,qz,x,y,z --normalize --out "$d/out"
expect_error "eval: --columns not a number" "evref.csv:2: column 2 (x): 'map, base' is not a number" \
    "$G" eval --ref "$d/evref.csv" --est "$ee" --ref-columns t,x,y,z,qx,qy,qz,qw --header --out "$d/out"
expect_error "eval: --columns quaternion named by its columns" "evref.csv:3: columns 4, 5, 6, 3 (qx qy qz qw): the quaternion has norm 1.0000507187138061, not 1" \
    "$G" eval --ref "$d/evref.csv" --est "$ee" --ref-columns header,t=time --out "$d/out"
awk '!/^#/ { print $2, $3, $4, $5, $6, $7, $8, $1 } NR == 3 { print $2, $3, $4, $5, $6, $7, $8, $1 }' "$er" >"$d/evref.tlast"
expect_error "eval: --columns times named by their column" "evref.tlast:3: column 8: times must increase strictly: 1305031102.2758 after 1305031102.2758 (a repeated stamp" \
    "$G" eval --ref "$d/evref.tlast" --est "$ee" --ref-columns x,y,z,qx,qy,qz,qw,t --normalize --out "$d/out"
expect_error "eval: --columns twice" "option given twice '--ref-columns'" \
    "$G" eval --ref "$er" --est "$ee" --ref-columns header --ref-columns header --out "$d/out"
# ---- near-duplicate keys: closer than 1% of the median spacing an error;
# --dedup merges them into their mean (time and pose), --min-gap 0 keeps them ----
printf '0 0 0 0 0 0 0 1\n0.0333 0.1 0 0 0 0 0 1\n0.0334 0.1001 0 0 0 0 0 1\n0.0666 0.2 0 0 0 0 0 1\n0.1 0.3 0 0 0 0 0 1\n' >"$d/dup"
expect_error "interp: near-duplicate keys" "dup:3: key at t = 0.0334 is 0.0001 s after the key at t = 0.0333 (line 2), closer than --min-gap 0.0003325 s (1% of the median spacing, 0.03325 s): pass --dedup to merge such keys, or --min-gap 0 to keep them" \
    "$G" interp --format pose --in "$d/dup" --samples 3 --out "$d/out"
expect_error "interp: --min-gap given" "closer than --min-gap 0.001 s: pass --dedup" \
    "$G" interp --format pose --in "$d/dup" --samples 3 --min-gap 0.001 --out "$d/out"
"$G" interp --format pose --in "$d/dup" --samples 3 --min-gap 0 >/dev/null || fail "--min-gap 0 keeps near-duplicates"
# merged: one key at t = 0.03335, x = 0.10005 (the keys lie on x, rotation none)
"$G" interp --format pose --in "$d/dup" --at 0.03335 --dedup >"$d/dedup" || fail "--dedup"
awk '{ e = $2 - 0.10005; exit !($1 == "0.03335" && e < 1e-15 && e > -1e-15) }' "$d/dedup" ||
    fail "--dedup: not the mean key: $(cat "$d/dedup")"
expect_error "interp: --dedup on affine" "--dedup applies to --group cga or matrix" \
    "$G" interp --group affine --in "$d/k3.mat" --samples 3 --dedup --out "$d/out"
expect_error "interp: --min-gap" "--min-gap needs a number >= 0, not: -1" \
    "$G" interp --format pose --in "$d/dup" --samples 3 --min-gap -1 --out "$d/out"
# ---- time units: whole-number stamps of 12 digits or more are not taken
# for seconds unless --time-unit says so ----
sed 's/^0 /1305031102175800000 /; s/^1 /1305031103175800000 /; s/^2.5 /1305031104675800000 /' "$d/k3" >"$d/k3.ns"
expect_error "interp: ns stamps as seconds" "k3.ns:1: the time 1305031102175800000 looks like nanoseconds (a whole number of 19 digits): pass --time-unit ns (or --time-unit s if it is seconds)" \
    "$G" interp --format pose --in "$d/k3.ns" --samples 3 --out "$d/out"
"$G" interp --format pose --in "$d/k3.ns" --samples 3 --time-unit ns >/dev/null || fail "--time-unit ns on ns stamps"
"$G" interp --format pose --in "$d/k3.ns" --samples 3 --time-unit s >/dev/null || fail "--time-unit s on ns stamps"
sed 's/^0 /1305031102175 /; s/^1 /1305031103175 /; s/^2.5 /1305031104675 /' "$d/k3" >"$d/k3.ms"
expect_error "interp: ms stamps" "k3.ms:1: the time 1305031102175 looks like milliseconds (a whole number of 13 digits): --time-unit takes s or ns: convert the times (or pass --time-unit s if they are seconds)" \
    "$G" interp --format pose --in "$d/k3.ms" --samples 3 --out "$d/out"
# ---- --scheme bspline: 12 keys at 100 Hz with epoch stamps; its range is
# the second key's time to the last but one's ----
awk 'BEGIN { for (i = 0; i < 12; i++) { t = i / 100; a = 3 * t + sin(9 * t); b = cos(7 * t)
    s = sin(a / 2) / sqrt(0.25 + b * b); printf "1305031102.%02d %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n",
    17 + i, sin(5 * t), cos(4 * t), 2 * t, 0.5 * s, b * s, 0, cos(a / 2) } }' >"$d/bs"
"$G" interp --scheme bspline --format pose --normalize --in "$d/bs" --samples 4 >"$d/bs.s" || fail "bspline --samples"
[ "$(cut -d' ' -f1 "$d/bs.s" | tr '\n' ' ')" = "1305031102.18 1305031102.21 1305031102.24 1305031102.27 " ] ||
    fail "bspline --samples: not over [t_1, t_{n-2}]: $(cut -d' ' -f1 "$d/bs.s" | tr '\n' ' ')"
"$G" interp --scheme bspline --format pose --normalize --in "$d/bs" --rate 100 >"$d/bs.r" || fail "bspline --rate"
[ "$(wc -l <"$d/bs.r")" -eq 10 ] && [ "$(sed -n 1p "$d/bs.r" | cut -d' ' -f1)" = 1305031102.18 ] ||
    fail "bspline --rate 100: $(wc -l <"$d/bs.r") samples from $(sed -n 1p "$d/bs.r" | cut -d' ' -f1), want 10 from the second key"
for gr in cga matrix; do
    "$G" interp --scheme bspline --group $gr --format pose --normalize --in "$d/bs" --rate 1000 \
        --with velocity,acceleration >"$d/bs.$gr" || fail "bspline --group $gr"
done
"$G" interp --scheme bspline --eval exact --format pose --normalize --in "$d/bs" --rate 1000 >"$d/bs.exact" ||
    fail "bspline --eval exact"
# cga = matrix and exact = direct, to 1e-12 of the scales: 1 for a pose,
# |d|/h for a velocity and |d|/h^2 for an acceleration (h = 0.01 s, the
# relative motions |d| between keys below 1: 1e2 and 1e4)
paste -d' ' "$d/bs.cga" "$d/bs.matrix" | awk '{ for (i = 2; i <= 20; i++) { e = $i - $(i + 20)
    s = i <= 8 ? 1 : i <= 14 ? 1e2 : 1e4; if (e < 0) e = -e; if (e / s > w) w = e / s } }
    END { exit !(NR == 91 && w <= 1e-12) }' || fail "bspline: cga and matrix differ by more than 1e-12"
cut -d' ' -f1-8 "$d/bs.cga" | paste -d' ' - "$d/bs.exact" | awk '{ for (i = 2; i <= 8; i++) { e = $i - $(i + 8)
    if (e < 0) e = -e; if (e > w) w = e } } END { exit !(NR == 91 && w <= 1e-12) }' || fail "bspline: exact and direct differ by more than 1e-12"
# hold before the range: the pose at the range's start, velocity zero
"$G" interp --scheme bspline --format pose --normalize --in "$d/bs" --at 1305031102.17 --extrapolate hold >"$d/bs.h" ||
    fail "bspline --extrapolate hold"
[ "$(cut -d' ' -f2- "$d/bs.h")" = "$(sed -n 1p "$d/bs.s" | cut -d' ' -f2-)" ] || fail "bspline hold: not the pose at t_1"
"$G" interp --scheme bspline --format pose --normalize --in "$d/bs" --at 1305031102.17 --extrapolate extend >/dev/null ||
    fail "bspline --extrapolate extend"
expect_error "interp: bspline outside" "--at time 1305031102.17 is outside the B-spline's range \\[1305031102.18, 1305031102.27\\]" \
    "$G" interp --scheme bspline --format pose --normalize --in "$d/bs" --at 1305031102.17 --out "$d/out"
expect_error "interp: --scheme unknown" "--scheme must be screw, bivector, quadratic, smooth, lihao2, lihao3, decoupled, decoupled-c2, bspline or c2, not 'spline'" \
    "$G" interp --scheme spline --format pose --in "$d/k3" --samples 3 --out "$d/out"
expect_error "interp: bspline, 3 keys" "--scheme bspline needs one key or at least 4, found 3" \
    "$G" interp --scheme bspline --format pose --in "$d/k3" --samples 3 --out "$d/out"
sed 's/^1305031102.22 /1305031102.2201 /' "$d/bs" >"$d/bs.uneven"
expect_error "interp: bspline uneven" "bs.uneven:6: --scheme bspline needs evenly spaced key times (to 1e-9 of the spacing): 1305031102.2201 is 0.0001 s off" \
    "$G" interp --scheme bspline --format pose --normalize --in "$d/bs.uneven" --samples 3 --out "$d/out"
expect_error "interp: bspline, --rate below the range" "--rate 5: no sample time in the path's range \\[1305031102.18, 1305031102.27\\]" \
    "$G" interp --scheme bspline --format pose --normalize --in "$d/bs" --rate 5 --out "$d/out"
# ---- streaming: each sample is made once and written as it is made; a
# failure after thousands of good samples names the sample and its time, and
# leaves no --out file (the temporary is removed); on standard output the
# samples before it stay written ----
awk 'BEGIN { for (i = 0; i < 3000; i++) print i / 3000; print "1e300" }' >"$d/late"
"$G" interp --format pose --in "$d/k3" --times "$d/late" --extrapolate extend >"$d/late.out" 2>"$d/late.err"
rc=$?
cat "$d/late.err" >>"$d/all_stderr"
[ "$rc" -eq 2 ] || fail "interp: a sample fails after 3000 (stdout): exit status $rc, want 2"
grep -q "k3: sample 3001 at t = 1e300: sampling failed: outside the domain" "$d/late.err" ||
    fail "interp: a sample fails after 3000 (stdout): message '$(cat "$d/late.err")'"
[ "$(wc -l <"$d/late.out")" -eq 3000 ] || fail "interp: the 3000 samples before the failure are not on stdout"
expect_error "interp: a sample fails after 3000 (--out)" "sample 3001 at t = 1e300: sampling failed" \
    "$G" interp --format pose --in "$d/k3" --times "$d/late" --extrapolate extend --out "$d/out"
# a run killed while it writes (SIGTERM; SIGINT and SIGHUP alike) removes its
# temporary: no sig.out.tmpXXXXXX is left
"$G" interp --format pose --in "$d/k3" --samples 99999999 --out "$d/sig.out" 2>/dev/null &
sigpid=$!
sleep 1
kill -TERM $sigpid 2>/dev/null
wait $sigpid
ls "$d"/sig.out.tmp* >/dev/null 2>&1 && fail "interp killed by SIGTERM left $(ls "$d"/sig.out.tmp*)"
rm -f "$d/sig.out"
expect_error "interp: --out and --svg one file" "--out and --svg name the same file: $d/same" \
    "$G" interp --format pose --in "$d/k3" --samples 3 --out "$d/same" --svg "$d/same"
# (at 1e4 only the acceleration the tool computed with every velocity overflowed,
# through the 4x4 jet's squarings; a velocity alone, and the closed-form
# acceleration, are finite there: 1e100 puts the velocity itself past DBL_MAX)
expect_error "interp: a velocity overflows" "sample 1 at t = 1e100: no velocity: outside the domain" \
    "$G" interp --format pose --scheme smooth --at 1e100 --extrapolate extend --with velocity \
    --in "$(dirname "$doc")/figures/schemes.keys" --out "$d/out"
# the chunked samples are those of one call: the same lines to standard output,
# to a file and to a FIFO, for every kind of sample time and evaluator
mkfifo "$d/fifo" 2>/dev/null || :
for args in "--samples 2000" "--samples 1500 --eval exact" "--samples 1300 --eval euler --step 0.01" \
    "--rate 1000 --with velocity,acceleration" "--times $d/late --extrapolate hold"; do
    # shellcheck disable=SC2086 # $args is several words
    "$G" interp --format pose --in "$d/k3" $args >"$d/s1" 2>/dev/null
    # shellcheck disable=SC2086
    "$G" interp --format pose --in "$d/k3" $args --out "$d/s2" 2>/dev/null
    if [ -p "$d/fifo" ]; then
        cat "$d/fifo" >"$d/s3" &
        # shellcheck disable=SC2086
        "$G" interp --format pose --in "$d/k3" $args --out "$d/fifo" 2>/dev/null
        wait
    else
        cp "$d/s1" "$d/s3"
    fi
    [ -s "$d/s1" ] && cmp -s "$d/s1" "$d/s2" && cmp -s "$d/s1" "$d/s3" ||
        fail "interp $args: standard output, --out and a FIFO differ (or are empty)"
done
# the samples of one chunk and of many agree: euler's running state, rebuilt
# from the key at a chunk's start (sample 513 of 700), is the one carried
# from the sample before (sample 113 of the last 300, one chunk)
head -n 700 "$d/late" >"$d/t700"
"$G" interp --format pose --in "$d/k3" --times "$d/t700" --eval euler --step 0.01 >"$d/e700"
tail -n 300 "$d/t700" >"$d/t300"
"$G" interp --format pose --in "$d/k3" --times "$d/t300" --eval euler --step 0.01 >"$d/e300"
tail -n 300 "$d/e700" | cmp -s - "$d/e300" || fail "interp --eval euler: chunked samples differ from one call's"
# ---- exact times: a TUM-like file (4-decimal epoch stamps and quaternions,
# irregular spacing, q/-q flips), the same keys with stamps shifted to 0, and
# in integer nanoseconds: the same samples, keys hit, stamps as written ----
cat >"$d/gen.awk" <<'EOF'
BEGIN { split("1000 1500 1333 2000 667 1250 1250", inc, " ")
    for (i = 0; i < 36; i++) {
        if (i) ticks += inc[(i - 1) % 7 + 1]
        t = ticks / 10000; ang = 0.4 * t + 0.2 * sin(t); ay = 0.5 * cos(0.3 * t)
        s = sin(ang / 2) / sqrt(0.09 + ay * ay + 0.64); qw = cos(ang / 2); sg = i % 7 == 3 ? -1 : 1
        tot = 1758 + ticks
        if (mode == "epoch") st = sprintf("%d.%04d", 1305031102 + int(tot / 10000), tot % 10000)
        else if (mode == "ns") st = sprintf("%d%04d00000", 1305031102 + int(tot / 10000), tot % 10000)
        else st = sprintf("%d.%04d", int(ticks / 10000), ticks % 10000)
        printf "%s %.6f %.6f %.6f %.4f %.4f %.4f %.4f\n", st, 0.5 * sin(0.7 * t), 0.3 * cos(0.5 * t) - 0.3,
            0.1 * t, sg * 0.3 * s, sg * ay * s, sg * 0.8 * s, sg * qw
    } }
EOF
for m in epoch shifted ns; do
    awk -v mode=$m -f "$d/gen.awk" >"$d/tum.$m"
    "$G" interp --format pose --normalize --scheme lihao3 --rate 100 --with velocity,acceleration \
        --in "$d/tum.$m" --time-unit "$([ $m = ns ] && echo ns || echo s)" >"$d/tum.$m.out" 2>"$d/err" ||
        fail "exact times, $m: $(cat "$d/err")"
done
[ "$(wc -l <"$d/tum.epoch.out")" -eq 451 ] || fail "exact times: $(wc -l <"$d/tum.epoch.out") samples at 100 Hz over 4.5 s, not 451"
# every number but the stamp: the same to 1e-12 relative (they are the same doubles)
for m in shifted ns; do
    paste -d' ' "$d/tum.epoch.out" "$d/tum.$m.out" | awk '{ for (i = 2; i <= 20; i++) { e = $i - $(i + 20)
        s = $i < 0 ? -$i : $i; if (s < 1) s = 1; if (e < 0) e = -e; if (e > 1e-12 * s) bad = 1 } } END { exit bad }' ||
        fail "exact times: the samples of the epoch stamps and the $m ones differ by more than 1e-12"
done
# the stamps: epoch = 1305031102.1758 + shifted, and ns = epoch with the point moved 9 places
paste -d' ' "$d/tum.epoch.out" "$d/tum.shifted.out" "$d/tum.ns.out" | awk '
    function strip(x) { if (index(x, ".")) { sub(/0+$/, "", x); sub(/[.]$/, "", x) } return x }
    { split($21, a, "."); f = a[2]; while (length(f) < 4) f = f "0"; tot = 1758 + a[1] * 10000 + f
      if (strip($1) != strip(sprintf("%d.%04d", 1305031102 + int(tot / 10000), tot % 10000))) { print "line " NR ": " $1 " after " $21; bad = 1 }
      split($1, b, "."); g = b[2]; while (length(g) < 9) g = g "0"
      if ($41 != b[1] g) { print "line " NR ": " $41 " for " $1; bad = 1 } }
    END { exit bad }' >"$d/err" || fail "exact times: stamps are not t0 + k/100 exactly: $(head -3 "$d/err")"
[ "$(sed -n 2p "$d/tum.epoch.out" | cut -d' ' -f1)" = 1305031102.1858 ] || fail "exact times: stamp $(sed -n 2p "$d/tum.epoch.out" | cut -d' ' -f1)"
# keys hit: each key on the 100 Hz grid (its offset a whole number of 1/100 s:
# 21 of the 36) has a sample stamped with the key's own text, whose pose is the
# normalised key to 1e-15 (4.5 ulp of 1: quaternion -> matrix -> rotor -> matrix
# -> quaternion, a few roundings each; measured 3.3e-16)
for m in epoch shifted ns; do
    awk 'FNR == 1 { f++ }
         f == 1 { split($1, a, "."); grid[FNR] = a[2] % 100 == 0; next }
         f == 2 { if (grid[FNR]) want[$1] = $0; next }
         ($1 in want) { split(want[$1], k, " "); hit++
             nq = sqrt(k[5] ^ 2 + k[6] ^ 2 + k[7] ^ 2 + k[8] ^ 2); sg = k[5] * $5 + k[6] * $6 + k[7] * $7 + k[8] * $8 < 0 ? -1 : 1
             for (i = 2; i <= 8; i++) { e = $i - (i < 5 ? k[i] : sg * k[i] / nq); if (e < 0) e = -e; if (e > 1e-15) bad = 1 } }
         END { if (hit != 21) print "hit " hit " keys of 21"; exit bad || hit != 21 }' \
        "$d/tum.shifted" "$d/tum.$m" "$d/tum.$m.out" >"$d/err" ||
        fail "exact times, $m: keys on the grid not hit, or not stamped as written: $(cat "$d/err")"
done
# velocity and acceleration against central differences of the poses, with
# steps h = 0.01 and 2h, on the samples whose stencil (t +- 4h) has no key
# inside (lihao3 is C1: the acceleration jumps at keys). The differences
# converge as h^2 (err(h) <= 0.3 err(2h)), and their Richardson limit
# (4 D(h) - D(2h))/3 agrees with the analytic value to 1% of err(h): an error
# in the analytic value would stay in that limit. (measured: velocity err(h)
# 1.1e-4, limit 7.3e-9; acceleration 2.8e-4, 2.5e-7.)
awk '
function vfd(k, m, out,   a, b, w, x, y, z, s, f) {
    a = k - m; b = k + m
    w = qw[a] * qw[b] + qx[a] * qx[b] + qy[a] * qy[b] + qz[a] * qz[b]
    x = qw[a] * qx[b] - qx[a] * qw[b] - qy[a] * qz[b] + qz[a] * qy[b]
    y = qw[a] * qy[b] + qx[a] * qz[b] - qy[a] * qw[b] - qz[a] * qx[b]
    z = qw[a] * qz[b] - qx[a] * qy[b] + qy[a] * qx[b] - qz[a] * qw[b]
    if (w < 0) { w = -w; x = -x; y = -y; z = -z }
    s = sqrt(x * x + y * y + z * z); f = s > 0 ? 2 * atan2(s, w) / s / (2 * m * h) : 0
    out[1] = f * x; out[2] = f * y; out[3] = f * z
    rotT(k, (px[b] - px[a]) / (2 * m * h), (py[b] - py[a]) / (2 * m * h), (pz[b] - pz[a]) / (2 * m * h), out)
}
function rotT(k, dx, dy, dz, out,   w, x, y, z) {
    w = qw[k]; x = qx[k]; y = qy[k]; z = qz[k]
    out[4] = (1 - 2 * (y * y + z * z)) * dx + 2 * (x * y + w * z) * dy + 2 * (x * z - w * y) * dz
    out[5] = 2 * (x * y - w * z) * dx + (1 - 2 * (x * x + z * z)) * dy + 2 * (y * z + w * x) * dz
    out[6] = 2 * (x * z + w * y) * dx + 2 * (y * z - w * x) * dy + (1 - 2 * (x * x + y * y)) * dz
}
function afd(k, m, out,   u, l, i) { vfd(k + m, m, u); vfd(k - m, m, l); for (i = 1; i <= 6; i++) out[i] = (u[i] - l[i]) / (2 * m * h) }
function ab(x) { return x < 0 ? -x : x }
FNR == NR { key[++nk] = $1 + 0; next }
{ n++; t[n] = $1 + 0; px[n] = $2; py[n] = $3; pz[n] = $4; qx[n] = $5; qy[n] = $6; qz[n] = $7; qw[n] = $8
  for (i = 1; i <= 6; i++) { v[n, i] = $(8 + i); a[n, i] = $(14 + i) } }
END {
    h = 0.01
    for (k = 5; k + 4 <= n; k++) {
        ok = 1
        for (j = 1; j <= nk; j++) if (key[j] > t[k - 4] && key[j] < t[k + 4]) ok = 0
        if (!ok) continue
        used++
        vfd(k, 1, v1); vfd(k, 2, v2); afd(k, 1, a1); afd(k, 2, a2)
        for (i = 1; i <= 6; i++) {
            if (ab(v1[i] - v[k, i]) > ev1) ev1 = ab(v1[i] - v[k, i]); if (ab(v2[i] - v[k, i]) > ev2) ev2 = ab(v2[i] - v[k, i])
            if (ab(a1[i] - a[k, i]) > ea1) ea1 = ab(a1[i] - a[k, i]); if (ab(a2[i] - a[k, i]) > ea2) ea2 = ab(a2[i] - a[k, i])
            e = ab((4 * v1[i] - v2[i]) / 3 - v[k, i]); if (e > rv) rv = e
            e = ab((4 * a1[i] - a2[i]) / 3 - a[k, i]); if (e > ra) ra = e
        }
    }
    printf "%d samples; velocity err(h) %.3g, err(2h) %.3g, limit %.3g; acceleration %.3g, %.3g, %.3g\n", used, ev1, ev2, rv, ea1, ea2, ra
    exit !(used >= 150 && ev1 <= 0.3 * ev2 && ea1 <= 0.3 * ea2 && rv <= 0.01 * ev1 && ra <= 0.01 * ea1 && ev1 > 0)
}' "$d/tum.shifted" "$d/tum.shifted.out" >"$d/fd" || fail "exact times: velocity and acceleration against finite differences: $(cat "$d/fd")"
# given times are written as given, but one equal to a key's as the key was
# written; a computed stamp reads back (relative to the same first key) as the
# time it was taken at: --rate 3's stamps given back as --times give the same
printf '1305031102.2000\n1305031102.27580\n' >"$d/tum.times"
"$G" interp --format pose --normalize --in "$d/tum.epoch" --times "$d/tum.times" | cut -d' ' -f1 | tr '\n' ' ' >"$d/st"
[ "$(cat "$d/st")" = "1305031102.2000 1305031102.2758 " ] || fail "--times stamps: $(cat "$d/st")"
[ "$("$G" interp --format pose --normalize --in "$d/tum.ns" --time-unit ns --at 1305031102175800000,13050311022e8 | cut -d' ' -f1 | tr '\n' ' ')" = \
    "1305031102175800000 13050311022e8 " ] || fail "--at with --time-unit ns: stamps not as given"
"$G" interp --format pose --normalize --in "$d/tum.epoch" --rate 3 >"$d/r3"
[ "$(sed -n 2p "$d/r3" | cut -d' ' -f1)" = 1305031102.5091333333333333 ] || fail "--rate 3: stamp $(sed -n 2p "$d/r3" | cut -d' ' -f1)"
cut -d' ' -f1 "$d/r3" >"$d/r3.times"
"$G" interp --format pose --normalize --in "$d/tum.epoch" --times "$d/r3.times" | cmp -s - "$d/r3" ||
    fail "--rate 3: its stamps read back as --times do not give the same samples"
"$G" interp --format pose --normalize --in "$d/tum.ns" --time-unit ns --samples 4 | cut -d' ' -f1 | tr '\n' ' ' >"$d/st"
[ "$(cat "$d/st")" = "1305031102175800000 1305031103675800000 1305031105175800000 1305031106675800000 " ] ||
    fail "--samples with --time-unit ns: $(cat "$d/st")"
expect_error "interp: --time-unit" "--time-unit must be s or ns, not 'ms'" \
    "$G" interp --format pose --normalize --in "$d/tum.epoch" --rate 1 --time-unit ms --out "$d/out"
expect_error "interp: --time-unit ns, a decimal key" "tum.epoch:1: --time-unit ns takes whole nanoseconds, not '1305031102.1758'" \
    "$G" interp --format pose --normalize --in "$d/tum.epoch" --rate 1 --time-unit ns --out "$d/out"
expect_error "interp: --time-unit ns, a decimal --at" "--at: --time-unit ns takes whole nanoseconds, not '1.5'" \
    "$G" interp --format pose --normalize --in "$d/tum.ns" --at 1.5 --time-unit ns --out "$d/out"
printf '1 2\n' >"$d/tt2"
expect_error "interp: --times two numbers" "tt2:1: expected 1 number (a time), found 2" \
    "$G" interp --format pose --in "$d/k3" --times "$d/tt2" --out "$d/out"
printf '# nothing\n' >"$d/tt0"
expect_error "interp: --times empty" "tt0: no times" "$G" interp --format pose --in "$d/k3" --times "$d/tt0" --out "$d/out"
expect_error "interp: --rate 0" "--rate needs a number > 0, not: 0" "$G" interp --in "$d/k3" --rate 0 --out "$d/out"
expect_error "interp: --rate huge" "--rate 1.0000000000000001e+300 gives more than 1e9 samples" \
    "$G" interp --format pose --in "$d/k3" --rate 1e300 --out "$d/out"
expect_error "interp: --extrapolate" "--extrapolate must be error, hold, extend or constant-velocity, not 'wrap'" \
    "$G" interp --format pose --in "$d/k3" --rate 1 --extrapolate wrap --out "$d/out"
expect_error "interp: too few keys (smooth)" "two: --scheme smooth needs one key or at least 3, found 2" \
    "$G" interp --scheme smooth --format pose --samples 3 --in "$d/two" --out "$d/out"
expect_error "interp: quadratic needs 3" "two: --scheme quadratic needs one key or exactly 3, found 2" \
    "$G" interp --scheme quadratic --format pose --samples 3 --in "$d/two" --out "$d/out"
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0.6 0.6\n' >"$d/badq"
expect_error "interp: quaternion not unit" "badq:2: not a rigid motion: the quaternion" \
    "$G" interp --format pose --samples 3 --in "$d/badq" --out "$d/out"
printf '0  1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n1  1 0 0 0 0 1 0 0 0 0 3 0 0 0 0 1\n' >"$d/badm"
expect_error "interp: matrix not rigid" "badm:2: not a rigid motion" \
    "$G" interp --samples 3 --in "$d/badm" --out "$d/out"
expect_error "interp: 8 numbers without --format pose" "two:1: expected 17 numbers" \
    "$G" interp --samples 3 --in "$d/two" --out "$d/out"
printf '0 0 0 0 0 0\n0 0 0 0 0 0\n' >"$d/vel2"
expect_error "interp: velocity count" "vel2: one velocity per key" \
    "$G" interp --scheme lihao3 --format pose --samples 3 --in "$d/keys" --velocities "$d/vel2" --out "$d/out"
printf '0 0 0 0 0 0\n0 0 0 0 0\n0 0 0 0 0 0\n' >"$d/vel5"
expect_error "interp: velocity with 5 numbers" "vel5:2: expected 6 numbers" \
    "$G" interp --scheme lihao3 --format pose --samples 3 --in "$d/keys" --velocities "$d/vel5" --out "$d/out"
expect_error "interp: --at outside" "outside the keys' range" \
    "$G" interp --format pose --at 0.5,4 --in "$d/keys" --out "$d/out"
expect_error "interp: --samples 1" "--samples needs" \
    "$G" interp --format pose --samples 1 --in "$d/keys" --out "$d/out"
expect_error "interp: euler without step" "needs --step" \
    "$G" interp --format pose --samples 3 --eval euler --in "$d/keys" --out "$d/out"
expect_error "interp: unknown scheme" "--scheme must be" \
    "$G" interp --scheme spline --format pose --samples 3 --in "$d/keys" --out "$d/out"
expect_error "interp: affine with poses" "affine takes keys as matrices" \
    "$G" interp --group affine --format pose --samples 3 --in "$d/keys" --out "$d/out"
expect_error "interp: neither --samples nor --at" "give one of --samples N" \
    "$G" interp --format pose --in "$d/keys" --out "$d/out"

# ---- more of the error table ----------------------------------------------
K="$d/keys"
expect_error "missing value" "missing value for: --samples" "$G" interp --in "$K" --samples
expect_error "option twice" "option given twice: --samples" \
    "$G" interp --format pose --samples 3 --samples 4 --in "$K" --out "$d/out"
expect_error "flag with a value" "this option takes no value: --normalize=1" \
    "$G" interp --format pose --samples 3 --normalize=1 --in "$K" --out "$d/out"
expect_error "--v0=" "--v0 takes its six numbers as separate words, not: --v0=1" \
    "$G" interp --scheme lihao2 --format pose --samples 3 --v0=1 --in "$K" --out "$d/out"
"$G" interp --format pose --samples 5 --in "$K" --out "$d/spaced"
"$G" interp --format=pose --samples=5 --in="$K" --out="$d/joined"
cmp -s "$d/spaced" "$d/joined" && pass || fail "--opt=value differs from --opt value"
[ "$("$G" --version)" = "garotor $(sed -n "s/^ *version *: *'\([^']*\)'.*/\1/p" "$(dirname "$doc")/../meson.build" | head -1)" ] && pass ||
    fail "--version does not print meson.build's version"
expect_error "--step not > 0" "--step needs a number in \\[1e-9, 1\\] (u units), not: 0" \
    "$G" interp --format pose --samples 3 --eval euler --step 0 --in "$K" --out "$d/out"
expect_error "--step above 1" "--step needs a number in \\[1e-9, 1\\] (u units), not: 2" \
    "$G" interp --format pose --samples 3 --eval euler --step 2 --in "$K" --out "$d/out"
expect_error "--v0 not a number" "--v0 needs 6 finite numbers, not: x" \
    "$G" interp --scheme lihao2 --format pose --samples 3 --v0 1 2 3 4 5 x --in "$K" --out "$d/out"
expect_error "unknown eval" "--eval must be" \
    "$G" interp --format pose --samples 3 --eval rk4 --in "$K" --out "$d/out"
expect_error "--step without euler" "--step applies only" \
    "$G" interp --format pose --samples 3 --step 0.1 --in "$K" --out "$d/out"
expect_error "unknown format" "--format must be" \
    "$G" interp --format csv --samples 3 --in "$K" --out "$d/out"
expect_error "--v0 with screw" "--v0 applies only" \
    "$G" interp --format pose --samples 3 --v0 0 0 0 0 0 0 --in "$K" --out "$d/out"
expect_error "--velocities with screw" "--velocities applies only" \
    "$G" interp --format pose --samples 3 --velocities "$d/vel2" --in "$K" --out "$d/out"
printf '0 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n1 1 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1\n' >"$d/matkeys"
expect_error "decoupled on affine" "--scheme decoupled is not defined on --group affine" \
    "$G" interp --scheme decoupled --group affine --samples 3 --in "$d/matkeys" --out "$d/out"
expect_error "c2 on affine" "--scheme c2 is not defined on --group affine" \
    "$G" interp --scheme c2 --group affine --samples 3 --in "$d/matkeys" --out "$d/out"
# c2 on keys that lie on one screw motion exp(t xi), at uneven times: that
# motion, to 1e-13 (the samples against `garotor exp` of t xi)
printf '%s\n' -0.7 0.4 0.9 2.6 3.1 4.4 >"$d/st"
awk '{ t = $1; print t * 0.3, t * -0.5, t * 0.4, t * 1.2, t * 0.2, t * -0.7 }' "$d/st" | "$G" exp >"$d/sm" &&
    paste -d ' ' "$d/st" "$d/sm" >"$d/skeys" || fail "c2 screw keys"
awk 'BEGIN { for (k = 0; k <= 50; k++) printf "%.17g\n", -0.7 + 5.1 * k / 50 }' >"$d/stimes"
awk '{ t = $1; printf "%.17g %.17g %.17g %.17g %.17g %.17g\n", t * 0.3, t * -0.5, t * 0.4, t * 1.2, t * 0.2, t * -0.7 }' \
    "$d/stimes" | "$G" exp >"$d/sexp"
for group in cga matrix; do
    "$G" interp --scheme c2 --group "$group" --times "$d/stimes" --in "$d/skeys" >"$d/sc2" 2>"$d/err" ||
        fail "c2 on one screw motion, $group: $(cat "$d/err")"
    cut -d ' ' -f 2- "$d/sc2" | paste -d ' ' - "$d/sexp" | awk '{ for (i = 1; i <= 16; i++) { e = $i - $(i + 16)
        if (e < 0) e = -e; if (e > m) m = e } } END { if (NR != 51 || m > 1e-13) { print NR, m; exit 1 } }' >"$d/err" ||
        fail "c2 does not reproduce the screw motion on $group: $(cat "$d/err")"
done
expect_error "--at not numbers" "--at needs finite times" \
    "$G" interp --format pose --at 0,x --in "$K" --out "$d/out"
expect_error "--view without --svg" "--view applies only with --svg" \
    "$G" interp --format pose --samples 3 --view xy --in "$K" --out "$d/out"
expect_error "demo --view without --svg" "demo: --view applies only with --svg" "$G" demo --view xy
expect_error "--svg to stdout" "--svg needs a file name, not '-'" \
    "$G" interp --format pose --samples 3 --svg - --in "$K" --out "$d/out"
expect_error "unknown view" "--view must be iso, xy, xz or yz, not 'top'" \
    "$G" interp --format pose --samples 3 --svg "$d/out.svg" --view top --in "$K" --out "$d/out"
expect_error "demo: unknown view" "--view must be" "$G" demo --svg "$d/out.svg" --view top
expect_error "read error" "$d:1: read error: Is a directory" "$G" exp --in "$d" --out "$d/out"
printf '0 0 0 0 0 2x\n' >"$d/junk"
expect_error "junk after a number" "junk:1: junk after number 6" "$G" exp --in "$d/junk" --out "$d/out"
printf '1000 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n' >"$d/abig"
expect_error "exp affine: overflow" "abig:1: outside the domain" \
    "$G" exp --group affine --in "$d/abig" --out "$d/out"
printf '0  1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n1  -1 0 0 0 0 -2 0 0 0 0 1 0 0 0 0 1\n' >"$d/negkeys"
expect_error "interp affine: no real log" "negkeys: cannot build the bivector path" \
    "$G" interp --group affine --scheme bivector --samples 3 --in "$d/negkeys" --out "$d/out" --svg "$d/out.svg"
printf '0 0 0 0 0 0\n0 0 0 0 0 0\n0 0 0 0 0 0\n0 0 0 0 0 0\n' >"$d/vel4"
expect_error "interp: more velocities than keys" "vel4:4: one velocity per key" \
    "$G" interp --scheme lihao3 --format pose --samples 3 --in "$K" --velocities "$d/vel4" --out "$d/out"
expect_error "--out in a missing directory" "nodir/x: cannot write" \
    "$G" exp --in "$d/twists" --out "$d/nodir/x"
expect_error "--svg in a missing directory" "nodir/x.svg: cannot write" \
    "$G" interp --format pose --samples 3 --in "$K" --out "$d/out" --svg "$d/nodir/x.svg"
expect_error "--out fails: no picture left" "nodir/x: cannot write" \
    "$G" interp --format pose --samples 3 --in "$K" --out "$d/nodir/x" --svg "$d/out.svg"
expect_error "demo --svg in a missing directory" "nodir/x.svg: cannot write" \
    "$G" demo --svg "$d/nodir/x.svg"
expect_error "interp: bad keys, no picture left" "same_t:3: key times must increase" \
    "$G" interp --format pose --samples 3 --in "$d/same_t" --out "$d/out" --svg "$d/out.svg"
expect_error "interp: bad keys, picture to a new name" "badq:2: not a rigid motion" \
    "$G" interp --format pose --samples 3 --in "$d/badq" --svg "$d/out.svg"
long=$d/out$(awk -v n=$((4090 - ${#d})) 'BEGIN { while (n-- > 0) printf "a" }')
expect_error "name too long" "name too long" "$G" exp --in "$d/twists" --out "$long"
if [ -w /dev/full ]; then
    "$G" exp --in "$d/twists" >/dev/full 2>"$d/stderr"
    rc=$?
    cat "$d/stderr" >>"$d/all_stderr"
    [ "$rc" -eq 2 ] && grep -q "<stdout>: write error" "$d/stderr" || fail "write error: status $rc, $(cat "$d/stderr")"
fi
if [ -w /dev/full ]; then
    # --out a device: written in place; its write error is reported, and the
    # picture already written is removed again
    expect_error "--out a full device" "/dev/full: write error" \
        "$G" interp --format pose --samples 3 --in "$K" --out /dev/full --svg "$d/out.svg"
fi
ls "$d"/*.tmp* >/dev/null 2>&1 && fail "temporary files left behind: $(ls "$d"/*.tmp*)"

# ---- where output goes ------------------------------------------------------
# a new file gets 0666 less the umask (not mkstemp's 0600); a replaced file
# keeps its mode; a symbolic link stays a link to the rewritten file
(umask 022 && "$G" exp --in "$d/twists" --out "$d/mode_new") || fail "exp --out a new file"
[ "$(stat -c %a "$d/mode_new")" = 644 ] || fail "new --out file has mode $(stat -c %a "$d/mode_new"), not 644"
chmod 640 "$d/mode_new"
"$G" exp --in "$d/twists" --out "$d/mode_new" || fail "exp --out an existing file"
[ "$(stat -c %a "$d/mode_new")" = 640 ] || fail "replaced --out file has mode $(stat -c %a "$d/mode_new"), not 640"
echo old >"$d/link_target"
ln -s link_target "$d/link"
"$G" exp --in "$d/twists" --out "$d/link" || fail "exp --out a symbolic link"
[ -L "$d/link" ] || fail "--out replaced a symbolic link by a file"
"$G" exp --in "$d/twists" | cmp -s - "$d/link_target" || fail "--out through a link did not write its target"
# a FIFO (and so /dev/null or a terminal) is written in place, never replaced
# by a regular file, and never removed when a later step fails
[ -p "$d/fifo" ] || mkfifo "$d/fifo" # made above for the chunked samples
cat "$d/fifo" >"$d/fifo_read" &
"$G" exp --in "$d/twists" --out "$d/fifo" || fail "exp --out a FIFO"
wait
[ -p "$d/fifo" ] || fail "--out replaced a FIFO by a regular file"
"$G" exp --in "$d/twists" | cmp -s - "$d/fifo_read" || fail "--out a FIFO: not what standard output gets"
if [ -w /dev/full ]; then
    cat "$d/fifo" >/dev/null &
    "$G" interp --format pose --samples 3 --in "$K" --out /dev/full --svg "$d/fifo" 2>/dev/null &&
        fail "--out /dev/full succeeded"
    wait
    [ -p "$d/fifo" ] || fail "a picture written to a FIFO was removed after a later error"
fi

# ---- pictures ---------------------------------------------------------------
svg_ok() { # svg_ok NAME FILE: well-formed (xmllint, if installed), an <svg> with a path
    [ -s "$2" ] || { fail "$1: no picture"; return; }
    if command -v xmllint >/dev/null 2>&1; then
        xmllint --noout "$2" 2>"$d/xml" || fail "$1: not well-formed XML: $(cat "$d/xml")"
    fi
    grep -q '^<svg xmlns="http://www.w3.org/2000/svg"' "$2" || fail "$1: no <svg> element"
    grep -q '<polyline' "$2" || fail "$1: no trajectory"
    [ "$(tail -n 1 "$2")" = "</svg>" ] || fail "$1: does not end with </svg>"
}
head -n 2 "$K" >"$d/two_turn"
"$G" interp --format pose --samples 21 --in "$d/two_turn" --out "$d/p.txt" --svg "$d/p.svg" ||
    fail "interp --svg"
svg_ok "interp --svg" "$d/p.svg"
[ "$(wc -l <"$d/p.txt")" -eq 21 ] || fail "interp --svg still writes the samples"
grep -q 'screw axis' "$d/p.svg" || fail "two keys, screw: the axis is drawn"
"$G" interp --scheme quadratic --format pose --samples 21 --in "$K" --out "$d/q.txt" \
    --svg "$d/q.svg" || fail "interp --svg quadratic"
svg_ok "quadratic" "$d/q.svg"
grep -q 'screw axis' "$d/q.svg" && fail "quadratic: no screw axis"
"$G" interp --format pose --samples 21 --in "$K" --out "$d/s.txt" --svg "$d/s.svg"
grep -q 'screw axis' "$d/s.svg" && fail "three keys on different screws: no axis"
for v in iso xy xz yz; do
    "$G" interp --format pose --samples 21 --in "$K" --out "$d/v.txt" --svg "$d/v-$v.svg" \
        --view "$v" || fail "--view $v"
    svg_ok "--view $v" "$d/v-$v.svg"
    grep -q "view $v<" "$d/v-$v.svg" || fail "--view $v: not named in the picture"
done
cmp -s "$d/v-iso.svg" "$d/v-xy.svg" && fail "--view xy draws the same as iso"
"$G" interp --format pose --samples 21 --in "$K" --out "$d/v.txt" --svg "$d/again.svg" --view xy
cmp -s "$d/v-xy.svg" "$d/again.svg" || fail "the same picture twice differs"
# a picture of many samples keeps at most 8193 of them (every stride-th and
# the last): the polyline ends on the last key, memory does not grow
"$G" interp --format pose --samples 20000 --in "$K" --out "$d/many.txt" --svg "$d/many.svg" --view xy ||
    fail "20000 samples --svg"
awk 'BEGIN { RS = "\"" } prev ~ /points=$/ { n = split($0, p, /[ \n]+/); while (p[n] == "") n--; print n, p[n] }
     { prev = $0 }' "$d/many.svg" >"$d/many.pts"
read -r npts lastpt <"$d/many.pts"
lastkey=$(grep -o '<circle cx="[^"]*" cy="[^"]*" r="3.5"' "$d/many.svg" | tail -n 1 | sed 's/<circle cx="\([^"]*\)" cy="\([^"]*\)".*/\1,\2/')
[ "$npts" -eq 6668 ] || fail "20000 samples: the picture keeps $npts points, not ceil(20000/3) + 1 = 6668"
[ "$lastpt" = "$lastkey" ] || fail "20000 samples: the polyline ends at $lastpt, the last key is at $lastkey"
[ "$(wc -l <"$d/many.txt")" -eq 20000 ] || fail "20000 samples --svg: every sample still written"
# key labels carry the key's time in full (an epoch stamp, not 1.30503e+09)
printf '1305031102.1758 0 0 0 0 0 0 1\n1305031103.1758 1 0 0 0 0 0 1\n' >"$d/epoch2"
"$G" interp --format pose --samples 3 --in "$d/epoch2" --out "$d/e.txt" --svg "$d/e.svg" || fail "epoch --svg"
grep -q '>t=1305031102.1758<' "$d/e.svg" && grep -q '>t=1305031103.1758<' "$d/e.svg" ||
    fail "epoch key labels: $(grep -o '>t=[^<]*' "$d/e.svg" | tr '\n' ' ')"
"$G" interp --group matrix --format pose --samples 21 --in "$K" --svg "$d/m.svg" >"$d/m.txt" ||
    fail "interp --svg with samples on standard output"
[ "$(wc -l <"$d/m.txt")" -eq 21 ] || fail "samples on standard output beside --svg"
svg_ok "--group matrix" "$d/m.svg"
"$G" interp --header --format pose --samples 5 --in "$(dirname "$doc")/figures/tool-poses.csv" >/dev/null ||
    fail "interp --header reads the tutorial's CSV"

# ---- the demonstration: no arguments, under a second, and its picture ------
start=$(date +%s%N 2>/dev/null)
"$G" >"$d/demo.txt" || fail "garotor with no arguments exits non-zero"
end=$(date +%s%N 2>/dev/null)
case "$start$end" in
*N*) ;; # no nanoseconds in this date
*) [ $(((end - start) / 1000000)) -lt 1000 ] || fail "garotor took $(((end - start) / 1000000)) ms" ;;
esac
grep -q "largest difference of a matrix entry" "$d/demo.txt" || fail "demo: the cross-check is reported"
grep -q "pitch" "$d/demo.txt" || fail "demo: the screws are reported"
"$G" demo --svg "$d/demo.svg" >"$d/demo2.txt" || fail "demo --svg"
svg_ok "demo --svg" "$d/demo.svg"
[ "$(grep -c '<polyline' "$d/demo.svg")" -eq 2 ] || fail "demo --svg draws two paths"
"$G" --svg "$d/demo3.svg" --view yz >/dev/null || fail "garotor --svg (the demo, options only)"
svg_ok "garotor --svg" "$d/demo3.svg"

# ---- versor: exp, log and apply of the general algebra (docs/versors.md) ---
# mv32 K=V ...: a line of 32 coefficients, V at canonical index K, 0 elsewhere
mv32() {
    awk -v set="$*" 'BEGIN { for (i = 0; i < 32; i++) c[i] = 0
        n = split(set, kv, " "); for (j = 1; j <= n; j++) { split(kv[j], p, "="); c[p[1]] = p[2] }
        for (i = 0; i < 32; i++) printf "%s%s", (i ? " " : ""), c[i]; printf "\n" }'
}
# bivectors (e12 e13 e14 e15 e23 e24 e25 e34 e35 e45) with every rotation part
# below a half-angle of pi/2: a rotation, a dilation, a translation (null), a
# transversion (null), a rotation with a dilation, a mixture, zero
cat >"$d/biv" <<'B'
0.7 0 0 0 0 0 0 0 0 0
0 0 0 0 0 0 0 0 0 -0.4
0 0 0.5 0.5 0 0 0 0 0 0
0 0 0.25 -0.25 0.5 0 0 0 0 0
0 0 0 0 0 0 0 0 0 0.3
0.2 -0.3 0.4 0.1 0.25 -0.6 0.35 0.15 -0.2 0.45
0 0 0 0 0 0 0 0 0 0
B
"$G" versor exp --in "$d/biv" --out "$d/rot" || fail "versor exp"
[ "$(wc -l <"$d/rot")" -eq 7 ] && [ "$(awk '{ print NF }' "$d/rot" | sort -u)" = 32 ] ||
    fail "versor exp writes 32 numbers a line, one line per bivector"
"$G" versor log --in "$d/rot" --out "$d/biv2" || fail "versor log"
paste -d ' ' "$d/biv" "$d/biv2" | awk '{ for (i = 1; i <= 10; i++) { e = $i - $(i + 10)
    if (e < 0) e = -e; if (e > 1e-13) { printf "versor log(exp B) line %d: %g\n", NR, e; bad = 1 } } }
    END { exit bad }' || fail "versor: log(exp(B)) = B to 1e-13"
# -T and -exp(1e-6 e23) T (T the translation by e1: 1 - e14/2 - e15/2, R
# a turn of 2 pi - 2e-6 about e1 times T) have logs, a turn near pi beside
# the translation; the second was refused (its closed form missed R by
# 5.7e-4), like every rotor near a full turn times a translation
mv32 0=-1 8=0.5 9=0.5 >"$d/minus_t"
mv32 0=-0.9999999999995 10=-9.999999999998333e-07 8=0.49999999999975 9=0.49999999999975 \
    26=4.999999999999167e-07 27=4.999999999999167e-07 >>"$d/minus_t"
"$G" versor log --in "$d/minus_t" | "$G" versor exp | paste -d ' ' - "$d/minus_t" |
    awk '{ e = 0; for (i = 1; i <= 32; i++) { x = $i - $(i + 32); if (x < 0) x = -x; if (x > e) e = x }
        if (NF != 64 || e > 1e-15) { printf "exp(log(R)) line %d: error %g\n", NR, e; bad = 1 } }
        END { exit bad + (NR != 2) }' ||
    fail "versor log near a full turn beside a translation, and exp of it, gives R"
# the dilation exp(a e45) scales by e^(-2a) about the origin: (1, 2, 3) by e^0.8
printf '0 0 0 0 0 0 0 0 0 -0.4\n' | "$G" versor exp | awk '{ print $0, 1, 2, 3 }' >"$d/dil"
"$G" versor apply --in "$d/dil" | awk '{ k = exp(0.8); e = 0
    for (i = 1; i <= 3; i++) { x = $i - i * k; if (x < 0) x = -x; if (x > e) e = x }
    if (NF != 3 || e > 4e-15 * 3 * k) { printf "dilation: %s (error %g)\n", $0, e; exit 1 } }' ||
    fail "versor apply: a dilation by e^0.8"
# errors: counts, no rotor, no versor, a point at infinity, overflow, NaN
printf '0 0 0 0 0 0 0 0 0\n' >"$d/v9"
expect_error "versor exp: wrong count" "v9:1: expected 10 numbers (a bivector: e12 " \
    "$G" versor exp --in "$d/v9" --out "$d/out"
head -n 1 "$d/biv" >"$d/v10"
expect_error "versor log: wrong count" "v10:1: expected 32 numbers (a rotor" \
    "$G" versor log --in "$d/v10" --out "$d/out"
{ head -n 1 "$d/rot"; mv32 0=1; } >"$d/v32"
expect_error "versor apply: wrong count" "v32:1: expected 35 numbers (a versor (32 coefficients) then a point (3)), found 32" \
    "$G" versor apply --in "$d/v32" --out "$d/out"
{ head -n 1 "$d/rot"; mv32 0=2; } >"$d/notrotor"
expect_error "versor log: R ~R = 4" "notrotor:2: no real logarithm: not a rotor" \
    "$G" versor log --in "$d/notrotor" --out "$d/out"
mv32 1=1 >"$d/odd"
expect_error "versor log: an odd versor" "odd:1: no real logarithm: not a rotor" \
    "$G" versor log --in "$d/odd" --out "$d/out"
# 0.8 + 0.6 e1234 (R ~R = 1 + 0.96 e1234), and cos + sin e12 off unit norm by
# 3.2e-8 (the tolerance is 1e-9)
mv32 0=0.8 26=0.6 >"$d/quad"
mv32 0=0.6 6=0.80000002 >"$d/drift"
for f in quad drift; do
    expect_error "versor log: $f" "$f:1: no real logarithm" "$G" versor log --in "$d/$f" --out "$d/out"
done
{ head -n 1 "$d/rot"; mv32 0=0.6 6=0.8 | sed 's/^0.6 0/0.6 nan/'; } >"$d/vnan"
expect_error "versor log: NaN" "vnan:2: number 2 is not finite" "$G" versor log --in "$d/vnan" --out "$d/out"
printf '0 0 0 0 0 0 0 0 0 800\n' >"$d/huge"
expect_error "versor exp: cosh overflows" "huge:1: outside the domain" "$G" versor exp --in "$d/huge" --out "$d/out"
printf '%s 1 2 3\n' "$(mv32 0=1 1=1)" >"$d/mixed"
expect_error "versor apply: even and odd" "mixed:1: not a versor: it has both even and odd parts" \
    "$G" versor apply --in "$d/mixed" --out "$d/out"
printf '%s 1 2 3\n' "$(mv32)" >"$d/zero"
expect_error "versor apply: V = 0" "zero:1: not a versor: not invertible" \
    "$G" versor apply --in "$d/zero" --out "$d/out"
# the inversion in the unit sphere (the odd versor e4) sends the origin to infinity
printf '%s 1 1 1\n%s 0 0 0\n' "$(mv32 4=1)" "$(mv32 4=1)" >"$d/toinf"
expect_error "versor apply: the centre of an inversion" "toinf:2: the point goes to infinity" \
    "$G" versor apply --in "$d/toinf" --out "$d/out"
printf '%s 1 inf 3\n' "$(mv32 0=1)" >"$d/pinf"
expect_error "versor apply: an infinite point" "pinf:1: number 34 is not finite" \
    "$G" versor apply --in "$d/pinf" --out "$d/out"
expect_error "versor: no operation" "garotor versor: which one: exp, log or apply?" "$G" versor
expect_error "versor: unknown operation" "garotor versor: unknown operation 'sqrt' (exp, log or apply)" \
    "$G" versor sqrt

# ---- versor --text and object: multivectors with blade names -------------------
# to_text: a line of 10 (a bivector) or 32 numbers into a multivector written
# with blade names, every term kept (0 coefficients too: they add nothing);
# to_numbers: what the tool writes back into 32 numbers
names='1 e1 e2 e3 e4 e5 e12 e13 e14 e15 e23 e24 e25 e34 e35 e45 e123 e124 e125 e134 e135 e145 e234 e235 e245 e345 e1234 e1235 e1245 e1345 e2345 e12345'
to_text() {
    awk -v names="$names" 'BEGIN { split(names, nm, " ") }
        { off = NF == 10 ? 6 : 0; s = ""
          for (i = 1; i <= NF; i++) { b = nm[i + off]; x = $i; sg = "+"
              if (substr(x, 1, 1) == "-") { sg = "-"; x = substr(x, 2) }
              s = s (i > 1 ? " " sg " " : (sg == "-" ? "-" : "")) x (b == "1" ? "" : " " b) }
          print s }'
}
to_numbers() {
    awk -v names="$names" 'BEGIN { n = split(names, nm, " "); for (i = 1; i <= n; i++) ix[nm[i]] = i }
        { for (i = 1; i <= 32; i++) c[i] = 0
          line = $0; gsub(/ \+ /, " +", line); gsub(/ - /, " -", line)
          k = split(line, t, " ")
          for (j = 1; j <= k; j++) { w = t[j]; sg = 1
            if (substr(w, 1, 1) == "+") w = substr(w, 2); else if (substr(w, 1, 1) == "-") { sg = -1; w = substr(w, 2) }
            b = "1"; if (match(w, /e[1-5]+$/)) { b = substr(w, RSTART); w = substr(w, 1, RSTART - 1) }
            if (w == "") w = 1
            c[ix[b]] = (sg < 0 ? "-" : "") w }
          s = ""; for (i = 1; i <= 32; i++) s = s (i > 1 ? " " : "") c[i]; print s }'
}
# the same numbers, in text and as numbers, bit for bit: exp and log
to_text <"$d/biv" >"$d/biv.txt"
"$G" versor exp --text --in "$d/biv.txt" --out "$d/rot.txt" || fail "versor exp --text"
to_numbers <"$d/rot.txt" | sed 's/-0\( \|$\)/0\1/g' >"$d/rot.back"
cmp -s "$d/rot.back" "$d/rot" || fail "versor exp --text: not the numbers of versor exp: $(diff "$d/rot" "$d/rot.back" | head -4)"
"$G" versor log --text --in "$d/rot.txt" | to_numbers | cut -d ' ' -f 7-16 >"$d/biv2.back"
cmp -s "$d/biv2.back" "$d/biv2" || fail "versor log --text: not the numbers of versor log: $(diff "$d/biv2" "$d/biv2.back" | head -4)"
[ "$(echo '0.5e45' | "$G" versor exp --text)" = "1.1276259652063807 + 0.5210953054937474e45" ] ||
    fail "versor exp --text of 0.5e45"
[ "$(echo 'e4; 2 0 0' | "$G" versor apply --text)" = "0.5 0 0" ] || fail "versor apply --text: the inversion e4"
# written text reads back as the same multivector (ga_mv_format, ga_mv_parse)
"$G" object build --in "$d/rot.txt" | cmp -s - "$d/rot.txt" || fail "object build: text read back is the same text"
# objects: built, read back against Euclid (to 1e-14)
near() { # near NAME WANT: the numbers of standard input against WANT's, to 1e-14
    awk -v want="$2" -v name="$1" '{ n = split(want, w, " ")
        if (NF != n) { printf "%s: %s\n", name, $0; exit 1 }
        for (i = 1; i <= n; i++) { if (w[i] ~ /^[a-z_]+$/) { if ($i != w[i]) { printf "%s: %s\n", name, $0; exit 1 } continue }
            e = $i - w[i]; if (e < 0) e = -e; if (e > 1e-14 * (1 + (w[i] < 0 ? -w[i] : w[i]))) { printf "%s: %s\n", name, $0; exit 1 } } }' ||
        fail "object: $1"
}
cut3() { awk '{ print $1, $2, $4, $5, $6, $8, $9, $10, $12 }'; } # kind reality centre direction r2
echo 'sphere 1 2 3 0.5' | "$G" object read | cut3 | near "sphere C R" "sphere real 1 2 3 0 0 0 0.25"
echo 'sphere 1 0 0 -1 0 0 0 1 0 0 0 1' | "$G" object read | cut3 | near "sphere through 4 points" "sphere real 0 0 0 0 0 0 1"
echo 'plane 0 0 2 1' | "$G" object read | cut3 | near "plane M D" "plane real 0 0 0.5 0 0 1 0"
echo 'circle 1 0 0 0 1 0 -1 0 0' | "$G" object read | cut3 | near "circle" "circle real 0 0 0 0 0 1 1"
echo 'line 1 2 3 2 2 3' | "$G" object read | cut3 | near "line" "line real 0 2 3 1 0 0 0"
echo 'pair 0 0 0 2 0 0' | "$G" object read | cut3 | near "pair" "pair real 1 0 0 1 0 0 1"
echo 'point 1 2 3' | "$G" object read | cut3 | near "point" "sphere tangent 1 2 3 0 0 0 0"
echo 'sphere 0 0 0 1; sphere 1.5 0 0 1' | "$G" object meet | "$G" object read | cut3 |
    near "meet of two spheres" "circle real 0.75 0 0 -1 0 0 0.4375"
echo 'line 0 0 0 1 0 0; line 0 0 0 0 1 0' | "$G" object meet-rel | "$G" object read | cut3 |
    near "meet-rel of two lines through the origin" "flatpoint real 0 0 0 0 0 0 0"
echo 'line 0 0 0 1 0 0; line 0 0 0 0 1 0' | "$G" object join | "$G" object read | cut3 |
    near "join of two lines through the origin" "plane real 0 0 0 0 0 -1 0"
[ "$(echo 'line 0 0 0 1 0 0; line 0 0 0 0 1 0' | "$G" object meet)" = 0 ] || fail "object meet: 0 in special position"
echo 'translation 100 0 0; sphere 1 2 3 0.5' | "$G" object move | "$G" object read | cut3 |
    near "move by a translation" "sphere real 101 2 3 0 0 0 0.25"
echo 'translation 1e6 0 0; plane 1 2 3 0.5' | "$G" object move | "$G" object read | cut3 |
    near "move a plane by a translation" "plane real 71428.607142857143 142857.21428571429 214285.82142857143 0.2672612419124244 0.5345224838248488 0.8017837257372732 0"
echo 'rotation 0 0 1 1.5707963267948966; line 1 0 0 1 0 1' | "$G" object move | "$G" object read | cut3 |
    awk '{ printf "%s %s %.15f %.15f %.15f %s %s %s %s\n", $1, $2, $3, $4, $5, $6, $7, $8, $9 }' |
    near "move by a rotation" "line real 0.000000000000000 1.000000000000000 0.000000000000000 0 0 1 0"
# the rotor between circles of radii 1 and 2: it moves A onto B
echo 'circle 1 0 0 0 1 0 -1 0 0; circle 3 2 1 3 4 3 3 2 5' >"$d/ab"
"$G" object between --in "$d/ab" --out "$d/V" || fail "object between"
printf '%s; circle 1 0 0 0 1 0 -1 0 0\n' "$(cat "$d/V")" | "$G" object move | "$G" object read | cut3 |
    near "between two circles, then move" "circle real 3 2 3 1 0 0 4"
echo 'sphere 0 0 0 1; sphere 0 0 0 4; 0.5' | "$G" object interp | "$G" object read | cut3 |
    near "interp of spheres: the radius geometric" "sphere real 0 0 0 0 0 0 4"
echo 'plane 0 0 1 0; plane 0 0 1 2; 0.25' | "$G" object interp | "$G" object read | cut3 |
    near "interp of planes" "plane real 0 0 0.5 0 0 1 0"
# errors, with the line and the column
printf 'e1\n1 + 2e21\n' >"$d/t21"
expect_error "text: a name not canonical" "t21:2:5: '2e21' is not a term of a multivector" "$G" object build --in "$d/t21" --out "$d/out"
printf '1 +\n' >"$d/tsign"
expect_error "text: a sign alone" "tsign:1:3: '+' with no term after it" "$G" object build --in "$d/tsign" --out "$d/out"
printf 'e1 + 1e+400e2\n' >"$d/tbig"
expect_error "text: beyond a double" "tbig:1:6: '1e+400e2': a number beyond the range of a double" "$G" object build --in "$d/tbig" --out "$d/out"
printf '1e+308 + 1e+308\n' >"$d/tsum"
expect_error "text: a sum beyond a double" "tsum:1:1: not a multivector: its terms add up beyond the range of a double" "$G" object build --in "$d/tsum" --out "$d/out"
printf ' ; e1\n' >"$d/tnone"
expect_error "text: an empty field" "tnone:1:2: no multivector here" "$G" object meet --in "$d/tnone" --out "$d/out"
printf 'e1; e2\n' >"$d/tfields"
expect_error "object: too many fields" "tfields:1:3: too many fields: at most 1, separated by ';'" "$G" object read --in "$d/tfields" --out "$d/out"
printf 'e1\n' >"$d/tone"
expect_error "object: too few fields" "tone:1:1: expected 2 fields separated by ';' (A; B), found 1" "$G" object join --in "$d/tone" --out "$d/out"
printf '  spere 0 0 0 1\n' >"$d/tword"
expect_error "object: unknown constructor" "tword:1:3: unknown object 'spere'" "$G" object build --in "$d/tword" --out "$d/out"
printf 'sphere 0 0 1\n' >"$d/tcount"
expect_error "object: numbers of a sphere" "tcount:1:1: expected 12 or 4 numbers after 'sphere' (four points, or a centre and a radius), found 3" \
    "$G" object build --in "$d/tcount" --out "$d/out"
printf 'point 0 0\n' >"$d/tcount1"
expect_error "object: numbers of a point" "tcount1:1:1: expected 3 numbers after 'point' (x y z), found 2" \
    "$G" object build --in "$d/tcount1" --out "$d/out"
printf 'point 0 x 0\n' >"$d/tnan"
expect_error "object: not a number" "tnan:1:9: 'x' is not a number" "$G" object build --in "$d/tnan" --out "$d/out"
printf 'point 0 2x 0\n' >"$d/tjunk"
expect_error "object: junk" "tjunk:1:10: junk after number 2" "$G" object build --in "$d/tjunk" --out "$d/out"
printf 'point 0 inf 0\n' >"$d/tinf"
expect_error "object: inf" "tinf:1:9: number 2 is not finite" "$G" object build --in "$d/tinf" --out "$d/out"
printf 'point 0,,0 0\n' >"$d/tcomma"
expect_error "object: empty field" "tcomma:1:9: empty field after number 1" "$G" object build --in "$d/tcomma" --out "$d/out"
printf 'point ,0 0 0\n' >"$d/tcomma0"
expect_error "object: empty field first" "tcomma0:1:7: empty field before number 1" "$G" object build --in "$d/tcomma0" --out "$d/out"
printf 'sphere 0 0 0 -1\n' >"$d/tneg"
expect_error "object: a negative radius" "tneg:1:1: sphere: the radius must be >= 0, not -1" "$G" object build --in "$d/tneg" --out "$d/out"
printf 'plane 0 0 0 1\n' >"$d/tnorm"
expect_error "object: a plane's zero normal" "tnorm:1:1: plane: the normal is 0" "$G" object build --in "$d/tnorm" --out "$d/out"
printf 'dilation 0 0 0 0; e1\n' >"$d/tdil"
expect_error "object: a dilation by 0" "tdil:1:1: dilation: the factor must be > 0, not 0" "$G" object move --in "$d/tdil" --out "$d/out"
printf 'point 1e200 0 0\n' >"$d/tover"
expect_error "object: a point that overflows" "tover:1:1: point: outside the domain" "$G" object build --in "$d/tover" --out "$d/out"
printf 'sphere 0 0 0 1; plane 0 0 1 0\n' >"$d/tmeet"
"$G" object meet --in "$d/tmeet" | "$G" object read >/dev/null || fail "object: a sphere's meet with a plane reads back"
printf 'line 0 0 0 1 0 0; line 0 0 0 0 1 0\n' >"$d/tzero"
"$G" object meet --in "$d/tzero" --out "$d/tzero.mv" || fail "object meet in special position"
expect_error "object read: 0" "tzero.mv:1:1: 0 is no object" "$G" object read --in "$d/tzero.mv" --out "$d/out"
printf '1 + e1\n' >"$d/tmixed"
expect_error "object read: mixed grades" "tmixed:1:1: not an object: not an object of the expected kind" "$G" object read --in "$d/tmixed" --out "$d/out"
printf '2; e1\n' >"$d/tjoin"
expect_error "object join: a scalar" "tjoin:1:1: join: outside the domain" "$G" object join --in "$d/tjoin" --out "$d/out"
printf 'e1 + e12; e1\n' >"$d/tmove"
expect_error "object move: even and odd" "tmove:1:1: not a versor: it has both even and odd parts" "$G" object move --in "$d/tmove" --out "$d/out"
printf '0; e1\n' >"$d/tmove0"
expect_error "object move: V = 0" "tmove0:1:1: not a versor: not invertible" "$G" object move --in "$d/tmove0" --out "$d/out"
printf 'sphere 0 0 0 1; circle 1 0 0 0 1 0 -1 0 0\n' >"$d/tkinds"
expect_error "object between: kinds" "tkinds:1:1: no rotor takes a sphere to a circle: the kinds differ" "$G" object between --in "$d/tkinds" --out "$d/out"
printf 'sphere 0 0 0 1; point 1 1 1\n' >"$d/tpoint"
expect_error "object between: a point and a sphere" "tpoint:1:1: no rotor takes a point (radius 0) to a round of radius > 0" \
    "$G" object between --in "$d/tpoint" --out "$d/out"
echo 'sphere 0 0 0 1; sphere 3 0 0 1' | "$G" object meet >"$d/imag"
printf '%s; circle 1 0 0 0 1 0 -1 0 0\n' "$(cat "$d/imag")" >"$d/timag"
expect_error "object between: imaginary" "timag:1:1: no rotor from A to B: an imaginary object" "$G" object between --in "$d/timag" --out "$d/out"
printf 'sphere 0 0 0 1; sphere 0 0 0 2; x\n' >"$d/tt"
expect_error "object interp: t" "tt:1:33: 'x' is not a number" "$G" object interp --in "$d/tt" --out "$d/out"
printf 'sphere 0 0 0 1; sphere 0 0 0 2; 1 2\n' >"$d/tt2"
expect_error "object interp: two t" "tt2:1:33: expected 1 number (t: 0 is A, 1 is B), found 2" "$G" object interp --in "$d/tt2" --out "$d/out"
expect_error "object: no operation" "garotor object: which one: build, read, meet, join, meet-rel, move, between or interp?" "$G" object
expect_error "object: unknown operation" "garotor object: unknown operation 'cut' (build, read, meet, join, meet-rel, move, between or interp)" \
    "$G" object cut
printf 'e4\n' >"$d/tapply"
expect_error "versor apply --text: no point" "tapply:1:3: expected a versor, ';', then a point (x y z): 'e4; 2 0 0'" \
    "$G" versor apply --text --in "$d/tapply" --out "$d/out"
printf 'e4; 2 0\n' >"$d/tapply2"
expect_error "versor apply --text: two numbers" "tapply2:1:5: expected 3 numbers (a point x y z) after ';', found 2" \
    "$G" versor apply --text --in "$d/tapply2" --out "$d/out"
printf '0.5e45 + e1\n' >"$d/texp"
expect_error "versor exp --text: no bivector" "texp:1:1: not a bivector: it has a part of grade 1" "$G" versor exp --text --in "$d/texp" --out "$d/out"
printf '2\n' >"$d/tlog"
expect_error "versor log --text: no rotor" "tlog:1:1: no real logarithm: not a rotor" "$G" versor log --text --in "$d/tlog" --out "$d/out"
expect_error "--text with exp" "garotor exp: unknown option: --text: an option of garotor versor, not of exp" "$G" exp --text

# --help of every command exits 0 and names it
for c in demo exp log interp versor object; do
    "$G" "$c" --help | grep -q "usage: garotor" || fail "$c --help"
done

# ---- hostile input and environment: the reader, output, signals, hints -----
# shellcheck source=tests/tool_input_test.sh
. "$(dirname "$0")/tool_input_test.sh"

# ---- every message of docs/tool.md's error table was produced above ---------
# A row's first code span is the message; {...} stands for any text.
if [ -f "$doc" ]; then
    awk '
    function regex(t,   r, i, c, inbrace) {
        r = "^"
        for (i = 1; i <= length(t); i++) {
            c = substr(t, i, 1)
            if (inbrace) { if (c == "}") { inbrace = 0; r = r ".*" } continue }
            if (c == "{") { inbrace = 1; continue }
            if (index("\\^$.|?*+()[]/", c)) r = r "\\" c; else r = r c
        }
        return r "$"
    }
    FNR == NR {
        if ($0 ~ /<!-- errors -->/) on = 1
        else if ($0 ~ /<!-- \/errors -->/) on = 0
        else if (on && $0 ~ /^\| `/) {
            t = $0; sub(/^\| `/, "", t); sub(/`.*/, "", t); gsub(/\\\|/, "|", t)
            n++; msg[n] = t; re[n] = regex(t)
        }
        next
    }
    { for (i = 1; i <= n; i++) if ($0 ~ re[i]) hit[i] = 1 }
    END {
        if (n < 30) { print "FAIL: only " n " rows read from the error table of docs/tool.md"; bad = 1 }
        for (i = 1; i <= n; i++) if (!hit[i]) { print "FAIL: no case produces: " msg[i]; bad = 1 }
        exit bad
    }' "$doc" "$d/all_stderr" || fails=$((fails + 1))
else
    fail "$doc is missing"
fi

[ "$fails" -eq 0 ] && echo "tool_test: all passed"
exit $((fails > 0))
