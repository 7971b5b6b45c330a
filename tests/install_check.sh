#!/bin/sh
# Install into a scratch destdir, then build and run the README's C example
# against the installed header, library and garotor.pc, as a user would.
set -eu
build=$1
readme=$2
cc=${CC:-cc}
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
meson install -C "$build" --destdir "$d/root" --no-rebuild >/dev/null
pc=$(find "$d/root" -name garotor.pc | head -n 1)
[ -n "$pc" ] || { echo "garotor.pc not installed"; exit 1; }
find "$d/root" -name garotor.h | grep -q . || { echo "garotor.h not installed"; exit 1; }
# the first C block after "A few lines of C" in the README
awk '/^## A few lines of C/{f=1} f&&/^```c/{p=1;next} p&&/^```/{exit} p' "$readme" > "$d/prog.c"
[ -s "$d/prog.c" ] || { echo "no C example found in $readme"; exit 1; }
export PKG_CONFIG_SYSROOT_DIR="$d/root" PKG_CONFIG_PATH="$(dirname "$pc")"
# shellcheck disable=SC2046
$cc -std=c11 -Wall -Wextra -Werror "$d/prog.c" -o "$d/prog" $(pkg-config --cflags --libs garotor)
libdir=$(dirname "$(dirname "$pc")")
LD_LIBRARY_PATH="$libdir" "$d/prog"
