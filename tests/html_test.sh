#!/bin/sh
# tests/html_test.sh: the web pages of `garotor demo --html` and
# `garotor interp --html` render in headless Chromium: the page's script marks
# <body data-state="drawn"> once drawn and data-error on any script error
# (tools/html.h), the browser's console log holds no error from the page, and
# a screenshot is not blank (more than a handful of distinct byte values in
# its decoded pixel rows; a blank white page has 2 or 3). Skips (77) without
# chromium or python3 (the PNG check).
# Usage: html_test.sh GAROTOR
set -u
tool=$1
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "SKIP no chromium (apt-get install -y chromium)"; exit 77; }
command -v python3 >/dev/null || { echo "SKIP no python3"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
run() { # url, extra flags...
    url=$1; shift
    timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$(mktemp -d -p "$tmp")" "$@" "$url"
}
printf '0 0 0 0 0 0 0 1\n1 1 0 0.5 0 0 0.38268343236508978 0.92387953251128674\n2 2 1 1 0 0 0.70710678118654757 0.70710678118654757\n' >"$tmp/keys.txt"
"$tool" demo --html "$tmp/demo.html" >/dev/null || { echo "FAIL garotor demo --html"; exit 1; }
"$tool" interp --format pose --samples 40 --in "$tmp/keys.txt" --out "$tmp/samples.txt" --html "$tmp/interp.html" ||
    { echo "FAIL garotor interp --html"; exit 1; }
for page in demo interp; do
    f="$tmp/$page.html"
    grep -q 'https\?://' "$f" && { echo "FAIL $page: the page names a network address"; fail=1; }
    run "file://$f" --dump-dom >"$tmp/$page.dom" 2>/dev/null
    if grep -q '<body[^>]*data-state="drawn"' "$tmp/$page.dom" && ! grep -q '<body[^>]*data-error' "$tmp/$page.dom"; then
        echo "ok   $page: drawn, no script error"
    else
        echo "FAIL $page: not drawn or a script error: $(grep -o '<body[^>]*>' "$tmp/$page.dom")"; fail=1
    fi
    run "file://$f" --enable-logging=stderr --v=0 --screenshot="$tmp/$page.png" --window-size=800,600 \
        >/dev/null 2>"$tmp/$page.log"
    if grep -E 'CONSOLE|Uncaught' "$tmp/$page.log" | grep -qi 'error'; then
        echo "FAIL $page: console error:"; grep -E 'CONSOLE|Uncaught' "$tmp/$page.log"; fail=1
    fi
    n=$(python3 - "$tmp/$page.png" <<'PY'
import struct, sys, zlib
d = open(sys.argv[1], 'rb').read()
assert d[:8] == b'\x89PNG\r\n\x1a\n'
i, idat = 8, b''
while i < len(d):
    n, t = struct.unpack('>I4s', d[i:i + 8])
    if t == b'IDAT':
        idat += d[i + 8:i + 8 + n]
    i += 12 + n
print(len(set(zlib.decompress(idat))))
PY
    ) || n=0
    if [ "$n" -gt 16 ]; then echo "ok   $page: screenshot not blank ($n distinct byte values)"
    else echo "FAIL $page: blank screenshot ($n distinct byte values)"; fail=1; fi
done
exit $fail
