#!/bin/sh
# test_sky_transform.sh - a sky_sphere's transform (tests/sky_transform.pov)
# is its pigments' transform in povray 3.7: the unit direction of a ray,
# taken as a point, goes through the inverse transform and is not
# normalised again, so a scale changes the sky and a translate moves it
# (lib/trace/atmosphere.c, sky_point()).  Four pixels of each case are
# povray's, recorded below (povray 3.7.0.10, 16x12, -A +WT1 -GA); each
# channel must be within 2 levels.  Before, the direction was normalised
# after the transform (a scale changed nothing, a translate was lost):
# case 0, pixel 9,12 (row, column) was 36,169,253 for povray's 227,136,131, and the
# corpus scene city.pov (sky_sphere { S_Cloud2 scale 0.8 }) scored SSIM
# 0.77.  With povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_0="172,153,202 167,154,206 227,136,131 181,151,194"
recorded_1="226,137,135 248,127,71 178,151,196 231,135,124"
recorded_2="111,163,236 185,149,190 243,129,91 132,161,227"
recorded_3="229,135,129 155,156,214 212,142,159 225,137,136"
pixel_cases "$srcdir/tests/sky_transform.pov" Case "0 1 2 3" \
  "3,3 6,8 9,12 10,2"
