#!/bin/sh
# tests/seed_sweep.sh: run a test program over other seeds (testkit.h,
# GAROTOR_TEST_SEED) and count its failures.
#
#   sh tests/seed_sweep.sh FIRST LAST PROGRAM [ARG]...
#
# runs PROGRAM [ARG]... once for each N in FIRST..LAST with
# GAROTOR_TEST_SEED=N, then prints, for every check that failed on some
# seed, how many seeds it failed on, the first such seed and its worst line
# (the largest ratio error / tolerance seen, err/tol for a check with a
# tolerance per case), and a
# last line: "PROGRAM: F of S seeds failed". Exit status 1 when any seed
# failed, so that it can stand as a test (the soak suite's object-seeds-*).
set -u
if [ $# -lt 3 ]; then
    echo "usage: $0 FIRST LAST PROGRAM [ARG]..." >&2
    exit 2
fi
first=$1
last=$2
shift 2
prog=$1
name=$(basename "$prog")
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
n=$first
while [ "$n" -le "$last" ]; do
    # each line marked with its seed; a crash (no summary line) is a failure too
    if out=$(GAROTOR_TEST_SEED=$n "$@" 2>&1); then
        :
    else
        printf '%s\n' "$out" | grep -E '^(FAIL|XPASS) ' | sed "s/^/$n /" >>"$tmp"
        printf '%s\n' "$out" | grep -q -E '(all passed|FAILED)$' || echo "$n FAIL (no summary: exit or crash)" >>"$tmp"
        echo "$n SEED-FAILED" >>"$tmp"
    fi
    n=$((n + 1))
done
awk -v name="$name" -v total=$((last - first + 1)) '
    $2 == "SEED-FAILED" { failed++; next }
    {
        seed = $1
        line = $0
        sub(/^[0-9]+ /, "", line)
        key = line
        sub(/^(FAIL|XPASS) +/, "", key)
        sub(/ +n=.*/, "", key)
        # how far past its tolerance: err/tol where the line gives it,
        # else worst/tol
        ratio = -1
        if (match(line, /err\/tol [^ )]+/)) {
            r = substr(line, RSTART + 8, RLENGTH - 8)
            ratio = r ~ /inf/ ? 1e308 : r + 0
        } else if (match(line, /worst [^ ]+  tol [^ ]+/)) {
            split(substr(line, RSTART, RLENGTH), w, / +/)
            ratio = w[2] ~ /inf|nan/ ? 1e308 : (w[4] + 0 > 0 ? w[2] / w[4] : 1e308)
        }
        if (!(key in count)) {
            order[++nk] = key
            firstseed[key] = seed
            worst[key] = line
            wr[key] = ratio
        } else if (ratio > wr[key]) {
            worst[key] = line
            wr[key] = ratio
        }
        count[key]++
    }
    END {
        for (i = 1; i <= nk; i++) {
            k = order[i]
            printf "%d seed(s), first %s, worst ratio %.3g: %s\n", count[k], firstseed[k], wr[k], worst[k]
        }
        printf "%s: %d of %d seeds failed\n", name, failed, total
        exit failed > 0
    }' "$tmp"
