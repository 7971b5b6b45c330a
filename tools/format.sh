#!/bin/sh
# tools/format.sh: the C and C++ sources in the style of .clang-format.
#
#   tools/format.sh            rewrite, in place, every file that differs
#   tools/format.sh --check    rewrite nothing; list the files that differ and
#                              exit 1 if there are any (what CI runs)
#   tools/format.sh --diff     like --check, and show each difference
#   tools/format.sh [--check|--diff] FILE...   only these files
#
# The files are the *.c, *.h and *.cpp files git knows about (outside a git
# checkout: those under the source directories); generated files (*.inc) are
# left alone. clang-format is the one on PATH, or $CLANG_FORMAT; the style is
# defined by Debian 12's clang-format 14, and another major version may
# format a few constructs differently (the script then says so).
set -eu

mode=fix
case "${1:-}" in
--check) mode='check'; shift ;;
--diff) mode='diff'; shift ;;
-h|--help) sed -n '2,14s/^# \{0,1\}//p' "$0"; exit 0 ;;
-*) echo "usage: $0 [--check|--diff] [FILE...]" >&2; exit 2 ;;
esac

# FILE arguments are relative to where the script was started
if [ $# -gt 0 ]; then
    for f in "$@"; do
        case $f in
        /*) set -- "$@" "$f" ;;
        *) set -- "$@" "$PWD/$f" ;;
        esac
        shift
    done
fi
cd "$(dirname "$0")/.."
root=$(pwd)

cf=${CLANG_FORMAT:-clang-format}
if ! command -v "$cf" >/dev/null 2>&1; then
    echo "$0: $cf not found (Debian: apt-get install clang-format)" >&2
    exit 2
fi
major=$("$cf" --version | sed -n 's/.*version \([0-9][0-9]*\)\..*/\1/p')
if [ "$major" != 14 ]; then
    echo "$0: note: $("$cf" --version) is not clang-format 14, which defines the style" >&2
fi

# a broken .clang-format fails here, not once per file
"$cf" --style=file --fallback-style=none --dump-config >/dev/null

if [ $# -eq 0 ]; then
    if [ -e .git ] && command -v git >/dev/null 2>&1; then
        set -- $(git ls-files '*.c' '*.h' '*.cpp')
    else
        set -- $(find ga interp include tools tests bench fuzz \
                      \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) -type f | sort)
    fi
fi

differ=0
for f in "$@"; do
    if "$cf" --style=file --fallback-style=none "$f" | cmp -s "$f" -; then
        continue
    fi
    differ=$((differ + 1))
    name=${f#"$root"/}
    case $mode in
    fix) "$cf" -i --style=file --fallback-style=none "$f"; echo "formatted $name" ;;
    check) echo "$name" ;;
    diff)
        echo "$name"
        "$cf" --style=file --fallback-style=none "$f" |
            diff -u --label "a/$name" --label "b/$name" "$f" - || true
        ;;
    esac
done

if [ "$mode" != fix ] && [ "$differ" -gt 0 ]; then
    echo "$0: $differ file(s) not formatted as .clang-format says; run tools/format.sh" >&2
    exit 1
fi
exit 0
