#!/bin/sh
# The API reference: Doxygen's HTML pages of the public headers
# (include/garotor/*.h and the build's version.h), from their /** */ comments.
#
#   docs/reference.sh BUILD_DIR [OUT_DIR]     (OUT_DIR: BUILD_DIR/reference)
#
# Open OUT_DIR/html/index.html. Any Doxygen warning is an error (the docs
# suite runs this: `meson test -C build reference`); exit 77 (skipped) where
# doxygen is not installed.
#
# The headers write grades as <X>_k and <a b>_0, which Doxygen would read as
# HTML tags: the pages are made from copies in which such a '<' (one before a
# letter, '<', '~' or '(', outside #include lines and Doxygen's own "/**<")
# is escaped for Doxygen ("\<"); the headers themselves stay as a reader of
# plain text wants them. Needs perl (skipped without it, as without doxygen).
set -eu
for p in doxygen perl; do
    command -v $p >/dev/null 2>&1 || {
        echo "skip: $p is not installed"
        exit 77
    }
done
build=$1
out=${2:-$build/reference}
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/garotor-ref.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/garotor" "$out"
for h in "$src"/include/garotor/*.h "$build"/include/garotor/version.h; do
    perl -pe 'next if /^#include/; s/(?<!\*\*)<(?=[A-Za-z<~(])/\\</g' "$h" >"$tmp/garotor/$(basename "$h")"
done
cat >"$tmp/Doxyfile" <<EOF
PROJECT_NAME           = garotor
PROJECT_BRIEF          = "Conformal geometric algebra G(4,1): rotors, exp and log, 4x4 matrices, interpolation"
INPUT                  = $tmp/garotor
FILE_PATTERNS          = *.h
STRIP_FROM_PATH        = $tmp
STRIP_FROM_INC_PATH    = $tmp
OUTPUT_DIRECTORY       = $out
GENERATE_HTML          = YES
GENERATE_LATEX         = NO
HAVE_DOT               = NO
QUIET                  = YES
WARNINGS               = YES
WARN_IF_UNDOCUMENTED   = NO
WARN_IF_DOC_ERROR      = YES
WARN_NO_PARAMDOC       = NO
WARN_AS_ERROR          = FAIL_ON_WARNINGS
OPTIMIZE_OUTPUT_FOR_C  = YES
EXTRACT_ALL            = YES
EXTRACT_STATIC         = YES
JAVADOC_AUTOBRIEF      = YES
MARKDOWN_SUPPORT       = NO
ENABLE_PREPROCESSING   = YES
MACRO_EXPANSION        = YES
EXPAND_ONLY_PREDEF     = YES
PREDEFINED             = GA_API= GA_NODISCARD=
EOF
doxygen "$tmp/Doxyfile" >"$tmp/log" 2>&1 || {
    cat "$tmp/log"
    echo "FAIL: doxygen reported warnings (above)"
    exit 1
}
if [ -s "$tmp/log" ]; then
    cat "$tmp/log"
    echo "FAIL: doxygen printed warnings (above)"
    exit 1
fi
[ -f "$out/html/index.html" ] || {
    echo "FAIL: no $out/html/index.html"
    exit 1
}
echo "ok   the API reference of $(ls "$tmp/garotor" | wc -l) headers: $out/html/index.html"
