#!/bin/sh
# test_csg_area_shadow.sh - soft shadows of CSG objects under a 4x4 area
# light (tests/csg_area_shadow.pov).  The light's shadow cache keeps the
# whole CSG object that last blocked it, not only simple shapes
# (lib/trace/shade.c), and a CSG part that gave all its crossings is not
# asked again (lib/trace/csg.c): the penumbra pixels below are povray's
# (3.7.0.10, 16x12, -A +WT1 -GA; row,column), each channel within 2 levels; with
# povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded="5,13=113,113,113 5,14=149,149,149 6,9=119,119,119
6,15=96,96,96 7,7=103,103,103 8,5=145,145,145 8,11=134,134,134
8,12=147,147,147 8,14=133,133,133 8,15=116,116,116 9,6=134,134,134
9,7=91,91,91 9,10=107,107,107 9,11=138,138,138 9,15=149,149,149
10,7=137,137,137 10,8=123,123,123 10,9=122,122,122 10,10=138,138,138"
pixel_case "$srcdir/tests/csg_area_shadow.pov" csgshadow X=0 $recorded
