#!/bin/sh
# test_quilted_normal.sh - quilted normals: povray 3.7 adds to the normal
# bump_size times the offset d of the point from the middle of its unit
# cube, times the cubic Bezier B(|d|) with control points 0, control0,
# control1, 1, over sqrt 3 / 2 (lib/scene/texture.c quilt_push,
# bench/conform/quilted_normal_probe.py).  tests/quilted_normal.pov
# shows the normal as colour; seven pixels of each case are povray's,
# recorded below (povray 3.7.0.10, 16x12, -A +WT1 -GA), each channel
# within 2 levels: default controls, control0 -2 control1 3, turbulence,
# and the plane seen from behind its normal.  Before (a Bezier relief
# differentiated), case 1 was up to 37 levels off and advanced/quilt1.pov
# scored SSIM 0.68 (0.995 now).  With povray installed the whole
# pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
px="0,0 0,15 6,8 11,0 11,15 3,4 8,11"
recorded_1="234,196,206 243,176,201 179,242,224 234,195,201 242,174,196 240,185,215 236,184,182"
recorded_2="221,216,217 239,187,206 194,236,223 224,214,215 240,181,199 229,206,218 235,188,186"
recorded_3="221,216,220 228,207,216 221,212,236 227,205,235 225,211,214 222,215,222 227,208,207"
recorded_4="$recorded_1"
pixel_cases "$srcdir/tests/quilted_normal.pov" Case "1 2 3 4" "$px"
