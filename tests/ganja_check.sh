#!/bin/sh
# garotor against ganja.js (Algebra(4,1), Float64): the geometric, outer and
# fat-dot products, the left contraction, reverse, involution, conjugate,
# dual and undual on random multivectors, and the sandwich of random versors
# (tests/ganja_dump.c writes the cases, tests/ganja_check.js recomputes and
# compares them with the bounds derived there).
#
#   ganja_check.sh GANJA_DUMP BUILD_DIR
#
# Needs node and the ganja.js package, looked up as $GANJA_DIR (the package's
# directory), else BUILD_DIR/node_modules/ganja.js, which
#   npm install --prefix BUILD_DIR --no-audit --no-fund ganja.js@1.0.204
# puts there. Without either the test is skipped (exit status 77).
set -u
dump=$1
build=$2
src=$(cd "$(dirname "$0")" && pwd)
if ! command -v node >/dev/null 2>&1; then
    echo "skip: no node on PATH"
    exit 77
fi
dir=${GANJA_DIR:-$build/node_modules/ganja.js}
if [ ! -f "$dir/package.json" ]; then
    echo "skip: no ganja.js at $dir (npm install --prefix $build ganja.js)"
    exit 77
fi
dir=$(cd "$dir" && pwd)
echo "ganja.js $(node -e "console.log(require('$dir/package.json').version)"), node $(node --version)"
"$dump" 500 14 | node "$src/ganja_check.js" "$dir"
