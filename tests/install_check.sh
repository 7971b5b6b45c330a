#!/bin/sh
# What a user of an installed garotor relies on, checked on a real install
# into a scratch prefix (meson install --destdir; every path below is the
# user's prefix inside it):
#   - include/ holds garotor/*.h and nothing else;
#   - the README's C example builds with `pkg-config --cflags --libs garotor`
#     and `#include <garotor/garotor.h>`, and runs;
#   - GAROTOR_VERSION_MAJOR/MINOR/PATCH match meson.build's version;
#   - the installed tool runs without LD_LIBRARY_PATH (it finds the library
#     beside it through its $ORIGIN-relative rpath);
#   - as a meson subproject, dependency('garotor') gives the same include.
# Usage: install_check.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
src=$2
cc=${CC:-cc}
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
meson install -C "$build" --destdir "$d/root" --no-rebuild >/dev/null
pc=$(find "$d/root" -name garotor.pc | head -n 1)
[ -n "$pc" ] || fail "garotor.pc not installed"
inc=$(find "$d/root" -type d -name include | head -n 1)
[ -n "$inc" ] || fail "no include directory installed"
[ "$(ls "$inc")" = garotor ] || fail "include/ holds more than garotor/: $(ls "$inc" | tr '\n' ' ')"
[ -z "$(find "$inc/garotor" ! -name '*.h' ! -path "$inc/garotor")" ] || fail "include/garotor/ holds more than headers"
[ -f "$inc/garotor/garotor.h" ] && [ -f "$inc/garotor/version.h" ] || fail "garotor.h or version.h not installed"
echo "ok   include/ holds garotor/ only: $(ls "$inc/garotor" | tr '\n' ' ')"

# the first C block after "A few lines of C" in the README
awk '/^## A few lines of C/{f=1} f&&/^```c/{p=1;next} p&&/^```/{exit} p' "$src/README.md" > "$d/prog.c"
[ -s "$d/prog.c" ] || fail "no C example found in README.md"
grep -q '#include <garotor/garotor.h>' "$d/prog.c" || fail "the README example does not include <garotor/garotor.h>"
export PKG_CONFIG_SYSROOT_DIR="$d/root" PKG_CONFIG_PATH="$(dirname "$pc")"
# shellcheck disable=SC2046
$cc -std=c11 -Wall -Wextra -Werror "$d/prog.c" -o "$d/prog" $(pkg-config --cflags --libs garotor)
libdir=$(dirname "$(dirname "$pc")")
LD_LIBRARY_PATH="$libdir" "$d/prog" >/dev/null || fail "the README example does not run"
echo "ok   the README example builds with pkg-config and runs"

# the version macros against meson.build's project(... version : 'X.Y.Z')
want=$(sed -n "s/^ *version : '\([0-9.]*\)'.*/\1/p" "$src/meson.build" | head -n 1)
cat > "$d/ver.c" <<'EOF'
#include <garotor/garotor.h>
#include <stdio.h>
int main(void)
{
    printf("%d.%d.%d %s\n", GAROTOR_VERSION_MAJOR, GAROTOR_VERSION_MINOR, GAROTOR_VERSION_PATCH,
           GAROTOR_VERSION_STRING);
    return 0;
}
EOF
# shellcheck disable=SC2046
$cc -std=c11 "$d/ver.c" -o "$d/ver" $(pkg-config --cflags garotor)
[ "$("$d/ver")" = "$want $want" ] || fail "version macros say '$("$d/ver")', meson.build says $want"
echo "ok   GAROTOR_VERSION_* = $want, as meson.build"
# pyproject.toml takes the version from meson.build (dynamic), never repeats it
grep -q "^dynamic = \['version'\]" "$src/pyproject.toml" && ! grep -q "^version *=" "$src/pyproject.toml" ||
    fail "pyproject.toml should take its version from meson.build (dynamic = ['version'])"

# the installed tool, with the environment a user's shell has
tool=$(find "$d/root" -type f -name garotor -perm -u+x | head -n 1)
[ -n "$tool" ] || fail "the tool is not installed"
out=$(echo "0 0 0 1 2 3" | env -u LD_LIBRARY_PATH "$tool" exp) || fail "the installed tool does not start"
[ "$(echo "$out" | cut -d' ' -f4)" = 1 ] || fail "the installed tool printed '$out'"
echo "ok   the installed tool runs without LD_LIBRARY_PATH"

# a meson superproject using garotor as a subproject
if [ "${SKIP_SUBPROJECT:-0}" != 1 ]; then
    sp=$d/super
    mkdir -p "$sp/subprojects"
    ln -s "$src" "$sp/subprojects/garotor"
    cat > "$sp/meson.build" <<'EOF'
project('super', 'c', default_options : ['c_std=c11'])
garotor = dependency('garotor', fallback : ['garotor', 'garotor_dep'],
  default_options : ['default_library=static'])
executable('ver', 'ver.c', dependencies : garotor)
EOF
    cp "$d/ver.c" "$sp/ver.c"
    # not found by pkg-config on purpose: the subproject is what is tested
    PKG_CONFIG_PATH= PKG_CONFIG_SYSROOT_DIR= meson setup "$sp/build" "$sp" --wrap-mode=forcefallback \
        >"$d/sp.log" 2>&1 || { cat "$d/sp.log"; fail "meson setup of a superproject failed"; }
    meson compile -C "$sp/build" ver >"$d/sp.log" 2>&1 || { cat "$d/sp.log"; fail "superproject build failed"; }
    [ "$("$sp/build/ver")" = "$want $want" ] || fail "the subproject's version macros are wrong"
    echo "ok   as a meson subproject: dependency('garotor') builds and runs"
fi
