#!/bin/sh
# gi_bounce.sh - what the radiosity block's recursion_limit does to a
# closed room lit by an emitting lamp, in povray's pictures and zrcube's
# (tests/gi_bounce.pov; the figures tests/test_gi_bounce.sh checks).
#
#   bench/gi_bounce.sh BUILD_DIR [OUT_DIR]
#
# For recursion_limit 1, 2, 3, 5 (and the block without one): povray
# 3.7 at its reference settings (Hi=1: count 1600, error_bound 0.1,
# nearest_count 20, pretrace_end 0.01; -A +WT1 -GA, 16-bit PNG) and at
# the test's (Hi=0: count 200), zrcube's automatic choice (the
# hierarchical solver), its irradiance cache (--gi=cache) and the
# solver with every bounce (--bounces=all); 80x60.  Printed: the mean
# linear value of five regions (rows, columns of the 80x60 picture):
# back wall 15-29 x 28-39, floor 50-57 x 25-41, red wall 15-34 x 3-14,
# the block's front 37-46 x 45-53, right wall 20-39 x 66-75.  povray
# at Hi=1 costs about 80 CPU seconds at recursion_limit 2, more above.
set -u
build=$(cd "${1:?usage: bench/gi_bounce.sh BUILD_DIR [OUT_DIR]}" && pwd) || exit 1
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/../tests/gi_bounce.pov
out=${2:-$here/out/gi_bounce}
zrcube=$build/bin/zrcube
mkdir -p "$out" || exit 1
cd "$out" || exit 1
for r in 1 2 3 5 0; do
  for hi in 1 0; do
    [ -f p_r${r}_h$hi.png ] ||
      nice -n 10 povray +I"$scene" +Op_r${r}_h$hi.png +W80 +H60 -D -A +WT1 \
        -GA +FN16 Declare=Rec=$r Declare=Hi=$hi </dev/null \
        >p_r${r}_h$hi.log 2>&1 || echo "povray failed: p_r${r}_h$hi.log"
  done
  for m in auto cache all; do
    case $m in
    auto) opt= ;;
    cache) opt=--gi=cache ;;
    all) opt="--gi=hierarchical --bounces=all" ;;
    esac
    nice -n 10 "$zrcube" +I"$scene" +Oz_r${r}_$m.png +W80 +H60 -D +WT1 +V \
      +FN16 $opt Declare=Rec=$r </dev/null >z_r${r}_$m.log 2>&1 ||
      echo "zrcube failed: z_r${r}_$m.log"
  done
done
/usr/bin/python3 - <<'PY'
import os
import numpy as np
from skimage import io

REG = {'back': (15, 30, 28, 40), 'floor': (50, 58, 25, 42),
       'red': (15, 35, 3, 15), 'block': (37, 47, 45, 54),
       'right': (20, 40, 66, 76)}


def linear(fn):
    a = io.imread(fn)[..., :3]
    a = a.astype(float) / np.iinfo(a.dtype).max
    return np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)


print('recursion_limit\trenderer\t' + '\t'.join(REG))
for r in (1, 2, 3, 5, 0):
    for name, fn in (('povray Hi=1', 'p_r%d_h1.png'), ('povray Hi=0', 'p_r%d_h0.png'),
                     ('zrcube auto', 'z_r%d_auto.png'),
                     ('zrcube cache', 'z_r%d_cache.png'),
                     ('zrcube --bounces=all', 'z_r%d_all.png')):
        fn = fn % r
        if not os.path.exists(fn):
            continue
        a = linear(fn)
        print('%s\t%s\t%s' % (r if r else '(none)', name, '\t'.join(
            '%.4f' % a[g[0]:g[1], g[2]:g[3]].mean() for g in REG.values())))
PY
