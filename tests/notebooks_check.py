#!/usr/bin/env python3
"""tests/notebooks_check.py: the notebooks of docs/notebooks/ run, and print
what they show.

    notebooks_check.py PYTHON_MODULE_DIR [--fix]

Executes every docs/notebooks/*.ipynb (nbclient, the ipykernel of this
Python, the garotor module from PYTHON_MODULE_DIR, the notebook's folder as
the working directory) and compares each code cell's
text outputs (printed streams, results, errors) with those stored in the
notebook, character for character, and that a cell that stored a picture
draws one again (the pixels are matplotlib's, not compared). The notebooks'
own cells assert what they teach (a point is null, the angle survives the
inversion, ...), so a wrong number fails there too. --fix writes the new
outputs into the notebooks. Skips (77) without nbclient, nbformat, ipykernel,
matplotlib or the module.

The notebooks run one after the other in one kernel: starting and stopping
a kernel costs about 2 s of CPU (ipykernel's imports alone 1.2 s), so a
kernel per notebook took 7.5 to 8.4 s of CPU for the three, one kernel 4.2
to 4.9 s (every process reaped and counted, on a loaded machine). Before
each notebook the kernel is made as a fresh one would be for it: its
namespace emptied (%reset -f: a name the notebook uses but does not define
is an error, as in a fresh kernel), its figures closed, numpy's print
options put back as the kernel started with them, and the notebook's folder
the working directory. What stays is what the imported modules hold (numpy,
matplotlib and garotor are imported once): a notebook that changed another
module setting (matplotlib's rcParams, say) would pass it on to the next;
none of the three changes any."""
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


# run in the kernel before each notebook: a fresh kernel's state for it
START = """import sys as _sys, types as _types, numpy as _np
_sys.modules['_garotor_check'] = _types.ModuleType('_garotor_check')
_sys.modules['_garotor_check'].printoptions = _np.get_printoptions()
del _sys, _types, _np"""
RESET = """%%reset -f
import os as _os, numpy as _np, matplotlib.pyplot as _plt, _garotor_check as _c
_np.set_printoptions(**_c.printoptions)
_plt.close('all')
_os.chdir(%r)
del _os, _np, _plt, _c"""


def kernel_cell(client, source):
    """runs source in the kernel as a cell of its own, not the notebook's"""
    client.execute_cell(nbformat.v4.new_code_cell(source), 0, store_history=False)  # raises on an error


fail = 0
first = nbformat.read(books[0], as_version=4)
client = nbclient.NotebookClient(first, timeout=120, kernel_name='python3', shutdown_kernel='immediate',
                                 resources={'metadata': {'path': os.path.dirname(books[0])}})
with client.setup_kernel():
    kernel_cell(client, START)
    for path in books:
        name = os.path.relpath(path, os.path.join(here, '..'))
        stored = nbformat.read(path, as_version=4)
        run = nbformat.read(path, as_version=4)
        kernel_cell(client, RESET % os.path.dirname(os.path.abspath(path)))
        client.nb = run
        client.reset_execution_trackers()
        try:
            for index, cell in enumerate(run.cells):
                client.execute_cell(cell, index)
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
                          % (name, i + 1, ta, tb,
                             '' if pa == pb else '\n  pictures: %d stored, %d now' % (pa, pb)))
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
