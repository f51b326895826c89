#!/bin/sh
# test_gi_bounce.sh - the hierarchical solver's picture follows the
# radiosity block's recursion_limit, as povray's does
# (tests/gi_bounce.pov: a closed room of walls diffuse 0.75, one red,
# a block, lit only by an emitting thin box hanging in it; no sky, so
# the automatic choice is the hierarchical solver).
#
# povray 3.7.0.10 at count 1600, error_bound 0.1 (Hi=1), -A +WT1 -GA,
# 80x60, mean linear value of four regions (rows x columns): back wall
# 15-29 x 28-39, floor 50-57 x 25-41, red wall 15-34 x 3-14, right wall
# 20-39 x 66-75 (bench/gi_bounce.sh prints these and the block's front):
#   recursion_limit 1: 0.0511 0.1443 0.0342 0.0780
#                   2: 0.1188 0.1948 0.0718 0.1458
#                   3: 0.1511 0.2286 0.0902 0.1799
#                   5: 0.1913 0.2685 0.1137 0.2227
# and without recursion_limit the same as 2 (0.1207 0.1962 0.0719
# 0.1455 at count 200, against 0.1209 0.1962 0.0722 0.1458 with 2).
# The solver solved every bounce whatever the limit (main before this
# test: 0.2175 0.2943 0.1327 0.2505, 4.3 times povray's back wall at
# limit 1, 1.8 times at the default 2).  Checks:
#  1. per limit, each region within 4% of povray's (measured: 2.5% to
#     0.0% below for 1 to 3, 3.3% to 2.4% below at 5; povray at count
#     200 gives 0.1779 0.2547 0.1047 0.2056 at 5, 4-8% below its count
#     1600, so a deep limit needs many rays in povray);
#  2. a block without recursion_limit gives the bytes of limit 2;
#  3. --bounces=all gives every bounce: within 3% of the path-traced
#     reference (--gi=path --spp=2048 --path-seed=3, recorded: 0.2191
#     0.2942 0.1325 0.2534).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/gi_bounce.pov
for c in 1 2 3 5 0 all; do
  case $c in
  all) set -- Declare=Rec=2 --gi=hierarchical --bounces=all ;;
  *) set -- Declare=Rec=$c ;;
  esac
  timeout 120 "$zrcube" +I"$scene" +Oz$c.png +W80 +H60 -D +WT1 +V +FN16 \
    "$@" </dev/null >z$c.log 2>&1 || { cat z$c.log >&2; exit 1; }
done
fail=0
grep -q "global illumination: hierarchical (auto" z2.log ||
  { echo "the automatic choice is not the hierarchical solver" >&2
    fail=1; }
cmp -s z0.png z2.png ||
  { echo "a block without recursion_limit: not the picture of 2 FAIL"
    fail=1; }
/usr/bin/python3 - <<'PY' || fail=1
import sys
import numpy as np
from skimage import io

REG = {'back': (15, 30, 28, 40), 'floor': (50, 58, 25, 42),
       'red': (15, 35, 3, 15), 'right': (20, 40, 66, 76)}
POVRAY = {'1': (0.0511, 0.1443, 0.0342, 0.0780),
          '2': (0.1188, 0.1948, 0.0718, 0.1458),
          '3': (0.1511, 0.2286, 0.0902, 0.1799),
          '5': (0.1913, 0.2685, 0.1137, 0.2227),
          'all': (0.2191, 0.2942, 0.1325, 0.2534)}
TOL = {'1': 0.04, '2': 0.04, '3': 0.04, '5': 0.04, 'all': 0.03}


def linear(fn):
    a = io.imread(fn)[..., :3]
    a = a.astype(float) / np.iinfo(a.dtype).max
    return np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)


fail = 0
for c in ('1', '2', '3', '5', 'all'):
    a = linear('z%s.png' % c)
    for (name, r), want in zip(REG.items(), POVRAY[c]):
        got = a[r[0]:r[1], r[2]:r[3]].mean()
        bad = abs(got / want - 1) > TOL[c]
        fail += bad
        print('%s: %s %.4f, %s %.4f (%+.1f%%)%s' % (
            'every bounce' if c == 'all' else 'recursion_limit ' + c, name,
            got, 'path-traced' if c == 'all' else 'povray', want,
            100 * (got / want - 1), ' FAIL' if bad else ''))
sys.exit(1 if fail else 0)
PY
exit $fail
