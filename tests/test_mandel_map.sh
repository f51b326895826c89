#!/bin/sh
# test_mandel_map.sh - mandel written without a colour map takes POV-Ray
# 3.7's own (the manual lists mandel among the patterns with "a built in
# default color_map"; lib/scene/texture.c mandel_map has the knots, read
# from povray's #debug values).  The tree before this test used the grey
# ramp: stock textures/pigments/pigment.pov's mandel ball was grey and
# black where povray's is cyan, magenta and yellow (SSIM 0.988 -> 1.000);
# here 590 of 768 pixels off, up to 255 levels.  tests/mandel_map.pov
# seen flat: case 1 at 1000 iterations, where the points that escape
# after one (value exactly 1/1000, row 0) are black; case 2 at 30.
# povray 3.7.0.10's pixels (32x24, -A +WT1 -GA), recorded below; with
# povray installed its whole picture is compared too (identical).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="0,0=0,0,0 0,11=0,0,0 0,20=85,255,245 1,22=233,255,118 2,21=162,255,209 3,21=220,145,255 3,23=254,28,255 4,22=0,255,255 12,16=180,194,255"
recorded_2="0,0=0,0,0 0,11=229,128,255 0,20=168,205,255 0,22=0,255,255 12,16=0,255,255"
pixel_w=32 pixel_h=24
pixel_cases "$srcdir/tests/mandel_map.pov" K "1 2"
