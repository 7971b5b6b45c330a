#!/usr/bin/env python3
"""gen/generate.py: the generator of garotor's generated C (the driver).

    python3 gen/generate.py            rewrite the generated files, print op counts
    python3 gen/generate.py --check    exit 1, with a diff, if a committed file differs
    python3 gen/generate.py --ops      print the op counts only, write nothing

Regenerating: edit the generator (this driver or a module below), never a
generated file, run `python3 gen/generate.py` and commit the generator and the
files it rewrote together. Each generated file starts with a comment saying
so. CI checks that they agree: `.ci/run` runs `python3 gen/generate.py
--check` right after the build, and the default test suite has a test
`generated` (tests/meson.build) that runs the same check wherever python3 is
found. The generator needs nothing but python3's standard library (no sympy,
no numpy), so a bare Debian 12 runs it, from any working directory.

One module per generated file, all built on gen/common.py:

  gen/common.py          sections 1-5: the blades of G(4,1) as bit masks and
                         their product (GP, OP, LC as in ga/mv.c), polynomials
                         with rational coefficients, C text, the compact
                         rotor's components, writing and checking a file
  gen/rotor_mul.py       section 6: include/garotor/rotor_mul.h
                         (ga_rotor_mul_inline, the compact rotor product)
  gen/numtext_table.py   section 7: ga/numtext_table.inc (the powers of ten of
                         the shortest-decimal writer ga/numtext.c)
  gen/mv_products.py     section 8: ga/mv_products.inc (the dense gp, op, lc
                         of ga/mv.c and gen_gp_blocks, their vector form)
  gen/rotor_sandwich.py  section 9: ga/rotor_sandwich.inc (R X ~R of
                         ga_rotor_apply_mv)
  gen/se3_dexp.py        sections 10-11: interp/se3_dexp.inc (the vector part
                         of se3_dexp, interp/group.c)
  gen/series.py          section 12: ga/internal/series_coef.inc (the
                         coefficients of the sinc family, ga/internal/series.h)
  gen/mv_kernels.py      section 13: ga/mv_kernels.inc (sp, dot, ip,
                         regressive and commutator of ga/mv_kernels.c, and
                         the sparse kernels of the geometric product)

The sections are numbered across the modules ("the script" in the generated
files' comments is this driver with its modules; they cite sections 1, 4
and 7). Each output module has PATH, the file it writes relative to the
source root, and generate(), which returns the file's text and its op counts.

Op counts: "mul" counts multiplications, "add" additions and subtractions
(negations are free: they fold into a subtraction).
"""

import argparse
import os
import sys

sys.dont_write_bytecode = True  # no gen/__pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import common  # noqa: E402
import mv_kernels  # noqa: E402
import mv_products  # noqa: E402
import numtext_table  # noqa: E402
import rotor_mul  # noqa: E402
import rotor_sandwich  # noqa: E402
import se3_dexp  # noqa: E402
import series  # noqa: E402

# in this order: the op counts print in it
GENERATED = [rotor_mul, se3_dexp, mv_products, rotor_sandwich, numtext_table, series, mv_kernels]


def main():
    ap = argparse.ArgumentParser(description='Write (or check) the generated C of garotor.')
    ap.add_argument('--check', action='store_true',
                    help='write nothing; exit 1 with a diff if a committed file differs')
    ap.add_argument('--ops', action='store_true', help='print the op counts, write nothing')
    args = ap.parse_args()
    stale = 0
    for module in GENERATED:
        text, counts = module.generate()
        if args.ops or not args.check:
            for what, (mul, add) in counts.items():
                print('%-40s %4d mul %4d add' % (what, mul, add))
        if args.ops:
            continue
        if not common.write_or_check(module.PATH, text, args.check):
            stale += 1
    if stale:
        print('run `python3 gen/generate.py` and commit the result')
    return 1 if stale else 0


if __name__ == '__main__':
    sys.exit(main())
