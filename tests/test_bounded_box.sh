#!/bin/sh
# test_bounded_box.sh - an object's own bounded_by that leaves part of the
# object out: POV-Ray 3.7 takes the bound's box in place of the object's
# box when it is the smaller by volume, and rays that miss it skip the
# object (lib/trace/prepare.c bound_by_box; tests/bounded_box.pov).  The
# tree before this test ignored the bound of any shape it could box
# itself and drew these objects whole.
# povray 3.7.0.10's pixels (32x24, -A +WT1 -GA; grey, so one value for
# R, G and B; rows from the top) and what the tree before gave:
#   1 torus under a sphere of radius 0.8: 14,6 16,8 11,5 black (before
#     217 215 205: the whole torus); 13,22 153 (both)
#   2 lathe, the same bound: 7,8 10,9 13,8 black (before 215 214 214)
#   3 cylinder of radius 0.63 (box 3.97, the bound's 4.10): whole, 10,7
#     212, 11,10 211, 14,27 205 (cut away if the bound were taken
#     whatever its volume, as case 4)
#   4 radius 0.65 (box 4.23): cut, 10,7 11,10 14,27 black (before 212
#     211 205)
#   5 sphere of radius 1.1 under a box 0.9 x 3 x 3: cut at x = 0.3, 7,12
#     9,10 9,14 black (before 218 215 212)
#   6 under a box 0.9 x 6 x 6 (larger than the sphere's): whole, 7,12 218,
#     9,10 215, 11,12 211
#   7 superellipsoid under the sphere of case 1: 4,8 3,11 7,7 black
#     (before 217 209 209)
#   8 mesh of two triangles, the same: 2,15 4,17 10,12 black (before 174
#     173 171)
# With povray installed its whole picture is compared too (within 2).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/bounded_box.pov
recorded_1="14,6=0,0,0 16,8=0,0,0 11,5=0,0,0 13,22=153,153,153"
recorded_2="7,8=0,0,0 10,9=0,0,0 13,8=0,0,0 12,22=96,96,96"
recorded_3="10,7=212,212,212 11,10=211,211,211 14,27=205,205,205 12,23=204,204,204"
recorded_4="10,7=0,0,0 11,10=0,0,0 14,27=0,0,0 12,19=207,207,207"
recorded_5="7,12=0,0,0 9,10=0,0,0 9,14=0,0,0 12,18=181,181,181"
recorded_6="7,12=218,218,218 9,10=215,215,215 11,12=211,211,211 12,15=199,199,199"
recorded_7="4,8=0,0,0 3,11=0,0,0 7,7=0,0,0 12,13=199,199,199"
recorded_8="2,15=0,0,0 4,17=0,0,0 10,12=0,0,0 13,17=168,168,168"
pixel_w=32 pixel_h=24
pixel_cases "$scene" K "1 2 3 4 5 6 7 8"
