#!/usr/bin/env python3
"""wasm/make_page.py: docs/interactive/conformal.html from its parts.

    make_page.py TEMPLATE PAGE_JS GLUE_JS OUT

Puts the emscripten glue (garotor-inline.js: the JS loader with garotor.wasm
inside it as base64, -sSINGLE_FILE) and the page's script into the HTML
template, so that one file opens from file:// with no network. Fails if
either script holds "</script" (it would end the element early)."""
import sys

template, page_js, glue_js, out = sys.argv[1:5]
html = open(template, encoding='utf-8').read()
parts = {'@GLUE@': open(glue_js, encoding='utf-8').read().strip(),
         '@PAGE@': open(page_js, encoding='utf-8').read().strip()}
for key, text in parts.items():
    if '</script' in text.lower():
        sys.exit('make_page.py: %s holds "</script"' % key)
    if html.count(key) != 1:
        sys.exit('make_page.py: the template must hold %s once' % key)
    html = html.replace(key, text)
with open(out, 'w', encoding='utf-8', newline='\n') as f:
    f.write(html)
