#!/bin/sh
# test_csg_inside.sh - CSG with a disc or a height field, whose inside
# reaches beyond its box: a disc's is its plane's half-space (the
# manual's "Disc"), a height field's all that lies below it over its unit
# square, however far below (measured: case 5).  lib/trace/prepare.c gives
# such a CSG child no box (lib/trace/bounds.c zr__box_holds_inside),
# bounds_csg.c narrows an intersection by a disc's box (POV-Ray skips the
# intersection for rays that miss it: cases 1-2) but not by a height
# field's, and obj_height_field.c's inside has no floor at y = 0.  The
# tree before this test took a point outside the disc's or the field's
# box to be outside it: stock advanced/desk/desk.pov's glass paperweight
# (a sphere cut by a disc) was a flat disc, and a box cut by a height
# field lost its sides (tests/csg_inside.pov).
# povray 3.7.0.10's pixels (32x24, -A +WT1 -GA; grey: one value for R, G
# and B) and what the tree before this test gave:
#   1 intersection { sphere disc }, from above: 9,11 179; 11,10 201;
#     12,18 190 (before 0 159 159: the flat disc alone)
#   2 the same, disc radius 0.3: 11,14 206; 12,15 207; 12,18 190 (before
#     158 159 0)
#   3 intersection { height_field box }: 8,11 203; 12,14 202; 20,20 199
#     (before 89 0 0: the field's top alone)
#   4 difference { box height_field }: 4,12 203; 14,11 16,14 20,20 black
#     (before 203 89 201 199: the box below y = 0 left)
#   5 the field's inside down to y = -1.4 (water_level 0.2): 8,12 203;
#     12,19 200; 22,19 197; 12,8 black (x < 0) (before 0 0 0 0)
# With povray installed its whole picture is compared too (within 2; it
# was identical).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/csg_inside.pov
recorded_1="9,11=179,179,179 11,10=201,201,201 12,18=190,190,190"
recorded_2="11,14=206,206,206 12,15=207,207,207 12,18=190,190,190"
recorded_3="8,11=203,203,203 12,14=202,202,202 20,20=199,199,199"
recorded_4="4,12=203,203,203 14,11=0,0,0 16,14=0,0,0 20,20=0,0,0"
recorded_5="8,12=203,203,203 12,19=200,200,200 22,19=197,197,197 12,8=0,0,0"
pixel_w=32 pixel_h=24
pixel_cases "$scene" K "1 2 3 4 5"
