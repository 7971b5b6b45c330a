#!/bin/sh
# The naming scheme of docs/conventions.md, checked on the built library and
# the public headers:
#   - every symbol the shared library exports starts with ga_;
#   - it exports exactly the functions and data the headers declare GA_API;
#   - enumerator families cannot collide: for each enum of the public headers,
#     its family prefix (the longest common prefix of its members, the first
#     member left out as it may be the family's zero, GA_OK) begins no member
#     of any other enum;
#   - each public header compiles on its own (a translation unit that
#     includes it and nothing else) as C11 with -Wall -Wextra -Wpedantic
#     -Werror, with ${CC:-cc}, and as C++ (-fsyntax-only) when ${CXX:-c++} is
#     found (skipped quietly otherwise).
# Usage: api_check.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
src=$2
fail=0
so=$(find "$build" -maxdepth 1 -name 'libgarotor.so*' -type f | head -n 1)
if [ -n "$so" ] && command -v nm >/dev/null 2>&1; then
    # names with two leading underscores are the compiler's (a sanitizer's
    # instrumentation defines some), not the library's
    bad=$(nm -D --defined-only "$so" | awk '{print $3}' | grep -v '^ga_' | grep -v '^__' || true)
    if [ -n "$bad" ]; then
        echo "FAIL exported symbols without the ga_ prefix: $bad"
        fail=1
    else
        echo "ok   all $(nm -D --defined-only "$so" | awk '{print $3}' | grep -c '^ga_') exported symbols start with ga_"
    fi
else
    echo "skip no shared library or nm: exported symbols not checked"
fi

# the ABI: the shared library exports exactly what the headers declare GA_API
# (include/garotor/export.h), functions and data, no more and no fewer
if [ -n "$so" ] && command -v nm >/dev/null 2>&1; then
    tmp=${TMPDIR:-/tmp}/garotor-abi.$$
    nm -D --defined-only "$so" | awk '{print $3}' | grep -v '^__' | sort -u >"$tmp.so"
    cat "$src"/include/garotor/*.h | tr '\n' ' ' | sed 's/;/;\n/g' | grep 'GA_API' |
        grep -o 'ga_[A-Za-z0-9_]*[[:space:]]*[(;]' | sed 's/[[:space:]]*[(;]$//' | sort -u >"$tmp.h"
    extra=$(comm -23 "$tmp.so" "$tmp.h" | tr '\n' ' ')
    missing=$(comm -13 "$tmp.so" "$tmp.h" | tr '\n' ' ')
    n=$(wc -l <"$tmp.h")
    rm -f "$tmp.so" "$tmp.h"
    if [ -n "$extra" ]; then
        echo "FAIL exported but not declared GA_API in include/garotor/: $extra"
        fail=1
    fi
    if [ -n "$missing" ]; then
        echo "FAIL declared GA_API but not exported: $missing"
        fail=1
    fi
    [ -z "$extra$missing" ] && echo "ok   the library exports exactly the $n names its headers declare GA_API"
    [ "$n" -ge 100 ] || { echo "FAIL only $n GA_API declarations found in the headers"; fail=1; }
fi

# one line per enum: its members, space-separated
cat "$src"/include/garotor/*.h | tr '\n' ' ' | sed 's/\/\*[^*]*\*\+\([^/*][^*]*\*\+\)*\///g' |
    grep -o 'enum[^{;]*{[^}]*}' | sed 's/.*{//; s/}//; s/=[^,]*//g; s/,/ /g' >"${TMPDIR:-/tmp}/garotor-enums.$$"
out=$(awk '
    function lcp(a, b,   n) { n = 0; while (n < length(a) && n < length(b) && substr(a, n + 1, 1) == substr(b, n + 1, 1)) n++; return substr(a, 1, n) }
    {
        n = split($0, m, " "); k++; cnt[k] = n
        for (i = 1; i <= n; i++) mem[k, i] = m[i]
        p = n > 1 ? m[2] : m[1]
        for (i = 3; i <= n; i++) p = lcp(p, m[i])
        pre[k] = p
    }
    END {
        for (a = 1; a <= k; a++) {
            printf "ok   enum of %d members (%s ...): family prefix %s\n", cnt[a], mem[a, 1], pre[a]
            for (b = 1; b <= k; b++) if (a != b)
                for (i = 1; i <= cnt[b]; i++)
                    if (index(mem[b, i], pre[a]) == 1) printf "FAIL %s (another enum) starts with the family prefix %s\n", mem[b, i], pre[a]
        }
    }' "${TMPDIR:-/tmp}/garotor-enums.$$")
rm -f "${TMPDIR:-/tmp}/garotor-enums.$$"
echo "$out"
case "$out" in *FAIL*) fail=1 ;; esac
[ "$(echo "$out" | grep -c '^ok   enum')" -ge 4 ] || { echo "FAIL fewer enums found than the headers have"; fail=1; }

# every public header on its own: the source include/ and the build's
# include/ (version.h is made by meson) on the include path
tmp=$(mktemp -d "${TMPDIR:-/tmp}/garotor-hdr.XXXXXX")
cc=${CC:-cc}
cxx=${CXX:-c++}
command -v "${cxx%% *}" >/dev/null 2>&1 || cxx=
nh=0
hfail=0
for h in "$src"/include/garotor/*.h "$build"/include/garotor/version.h; do
    [ -f "$h" ] || continue
    name=$(basename "$h")
    # a declaration of its own: a header of macros only would leave ISO C an
    # empty translation unit
    printf '#include <garotor/%s>\ntypedef int garotor_header_check;\n' "$name" >"$tmp/t.c"
    if ! $cc -std=c11 -Wall -Wextra -Wpedantic -Werror -I"$src/include" -I"$build/include" \
        -c "$tmp/t.c" -o "$tmp/t.o" >"$tmp/err" 2>&1; then
        echo "FAIL <garotor/$name> does not compile on its own as C11:"
        sed 's/^/     /' "$tmp/err"
        hfail=1
    fi
    if [ -n "$cxx" ] && ! $cxx -x c++ -fsyntax-only -Wall -Wextra -Wpedantic -Werror -I"$src/include" \
        -I"$build/include" "$tmp/t.c" >"$tmp/err" 2>&1; then
        echo "FAIL <garotor/$name> does not compile on its own as C++:"
        sed 's/^/     /' "$tmp/err"
        hfail=1
    fi
    nh=$((nh + 1))
done
rm -rf "$tmp"
[ "$nh" -ge 14 ] || { echo "FAIL only $nh public headers found"; hfail=1; }
if [ "$hfail" = 0 ]; then
    echo "ok   each of the $nh public headers compiles on its own as C11${cxx:+ and as C++} (-Wall -Wextra -Wpedantic -Werror)"
else
    fail=1
fi
exit $fail
