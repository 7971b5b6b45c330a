#!/bin/sh
# A robot's pose log in the TUM format (t tx ty tz qx qy qz qw), resampled by
# garotor interp --normalize --rate 100 --with velocity,acceleration, and
# checked from outside. The log is made here by a seeded awk script (no
# Python needed): 64 keys at about 30 Hz with jitter, epoch stamps with 4
# decimals from 1305031102.1758 (every 8th key on the 100 Hz grid), positions
# and quaternions rounded to 4 decimals (norms off by up to 7.8e-5), the sign
# of q flipped on about 30% of the keys, a stretch of 8 keys with one rotation
# (pure translation), and a key 5e-4 short of a half turn (qw = 0.0003). For
# each scheme that hits its keys (screw, lihao3, decoupled-c2, and c2 when the
# tool has it):
#   1. keys hit: the samples at the keys' times (--times) are the normalised
#      keys (q up to sign) to 1e-15, stamped as the keys were written;
#   2. derivatives: at 0.37 of every segment, the velocity against central
#      differences of the poses (h = 1e-5 s), the acceleration against central
#      differences of the velocity (see "the bound" below); screw's body
#      acceleration is zero inside a segment; at the interior keys the
#      quantities the scheme makes continuous are (their jump over +-1e-7 s a
#      tenth of that over +-1e-6 s): screw none, lihao3 the velocity,
#      decoupled-c2 (and c2) the velocity and acceleration;
#   3. shifting every stamp to start at 0 (the first stamp subtracted exactly
#      in the decimal text) changes no sample by more than 1e-12 relative, the
#      computed stamps differ by exactly the shift, and the samples at keys on
#      the 100 Hz grid are stamped as those keys were written (0.2600, not 0.26).
# The worst figures are printed, one line each. With --log [1] instead of
# the tool, the script prints the log (1: stamped from 0) and exits.
set -u
G=$1
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# ---- the log: a Park-Miller generator, so every awk makes the same file ----
# shifted=1: the same keys stamped from 0.0000 (the offsets, in 1e-4 s)
gen() {
    awk -v shifted="$1" '
    function rnd() { seed = (seed * 16807) % 2147483647; return seed / 2147483647 }
    function stamp(u,   i) { i = int(u / 10000); return sprintf("%d.%04d", i, u - i * 10000) }
    BEGIN {
        seed = 20110507; T0 = 13050311021758; n = 64
        for (k = 1; k < n; k++) {                 # 1/30 s +- 4 ms, in 1e-4 s
            u[k] = u[k - 1] + 333 + int(rnd() * 81) - 40
            if (k % 8 == 0) u[k] = int(u[k] / 100 + 0.5) * 100   # on the 100 Hz grid
        }
        cut = (u[27] - u[20]) / 10000              # keys 20..27: one rotation
        for (k = 0; k < n; k++) {
            t = u[k] / 10000
            r = k < 20 ? t : (k <= 27 ? u[20] / 10000 : t - cut)
            th = 3.14109 + 1.5 * (r - (u[44] / 10000 - cut))   # key 44: pi - 5e-4
            ax = sin(0.7 * r); ay = 0.4; az = cos(0.5 * r); an = sqrt(ax * ax + ay * ay + az * az)
            s = sin(th / 2) / an; qx = ax * s; qy = ay * s; qz = az * s; qw = cos(th / 2)
            if (rnd() < 0.3) { qx = -qx; qy = -qy; qz = -qz; qw = -qw }
            x = 0.8 * sin(1.3 * t) + 0.002 * (rnd() - 0.5); y = 0.5 * cos(0.9 * t); z = 0.3 * t
            printf "%s %.4f %.4f %.4f %.4f %.4f %.4f %.4f\n", stamp(shifted ? u[k] : T0 + u[k]),
                   x, y, z, qx, qy, qz, qw
        }
    }'
}
# tests/tum_check.sh --log [shifted]: print the log (0: epoch stamps, 1: from 0)
if [ "$G" = --log ]; then
    gen "${2:-0}"
    exit 0
fi
gen 0 >"$d/keys"
gen 1 >"$d/keys0"
# the file is what it should be: norms off by up to 1e-4, the flips, the half turn
awk '{ n = sqrt($5 * $5 + $6 * $6 + $7 * $7 + $8 * $8); e = n > 1 ? n - 1 : 1 - n; if (e > m) m = e
       if ($8 < 0) neg++; if ($8 > -0.001 && $8 < 0.001) half++ }
     END { printf "tum_check: %d keys, quaternion norms off by up to %.2g, %d with qw < 0, %d with |qw| < 1e-3\n",
                  NR, m, neg, half
           exit !(NR == 64 && m > 5e-5 && m < 1e-4 && neg >= 10 && half == 1) }' "$d/keys" ||
    fail "the generated log is not as described"

