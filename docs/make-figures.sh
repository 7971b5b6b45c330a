#!/bin/sh
# docs/make-figures.sh: regenerate every figure of docs/ with the garotor tool.
#
#   sh docs/make-figures.sh [GAROTOR [OUTDIR]]
#
# GAROTOR is the built tool (default: build/garotor beside docs/), OUTDIR where
# the figures go (default: docs/figures). The inputs are the committed files
# docs/figures/*.keys, *.twist and *.csv (but ros-gt.csv and ros-est.csv,
# written here with docs/ros-export.awk); everything else is computed here by
# garotor (exp, log, interp --svg) and a little POSIX awk, and the pictures of
# the conformal model (cga-*.svg) by docs/examples/figures.c, which the build
# compiles beside the tool as conformal-figures. It takes well under a second. tests/figures_test.sh runs it into a temporary directory and checks
# that the result is byte for byte what is committed.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
src=$here/figures
G=${1:-$here/../build/garotor}
out=${2:-$src}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# ---- Wareham-Lasenby Fig. 5: piecewise linear (screw) against quadratic ----
for s in screw quadratic; do
    "$G" interp --scheme "$s" --format pose --samples 101 --in "$src/wl-fig5.keys" \
        --out "$tmp/samples" --svg "$out/wl-fig5-$s.svg"
done

# ---- Wareham-Lasenby Fig. 7: the helix exp(lambda B), 0 <= lambda <= 1 ------
# psi = 9 pi is 4.5 turns, more than one principal log can hold, so the keys
# are exp(k/12 xi), k = 0..12 (3/4 pi apart), and the screw scheme through
# them, which is exp(lambda xi) exactly; the keys lie on one screw, so the
# picture shows its axis.
grep -v '^#' "$src/wl-fig7.twist" |
    awk '{ for (k = 0; k <= 12; k++) { for (i = 1; i <= 6; i++)
               printf "%.17g%s", $i * k / 12, (i < 6 ? " " : "\n") } }' >"$tmp/twists"
"$G" exp --in "$tmp/twists" --out "$tmp/motions"
awk '{ printf "%.17g %s\n", (NR - 1) / 12, $0 }' "$tmp/motions" >"$tmp/helix.keys"
"$G" interp --scheme screw --samples 1201 --in "$tmp/helix.keys" --out "$tmp/samples" \
    --svg "$out/wl-fig7-helix.svg"

# ---- Li-Hao Fig. 3: quadratic (lihao2) against cubic (lihao3), four keys ----
# The velocities of Li-Hao's table, with A = I: log(A^-1 B) = log B, ...
# rel A B: the matrix A^-1 B of two rigid motions (16 numbers each).
rel() {
    awk -v a="$1" -v b="$2" 'BEGIN { split(a, p, " "); split(b, q, " ")
        for (i = 0; i < 3; i++) { for (j = 0; j < 4; j++) { s = 0
            for (k = 0; k < 3; k++) s += p[4 * k + i + 1] * (q[4 * k + j + 1] - (j == 3 ? p[4 * k + 4] : 0))
            printf "%.17g ", s }
        } print "0 0 0 1" }'
}
grep -v '^#' "$src/lihao-fig3.keys" | awk 'NF' |
    awk '{ m = $2; for (i = 3; i <= 17; i++) m = m " " $i; print m }' >"$tmp/abcd"
A=$(sed -n 1p "$tmp/abcd") B=$(sed -n 2p "$tmp/abcd") C=$(sed -n 3p "$tmp/abcd") D=$(sed -n 4p "$tmp/abcd")
{ rel "$A" "$B"; rel "$A" "$C"; rel "$B" "$D"; rel "$C" "$D"; } >"$tmp/rel"
"$G" log --in "$tmp/rel" --out "$tmp/logs" # log(A^-1 B), log(A^-1 C), log(B^-1 D), log(C^-1 D)
scaled() { # scaled LINE FACTOR: that log times the factor
    awk -v n="$1" -v f="$2" 'NR == n { for (i = 1; i <= 6; i++) printf "%.17g%s", f * $i, (i < 6 ? " " : "\n") }' "$tmp/logs"
}
lihao() { # lihao PANEL OPTIONS...
    panel=$1
    shift
    "$G" interp --samples 151 --in "$src/lihao-fig3.keys" --out "$tmp/samples" \
        --svg "$out/lihao-fig3$panel.svg" "$@"
}
# shellcheck disable=SC2046 # --v0 takes six words
lihao a --scheme lihao2 --v0 $(scaled 2 0.9)
# shellcheck disable=SC2046
lihao b --scheme lihao2 --v0 $(scaled 2 -0.9)
lihao c --scheme lihao2 # the default first velocity, log(A^-1 B)
{ scaled 1 0.33333333333333333; scaled 2 0.33333333333333333
  scaled 3 0.33333333333333333; scaled 4 0.33333333333333333; } >"$tmp/vel-d"
