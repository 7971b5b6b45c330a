#!/usr/bin/env python3
"""tests/page_current.py: docs/interactive/conformal.html is what the build
makes of wasm/ (the library, the shim, the page's script and template), and
the node example of docs/interactive.md prints what the page says (where
node is found).

    page_current.py COMMITTED [BUILT]

Without BUILT (no emscripten: -Dwasm=disabled or emcc not found) it skips
(77). After a change to the library or to wasm/, rebuild and copy:
    meson compile -C build conformal-page
    cp build/wasm/conformal.html docs/interactive/conformal.html"""
import sys

if len(sys.argv) < 3:
    print('SKIP no WebAssembly build (emscripten not found, or -Dwasm=disabled)')
    sys.exit(77)
import os
import re
import shutil
import subprocess

fail = 0
doc = open(os.path.join(os.path.dirname(sys.argv[1]), '..', 'interactive.md'), encoding='utf-8').read()
m = re.search(r'```js\n(.*?)```\n\nprints.*?```text\n(.*?)```', doc, re.S)
node = shutil.which('node')
if not m:
    print('FAIL docs/interactive.md: no ```js example followed by "prints" and its ```text output')
    fail = 1
elif not node:
    print('skip the node example of docs/interactive.md: no node')
else:
    inline = os.path.join(os.path.dirname(os.path.abspath(sys.argv[2])), 'garotor-inline.js')
    js = m.group(1).replace("'./build/wasm/garotor-inline.js'", repr(inline))
    out = subprocess.run([node, '-e', js], capture_output=True, text=True, timeout=60)
    if out.returncode == 0 and out.stdout == m.group(2):
        print('ok   the node example of docs/interactive.md prints %r' % out.stdout.strip())
    else:
        print('FAIL the node example of docs/interactive.md: status %d, printed %r, the page says %r%s'
              % (out.returncode, out.stdout, m.group(2), out.stderr[-300:]))
        fail = 1
committed, built = (open(p, 'rb').read() for p in sys.argv[1:3])
if committed == built:
    print('ok   docs/interactive/conformal.html is the page the build makes (%d bytes)' % len(built))
    sys.exit(fail)
print('FAIL docs/interactive/conformal.html differs from %s: rebuild and copy it\n'
      '     (meson compile -C build conformal-page && cp build/wasm/conformal.html docs/interactive/)'
      % sys.argv[2])
sys.exit(1)