schemes="screw lihao3 decoupled-c2"
printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n' >"$d/two"
"$G" interp --scheme c2 --format pose --in "$d/two" --samples 2 >/dev/null 2>&1 && schemes="$schemes c2"

interp() { # interp SCHEME KEYS OUT ARGS...
    s=$1 k=$2 o=$3
    shift 3
    "$G" interp --scheme "$s" --format pose --normalize --with velocity,acceleration --in "$k" --out "$o" "$@" \
        2>"$d/err" || fail "interp --scheme $s $*: $(cat "$d/err")"
}

# times as decimal text: stamp T (1e-4 s units, as in the file) plus D units of 10^-P s
at_times() { # at_times P awk-program-printing-"key offset" pairs < keys
    awk -v P="$1" "function pt(s, off,   a, i, f, m) { split(s, a, \".\"); m = 10 ^ (P - 4)
        i = a[1]; f = a[2] * m + off; while (f < 0) { f += 10 ^ P; i-- } while (f >= 10 ^ P) { f -= 10 ^ P; i++ }
        printf \"%d.%0\" P \"d\\n\", i, f } $2"
}

# ---- 1. keys hit ----
cut -d ' ' -f 1 "$d/keys" >"$d/keytimes"
for s in $schemes; do
    interp "$s" "$d/keys" "$d/hit.$s" --times "$d/keytimes"
    paste -d ' ' "$d/hit.$s" "$d/keys" | awk -v s="$s" '
        function abs(x) { return x < 0 ? -x : x }
        { n = sqrt($25 * $25 + $26 * $26 + $27 * $27 + $28 * $28); e = 0; ep = 0; em = 0
          for (i = 2; i <= 4; i++) if (abs($i - $(i + 20)) > e) e = abs($i - $(i + 20))
          for (i = 5; i <= 8; i++) { if (abs($i - $(i + 20) / n) > ep) ep = abs($i - $(i + 20) / n)
                                     if (abs($i + $(i + 20) / n) > em) em = abs($i + $(i + 20) / n) }
          e = e > (ep < em ? ep : em) ? e : (ep < em ? ep : em); if (e > m) m = e
          if ($1 != $21) { printf "%s: the sample at %s is stamped %s\n", s, $21, $1; bad = 1 } }
        END { printf "tum_check: keys hit, %s: %d keys, worst |sample - normalised key| %.3g (bound 1e-15)\n", s, NR, m
              exit bad || NR != 64 || m > 1e-15 }' || fail "$s: the samples at the keys are not the normalised keys"
done

# ---- 2. velocity and acceleration against finite differences ----
# At t = 0.37 of each segment, in microseconds, the 5 times t - 2h .. t + 2h,
# h = 1e-5 s. D_h is the central difference over +-h, D_2h over +-2h. The
# velocity V (body: N^-1 dN/dt, so w = 2 Im(q* dq/dt), v = R^T dp/dt) is
# checked against D_h of the poses, the acceleration against D_h of V.
# The bound: D_h's error is h^2/6 f''' + O(h^4) plus rounding, and
# D_2h - D_h = 3 h^2/6 f''' + O(h^4) (Richardson), so |V - D_h| may be at
# most |D_2h - D_h| (three times the truncation error D_h has) plus the
# rounding of the differences: 1e-10 for the velocity (poses of size <= 1
# accurate to a few 1e-16, over 2h = 2e-5), 1e-9 for the acceleration
# (velocities of size <= 10). Also |V - D_h| <= 1e-6 and |A - D_h| <= 1e-5
# outright. A velocity off by 1e-6 of itself fails.
at_times 6 '{ split($1, a, "."); v[NR] = a[2] * 100; s[NR] = $1 }
    END { for (i = 1; i < NR; i++) { l = v[i + 1] - v[i]; if (l < 0) l += 1e6
          for (j = -2; j <= 2; j++) pt(s[i], int(l * 0.37) + 10 * j) } }' <"$d/keys" >"$d/fdtimes"