lihao d --scheme lihao3 --velocities "$tmp/vel-d"
{ scaled 1 0.33333333333333333; scaled 2 -0.33333333333333333
  scaled 3 -0.33333333333333333; scaled 4 0.33333333333333333; } >"$tmp/vel-e"
lihao e --scheme lihao3 --velocities "$tmp/vel-e"
printf '0 0 0 0 0 0\n0 0 0 0 0 0\n0 0 0 0 0 0\n0 0 0 0 0 0\n' >"$tmp/vel-f"
lihao f --scheme lihao3 --velocities "$tmp/vel-f"

# ---- Li-Hao Fig. 5: the Euler error against the step, log-log --------------
# The cubic path of Fig. 3d, 61 samples; the error of a step H is the largest
# difference of a matrix entry between --eval euler --step H and --eval direct.
"$G" interp --scheme lihao3 --velocities "$tmp/vel-d" --samples 61 \
    --in "$src/lihao-fig3.keys" --out "$tmp/direct"
: >"$tmp/errors"
for k in 2 3 4 5 6 7 8 9 10 11 12 13 14; do
    h=$(awk -v k="$k" 'BEGIN { printf "%.17g", 2 ^ -k }')
    "$G" interp --scheme lihao3 --velocities "$tmp/vel-d" --samples 61 --eval euler --step "$h" \
        --in "$src/lihao-fig3.keys" --out "$tmp/euler"
    paste -d ' ' "$tmp/direct" "$tmp/euler" | awk -v h="$h" '
        { for (i = 2; i <= 17; i++) { e = $i - $(i + 17); if (e < 0) e = -e; if (e > m) m = e } }
        END { printf "%.6g %.6g\n", h, m }' >>"$tmp/errors"
done
{ echo "# Li-Hao Fig. 5: the generalized Euler error of the cubic path of Fig. 3d"
  echo "# step H (u units)   largest |M_euler - M_direct| entry, 61 samples"
  cat "$tmp/errors"; } >"$out/lihao-fig5.txt"
awk -f "$here/loglog.awk" "$tmp/errors" >"$out/lihao-fig5.svg"
awk '{ x = log($1) / log(10); y = log($2) / log(10); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
     END { printf "Li-Hao Fig. 5: fitted slope of log(error) against log(step): %.3f\n",
           (n * sxy - sx * sy) / (n * sxx - sx * sx) }' "$tmp/errors"

# ---- one picture per scheme, through the same five keys ---------------------
for s in screw bivector smooth lihao2 lihao3; do
    "$G" interp --scheme "$s" --format pose --samples 201 --in "$src/schemes.keys" \
        --out "$tmp/samples" --svg "$out/scheme-$s.svg"
done

# bspline needs even times: the same five poses at t = 0, 1, 2, 3, 4
awk '/^#/ { next } { $1 = n++; print }' "$src/schemes.keys" >"$tmp/even.keys"
"$G" interp --scheme bspline --format pose --samples 201 --in "$tmp/even.keys" --out "$tmp/samples" \
    --svg "$out/scheme-bspline.svg"

# ---- the tutorial: one screw, a robot's tool poses from a CSV file, the demo -
"$G" interp --format pose --samples 21 --in "$src/two-poses.keys" --out "$tmp/samples" \
    --svg "$out/two-poses.svg"
"$G" interp --header --format pose --scheme lihao3 --samples 51 --in "$src/tool-poses.csv" \
    --out "$tmp/samples" --svg "$out/tool-poses.svg"
"$G" interp --header --format pose --scheme lihao3 --samples 51 --in "$src/tool-poses.csv" \
    --out "$tmp/samples" --svg "$out/tool-poses-xy.svg" --view xy
"$G" demo --svg "$out/demo.svg" >"$tmp/report"

# ---- the tutorial's ROS export pair: one c2 path through ros-motion.keys --
# ground truth at 100 Hz as `rostopic echo -p` writes it (ros-gt.csv); an
# estimate at about 30 Hz, jittered stamps, in another frame with a yaw
# drift and noise, as pandas writes a CSV, quoted (ros-est.csv). Positions
# are written to the micrometre and quaternions with 12 digits, so that the
# last digits of the tool's output do not reach the files.
"$G" interp --format pose --time-unit ns --scheme c2 --rate 100 --in "$src/ros-motion.keys" \
    --output-format tum --out "$tmp/gt"
awk -v what=gt -v seed=20261203 -f "$here/ros-export.awk" "$tmp/gt" >"$out/ros-gt.csv"
awk -v what=stamps -v seed=20261204 -f "$here/ros-export.awk" >"$tmp/est.times"
"$G" interp --format pose --time-unit ns --scheme c2 --times "$tmp/est.times" --in "$src/ros-motion.keys" \
    --output-format tum --out "$tmp/est"
awk -v what=est -v seed=20261205 -f "$here/ros-export.awk" "$tmp/est" >"$out/ros-est.csv"

# ---- the conformal model: objects, meets, an inversion, a dilation ----------
# docs/examples/figures.c builds each object with the library, reads it back
# and draws it, checking every point it draws against the object's blade
"$(dirname "$G")/conformal-figures" "$out"
