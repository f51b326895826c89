#!/bin/sh
# test_clip_box.sh - a clip whose inside reaches beyond its box (a height
# field, a disc) bounds the object by that box when it is the smaller by
# volume, as POV-Ray 3.7 draws it (lib/trace/prepare.c clip_by_box;
# tests/clip_box.pov; stock objects/csg/hfclip.pov).  The tree before
# this test drew the clipped surface all the way down the field's or the
# disc's inside.
# povray 3.7.0.10's pixels (32x24, -A +WT1 -GA; grey, so one value for
# R, G and B; rows from the top) and what the tree before gave:
#   1 infinite quadric cylinder clipped by a height field: ends at a
#     straight edge, 11,14 12,17 black (before 210 178); 8,15 89 (the
#     field's dark inside face; before black)
#   2 finite cylinder (box 2 x 6 x 2) clipped by the same field (box
#     6 x 0.8 x 6): whole, 11,14 210, 15,14 206, 19,14 201 (black where
#     case 1 is cut)
#   3 sphere clipped by a disc of radius 1: only through the disc's flat
#     box, 13,12 14,15 16,13 black (before 216 209 196)
#   4 the infinite cylinder clipped by a disc of radius 2: 13,14 17,14
#     21,14 black (before 208 204 198)
# With povray installed its whole picture is compared too (within 2).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/clip_box.pov
recorded_1="11,14=0,0,0 12,17=0,0,0 8,15=89,89,89 7,18=210,210,210"
recorded_2="11,14=210,210,210 15,14=206,206,206 19,14=201,201,201 8,14=89,89,89"
recorded_3="13,12=0,0,0 14,15=0,0,0 16,13=0,0,0 9,17=213,213,213"
recorded_4="13,14=0,0,0 17,14=0,0,0 21,14=0,0,0 10,16=206,206,206"
pixel_w=32 pixel_h=24
pixel_cases "$scene" K "1 2 3 4"