for s in $schemes; do
    interp "$s" "$d/keys" "$d/fd.$s" --times "$d/fdtimes"
    awk -v s="$s" -v h=1e-5 '
    function abs(x) { return x < 0 ? -x : x }
    function bodyvel(a, b, hh, c,   sa, sb, i, d) { # D of rows a, b (+-hh) at row c
        sa = Q[a,1] * Q[c,1] + Q[a,2] * Q[c,2] + Q[a,3] * Q[c,3] + Q[a,4] * Q[c,4] < 0 ? -1 : 1
        sb = Q[b,1] * Q[c,1] + Q[b,2] * Q[c,2] + Q[b,3] * Q[c,3] + Q[b,4] * Q[c,4] < 0 ? -1 : 1
        for (i = 1; i <= 4; i++) d[i] = (sb * Q[b,i] - sa * Q[a,i]) / (2 * hh)
        x = Q[c,1]; y = Q[c,2]; z = Q[c,3]; w = Q[c,4]
        B[1] = 2 * (w * d[1] - d[4] * x - (y * d[3] - z * d[2]))
        B[2] = 2 * (w * d[2] - d[4] * y - (z * d[1] - x * d[3]))
        B[3] = 2 * (w * d[3] - d[4] * z - (x * d[2] - y * d[1]))
        for (i = 1; i <= 3; i++) p[i] = (P[b,i] - P[a,i]) / (2 * hh)
        # R^T p: p rotated by the quaternion (-x, -y, -z, w)
        tx = -2 * (y * p[3] - z * p[2]); ty = -2 * (z * p[1] - x * p[3]); tz = -2 * (x * p[2] - y * p[1])
        B[4] = p[1] + w * tx - (y * tz - z * ty); B[5] = p[2] + w * ty - (z * tx - x * tz)
        B[6] = p[3] + w * tz - (x * ty - y * tx)
    }
    { r = (NR - 1) % 5 + 1
      for (i = 1; i <= 3; i++) P[r,i] = $(i + 1)
      for (i = 1; i <= 4; i++) Q[r,i] = $(i + 4)
      for (i = 1; i <= 6; i++) { V[r,i] = $(i + 8); A[r,i] = $(i + 14) }
      if (r < 5) next
      bodyvel(2, 4, h, 3); for (i = 1; i <= 6; i++) D1[i] = B[i]
      bodyvel(1, 5, 2 * h, 3); for (i = 1; i <= 6; i++) D2[i] = B[i]
      ev = 0; rv = 0; ea = 0; ra = 0
      for (i = 1; i <= 6; i++) {
          if (abs(V[3,i] - D1[i]) > ev) ev = abs(V[3,i] - D1[i])
          if (abs(D2[i] - D1[i]) > rv) rv = abs(D2[i] - D1[i])
          a1 = (V[4,i] - V[2,i]) / (2 * h); a2 = (V[5,i] - V[1,i]) / (4 * h)
          if (abs(A[3,i] - a1) > ea) ea = abs(A[3,i] - a1)
          if (abs(a2 - a1) > ra) ra = abs(a2 - a1)
          if (s == "screw" && A[3,i] != 0) { printf "screw: body acceleration %s inside segment %d\n", A[3,i], NR / 5; bad = 1 }
      }
      if (ev > rv + 1e-10 || ev > 1e-6) { printf "%s, segment %d: |V - D_h| = %.3g, |D_2h - D_h| = %.3g\n", s, NR / 5, ev, rv; bad = 1 }
      if (ea > ra + 1e-9 || ea > 1e-5) { printf "%s, segment %d: |A - D_h V| = %.3g, |D_2h V - D_h V| = %.3g\n", s, NR / 5, ea, ra; bad = 1 }
      if (ev > mv) mv = ev; if (ea > ma) ma = ea; if (rv > mrv) mrv = rv; if (ra > mra) mra = ra }
    END { printf "tum_check: derivatives, %s: %d segments, worst |V - D_h| %.3g (|D_2h - D_h| up to %.3g), worst |A - D_h V| %.3g (|D_2h V - D_h V| up to %.3g)\n",
                 s, NR / 5, mv, mrv, ma, mra
          exit bad || NR != 315 }' "$d/fd.$s" || fail "$s: velocity or acceleration against finite differences"
