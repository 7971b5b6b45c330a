#!/usr/bin/env python3
"""tests/page_current.py: docs/interactive/conformal.html is wasm/'s page:
the template wasm/conformal.html.in and the script wasm/conformal.js as they
are now, around an emscripten module; and the node example of
docs/interactive.md prints what that page says (with the module built here,
where emscripten and node are found).

    page_current.py COMMITTED TEMPLATE PAGE_JS [BUILT_PAGE]

The module inside the committed page may be an older build of the library:
any change to ga/ or interp/ changes the bytes of garotor.wasm, not always
its numbers, and tests/page_test.py checks the committed page's numbers
against the native library bit for bit (the test page, in its second tab
beside a WebAssembly build, in its only one where emscripten is missing). This test says whether the module is the one built
here, and fails only when the page's own parts are stale. To refresh the
page:
    meson compile -C build conformal-page
    cp build/wasm/conformal.html docs/interactive/conformal.html"""
import os
import re
import shutil
import subprocess
import sys

committed_path, template_path, js_path = sys.argv[1:4]
built_path = sys.argv[4] if len(sys.argv) > 4 else None
fail = 0
committed = open(committed_path, encoding='utf-8').read()
expect = open(template_path, encoding='utf-8').read().replace(
    '@PAGE@', open(js_path, encoding='utf-8').read().strip())
pre, post = expect.split('@GLUE@')
if committed.startswith(pre) and committed.endswith(post) and 'garotorWasm' in committed[len(pre):-len(post)]:
    print('ok   docs/interactive/conformal.html holds wasm/conformal.html.in and wasm/conformal.js as they are')
else:
    print('FAIL docs/interactive/conformal.html is not wasm/conformal.html.in with wasm/conformal.js as they are:\n'
          '     meson compile -C build conformal-page && cp build/wasm/conformal.html docs/interactive/')
    fail = 1
if built_path is None:
    print('skip the module: no WebAssembly build here (emscripten not found, or -Dwasm=disabled)')
    sys.exit(fail if fail else 77)
built = open(built_path, encoding='utf-8').read()
print('     the module in the committed page is %s the one built here'
      % ('byte for byte' if built == committed else 'not'))

doc = open(os.path.join(os.path.dirname(committed_path), '..', 'interactive.md'), encoding='utf-8').read()
m = re.search(r'```js\n(.*?)```\n\nprints.*?```text\n(.*?)```', doc, re.S)
node = shutil.which('node')
if not m:
    print('FAIL docs/interactive.md: no ```js example followed by "prints" and its ```text output')
    fail = 1
elif not node:
    print('skip the node example of docs/interactive.md: no node')
else:
    inline = os.path.join(os.path.dirname(os.path.abspath(built_path)), 'garotor-inline.js')
    js = m.group(1).replace("'./build/wasm/garotor-inline.js'", repr(inline))
    out = subprocess.run([node, '-e', js], capture_output=True, text=True, timeout=60)
    if out.returncode == 0 and out.stdout == m.group(2):
        print('ok   the node example of docs/interactive.md prints %r' % out.stdout.strip())
    else:
        print('FAIL the node example of docs/interactive.md: status %d, printed %r, the page says %r%s'
              % (out.returncode, out.stdout, m.group(2), out.stderr[-300:]))
        fail = 1
sys.exit(fail)
