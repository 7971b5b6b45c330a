#!/usr/bin/env python3
"""tests/notebooks_check.py: the notebooks of docs/notebooks/ run, and print
what they show.

    notebooks_check.py PYTHON_MODULE_DIR [--fix]

Executes every docs/notebooks/*.ipynb in a fresh kernel (nbclient, the
ipykernel of this Python, the garotor module from PYTHON_MODULE_DIR, the
notebook's folder as the working directory) and compares each code cell's
text outputs (printed streams, results, errors) with those stored in the
notebook, character for character, and that a cell that stored a picture
draws one again (the pixels are matplotlib's, not compared). The notebooks'
own cells assert what they teach (a point is null, the angle survives the
inversion, ...), so a wrong number fails there too. --fix writes the new
outputs into the notebooks. Skips (77) without nbclient, nbformat, ipykernel,
matplotlib or the module."""
import glob
import os
import sys

try:
    import nbclient
    import nbformat
    import ipykernel  # noqa: F401  (the kernel nbclient starts)
    import matplotlib  # noqa: F401
except ImportError as e:
    print('SKIP %s (Debian: python3-nbclient python3-ipykernel python3-matplotlib)' % e)
    sys.exit(77)

moddir = os.path.abspath(sys.argv[1])
fix = '--fix' in sys.argv[2:]
if not glob.glob(os.path.join(moddir, 'garotor', '_garotor*.so')):  # the package garotor
    print('SKIP no garotor module in %s (-Dpython=disabled?)' % moddir)
    sys.exit(77)
os.environ['PYTHONPATH'] = moddir + os.pathsep + os.environ.get('PYTHONPATH', '')
os.environ.pop('MPLBACKEND', None)  # the kernel's inline backend draws the pictures
os.environ['PYDEVD_DISABLE_FILE_VALIDATION'] = '1'  # ipykernel's debugger's warning about frozen modules
here = os.path.dirname(os.path.abspath(__file__))
books = sorted(glob.glob(os.path.join(here, '..', 'docs', 'notebooks', '*.ipynb')))
if not books:
    print('FAIL no notebook in docs/notebooks/')
    sys.exit(1)


def texts(cell):
    """what a code cell shows as text, and how many pictures it draws"""
    out, pictures = [], 0
    for o in cell.get('outputs', []):
        if o['output_type'] == 'stream':
            out.append((o['name'], o['text']))
        elif o['output_type'] in ('execute_result', 'display_data'):
            if 'image/png' in o.get('data', {}):
                pictures += 1
            elif 'text/plain' in o.get('data', {}):
                out.append(('result', o['data']['text/plain']))
        elif o['output_type'] == 'error':
            out.append(('error', '%s: %s' % (o['ename'], o['evalue'])))
    # consecutive writes to one stream may be split differently from run to run
    merged = []
    for kind, text in out:
        if merged and merged[-1][0] == kind and kind in ('stdout', 'stderr'):
            merged[-1] = (kind, merged[-1][1] + text)
        else:
            merged.append((kind, text))
    return merged, pictures


fail = 0
for path in books:
    name = os.path.relpath(path, os.path.join(here, '..'))
    stored = nbformat.read(path, as_version=4)
    run = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(run, timeout=120, kernel_name='python3',
                                     resources={'metadata': {'path': os.path.dirname(path)}})
    try:
        client.execute()
    except nbclient.exceptions.CellExecutionError as e:
        print('FAIL %s: a cell raised:\n%s' % (name, str(e)[-1500:]))
        fail = 1
        continue
    cells = [(a, b) for a, b in zip(stored.cells, run.cells) if a.cell_type == 'code']
    bad = 0
    for i, (a, b) in enumerate(cells):
        (ta, pa), (tb, pb) = texts(a), texts(b)
        if ta != tb or pa != pb:
            bad += 1
            if not fix:
                print('FAIL %s, code cell %d prints differently now:\n  stored: %r\n  now:    %r%s'
                      % (name, i + 1, ta, tb, '' if pa == pb else '\n  pictures: %d stored, %d now' % (pa, pb)))
    nums = sum(len(t) for c in run.cells if c.cell_type == 'code' for _, t in texts(c)[0])
    pics = sum(texts(c)[1] for c in run.cells if c.cell_type == 'code')
    if fix:
        for c in run.cells:
            if c.cell_type == 'code':
                c.execution_count = None
                for o in c.get('outputs', []):
                    if 'execution_count' in o:
                        o['execution_count'] = None
        run.metadata.pop('widgets', None)
        nbformat.write(run, path)
        print('%s %s (%d code cells, %d differed)' % ('wrote', name, len(cells), bad))
    elif bad:
        fail = 1
    else:
        print('ok   %s: %d code cells run, their %d characters of output as stored, %d pictures drawn'
              % (name, len(cells), nums, pics))
sys.exit(fail)
