#!/bin/sh
# test_irid_turbulence.sh - irid's turbulence (tests/irid_turbulence.pov):
# in povray 3.7 turbulence u makes the film's thickness t (1 + u (2 s - 1)),
# s the scalar turbulence sum of 5 octaves at the point
# (bench/conform/irid_turbulence_probe.py, lib/trace/shade.c).  The pixels
# below are povray's (povray 3.7.0.10, 16x12, -A +WT1 -GA); each channel
# must be within 2 levels.  Before, the thickness varied by the x
# component of the vector turbulence: the middle pixel of case 2 was
# 180,153,149 for povray's 150,191,208 and textures/pigments/irid.pov
# scored SSIM 0.914.  With povray installed the whole pictures are
# compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_0="170,150,237 210,175,191 243,239,156 243,186,239"
recorded_1="203,239,226 181,243,198 155,227,157 243,236,211"
recorded_2="151,198,215 150,191,208 149,181,197 171,149,150"
pixel_cases "$srcdir/tests/irid_turbulence.pov" Case "0 1 2" \
  "2,2 6,8 9,13 10,5"
