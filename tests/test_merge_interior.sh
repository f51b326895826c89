#!/bin/sh
# test_merge_interior.sh - which interior a ray is in, and where its
# fade_distance applies (lib/trace/shade.c stretch_interior,
# lib/trace/prepare.c).  povray 3.7 fades a stretch of a ray only where
# the ray leaves an object it is inside, by that object's interior,
# over the stretch since the surface before; a CSG part with its own
# interior is entered with it (a merge of glass parts each with its own
# interior refracts; the whole had the default interior and let rays
# through unbent: advanced/wineglass.pov's merge, SSIM 0.883 -> 0.928).
# tests/merge_interior.pov, pixels recorded from povray 3.7.0.10
# (16x12, -A +WT1 -GA), each channel within 2 levels:
#   case 1: a block nested in a fading block: 170 (0.4 of the light,
#           1.5 of the 4 units faded; before, 111: 0.16);
#   case 2: two overlapping blocks, the first fading: 245 along +x
#           (only the 0.1 from entering the second to leaving the
#           first; before, 156) and 156 along -x;
#   case 3: the same merged: not faded either way (255);
#   case 4: a merge of two glass spheres, each its own interior of ior
#           1.5 (before, up to 181 levels off).
# With povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/merge_interior.pov
fail=0
check() { # TAG CASE DIR VALUE: the middle pixels are all VALUE
  v=$4,$4,$4
  echo "case $2, direction $3:"
  pixel_case "$scene" $1 "Case=$2 Declare=Dir=$3" 6,8=$v 5,7=$v 6,7=$v \
    5,8=$v || fail=1
}
check n1 1 1 170
check n2 1 -1 170
check u1 2 1 245
check u2 2 -1 156
check m1 3 1 255
check m2 3 -1 255
echo "case 4:"
pixel_case "$scene" g Case=4 3,4=182,182,182 4,5=181,181,181 5,3=64,64,64 \
  7,2=0,0,0 8,3=0,0,0 9,6=0,0,0 6,12=179,179,179 || fail=1
exit $fail