done
# continuity at the 62 interior keys: jumps over +-1e-6 s and +-1e-7 s
at_times 7 'NR > 1 && NR < 64 { pt($1, -10); pt($1, 10) }' <"$d/keys" >"$d/j6"
at_times 7 'NR > 1 && NR < 64 { pt($1, -1); pt($1, 1) }' <"$d/keys" >"$d/j7"
for s in $schemes; do
    case $s in screw) cont=0 ;; lihao3) cont=1 ;; *) cont=2 ;; esac
    interp "$s" "$d/keys" "$d/j6.$s" --times "$d/j6"
    interp "$s" "$d/keys" "$d/j7.$s" --times "$d/j7"
    awk -v s="$s" -v cont="$cont" '
        function abs(x) { return x < 0 ? -x : x }
        { for (i = 9; i <= 20; i++) x[NR % 2, i] = $i }
        NR % 2 == 0 { for (i = 9; i <= 20; i++) { e = abs(x[0,i] - x[1,i]); k = i < 15 ? "V" : "A"
                      if (e > J[FILENAME == ARGV[1], k]) J[FILENAME == ARGV[1], k] = e } }
        END { printf "tum_check: at the keys, %s: worst jump over +-1e-6 s / +-1e-7 s: velocity %.3g / %.3g, acceleration %.3g / %.3g\n",
                     s, J[1,"V"], J[0,"V"], J[1,"A"], J[0,"A"]
              # continuous: a tenth; not: the same within a few percent
              if (cont >= 1) bad = J[0,"V"] > 0.11 * J[1,"V"]; else bad = J[0,"V"] < 0.9 * J[1,"V"] || J[1,"V"] < 0.1
              if (cont >= 2) bad = bad || J[0,"A"] > 0.11 * J[1,"A"]
              else if (cont == 1) bad = bad || J[0,"A"] < 0.9 * J[1,"A"] || J[1,"A"] < 1
              exit bad }' "$d/j6.$s" "$d/j7.$s" || fail "$s: continuity at the keys"
done

# ---- 3. stamps shifted to 0 ----
for s in $schemes; do
    interp "$s" "$d/keys" "$d/r.$s" --rate 100
    interp "$s" "$d/keys0" "$d/r0.$s" --rate 100
    paste -d ' ' "$d/r.$s" "$d/r0.$s" | awk -v s="$s" '
        function abs(x) { return x < 0 ? -x : x }
        function units(t,   a, f) { # t in 1e-4 s, exactly (the stamps have at most 4 decimals)
            if (split(t, a, ".") == 1) a[2] = ""
            f = a[2]; while (length(f) < 4) f = f "0"
            if (t !~ /^[0-9]+(\.[0-9]+)?$/ || length(a[2]) > 4) { printf "%s: stamp %s\n", s, t; bad = 1 }
            return a[1] * 10000 + f }
        { for (i = 2; i <= 20; i++) { e = abs($i - $(i + 20)); m = abs($i) > abs($(i + 20)) ? abs($i) : abs($(i + 20))
              if (e > 1e-12 * m) { printf "%s: %s and %s differ in column %d: %s %s\n", s, $1, $21, i, $i, $(i + 20); bad = 1 }
              if (m > 0 && e / m > w) w = e / m }
          if (units($1) - 13050311021758 != units($21)) { printf "%s: stamps %s and %s\n", s, $1, $21; bad = 1 }
          if (units($21) != 100 * (NR - 1)) { printf "%s: sample %d stamped %s\n", s, NR, $21; bad = 1 } }
        END { printf "tum_check: shifted to 0, %s: %d samples, worst relative difference %.3g (bound 1e-12)\n", s, NR, w
              exit bad || NR != 209 }' || fail "$s: shifting the stamps changes the samples"
    # the keys on the 100 Hz grid: the sample at each is stamped as the key was written
    for k in keys keys0; do
        r=$([ $k = keys ] && echo r || echo r0)
        awk -v s="$s" 'NR == FNR { split($1, a, "."); v = a[1] * 10000 + a[2]; if (FNR == 1) v0 = v
                                   if ((v - v0) % 100 == 0) want[(v - v0) / 100 + 1] = $1; next }
            FNR in want { if ($1 != want[FNR]) { printf "%s: the key %s is stamped %s\n", s, want[FNR], $1; bad = 1 }
                          n++ }
            END { exit bad || n != 8 }' "$d/$k" "$d/$r.$s" || fail "$s: the samples at the keys on the grid ($k)"
    done
done
# the shifted stamps do test the text: 0.2600 is not how 0.26 is written
grep -q '^0\.2600 ' "$d/r0.screw" || fail "the key 0.2600 is not on the grid"

[ "$fails" -eq 0 ] && echo "tum_check: all passed"
exit $((fails > 0))
