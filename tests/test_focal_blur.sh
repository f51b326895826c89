#!/bin/sh
# test_focal_blur.sh - the width of focal blur's lens.  A small bright
# sphere far behind the focal plane blurs into the image of the lens
# disc; bench/conform/focal_blur_probe.py turns its spread into the lens
# radius as a fraction of `aperture`.  povray 3.7.0.10 printed (cases a
# b c e: direction 1 and 2, aperture 0.5 and 1, focal distance 1 and 2)
#   0.259 0.260 0.254 0.277
# (the sphere's own size adds a little; 2026-12-03): a lens of radius
# aperture / 4.  zrcube must be within 0.03 of each.  Before, zrcube's
# lens had radius aperture / 2 (0.50 in every case) and the corpus
# focalblur.pov scored SSIM 0.902.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
py=/usr/bin/python3
$py -c 'import numpy, skimage' 2>/dev/null ||
  { echo "no python3 numpy/skimage: skipped"; exit 77; }
out=$($py "$srcdir/bench/conform/focal_blur_probe.py" "$zrcube") ||
  { echo "FAIL: the probe did not run"; exit 1; }
echo "$out"
echo "$out" | $py -c '
import sys
recorded = {"a": 0.259, "b": 0.260, "c": 0.254, "e": 0.277}
bad = 0
seen = 0
for line in sys.stdin:
    name, _, ratio = line.split()[:3]
    seen += 1
    if abs(float(ratio) - recorded[name]) > 0.03:
        print("FAIL: case %s lens radius / aperture %s, povray %.3f"
              % (name, ratio, recorded[name]))
        bad = 1
if seen != len(recorded):
    print("FAIL: %d cases printed" % seen)
    bad = 1
sys.exit(bad)
'
