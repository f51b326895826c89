#!/bin/sh
# test_isosurface_nan.sh - isosurfaces whose function is not a number in
# places (tests/isosurface_nan.pov): povray 3.7 finds no crossing in a
# stretch of the ray with a NaN at either end and does not halve it
# further.  The pixels below are povray's (povray 3.7.0.10, 16x12, -A
# +WT1 -GA); each channel must be within 2 levels.  Before, zrcube
# halved such stretches down to the accuracy (20,000 evaluations a ray
# on corpus sep05.pov, 10x povray's time) and drew cases 0, 1 and 3,
# which povray leaves empty (background 0,0,124).  Case 2 (a sphere
# behind a slab of NaN) is drawn by both.  With povray installed the
# whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_0="0,0,124 0,0,124 0,0,124 0,0,124"
recorded_1="0,0,124 0,0,124 0,0,124 0,0,124"
recorded_2="109,226,166 123,254,187 124,89,56 108,225,165"
recorded_3="0,0,124 0,0,124 0,0,124 0,0,124"
pixel_cases "$srcdir/tests/isosurface_nan.pov" Case "0 1 2 3" \
  "6,8 4,6 8,10 7,5"
