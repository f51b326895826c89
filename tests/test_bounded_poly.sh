#!/bin/sh
# test_bounded_poly.sh - bounded_by on a poly, cubic or quartic: POV-Ray
# traces the shape only for rays that meet the bounding object itself
# (lib/trace/intersect.c meets_bound), and a plane's own bound it ignores
# (lib/trace/prepare.c; tests/bounded_poly.pov).  The tree
# before this test used the bound's box only, which drew the cases below
# with square edges and cut the corners of objects/quartic/hyptorus.pov's
# tubes, which POV-Ray leaves out (SSIM 0.981 at 160x120, now 1.0000).
# povray 3.7.0.10's pixels (32x24, -A +WT1 -GA; grey, so one value for
# R, G and B) and what the tree before this test gave:
#   1 poly sphere of radius 1, bounded by a sphere of radius 0.5: a disc
#     of radius 0.5 shaded as the big sphere; 12,16 195; 7,11 10,11 16,13
#     black (before 218 214 179: the bound's box)
#   2 quartic torus bounded by a sphere over its right side: 12,22 209;
#     4,13 5,16 15,27 black (before 177 146 109)
#   3 the same torus in a union that has the bound: as 2
#   4 a plane's own bound (a box): POV-Ray ignores it (lib/trace/
#     prepare.c); 20,2 168; 20,29 118; 14,16 117 (before 0 0 117: the
#     bound's box cut a square out of the plane)
#   5 a plane in a union that has the bound: cut, 20,2 20,29 black;
#     14,16 117; 5,16 143 (unchanged)
# With povray installed its whole picture is compared too (within 2).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/bounded_poly.pov
recorded_1="12,16=195,195,195 7,11=0,0,0 10,11=0,0,0 16,13=0,0,0"
recorded_2="12,22=209,209,209 4,13=0,0,0 5,16=0,0,0 15,27=0,0,0"
recorded_3=$recorded_2
recorded_4="20,2=168,168,168 20,29=118,118,118 14,16=117,117,117"
recorded_5="20,2=0,0,0 20,29=0,0,0 14,16=117,117,117 5,16=143,143,143"
pixel_w=32 pixel_h=24
pixel_cases "$scene" K "1 2 3 4 5"
