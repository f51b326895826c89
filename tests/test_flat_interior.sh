#!/bin/sh
# test_flat_interior.sh - a union of triangles with an interior of its
# own is refracted as a solid (tests/flat_interior.pov, a cube of twelve
# clear triangles of ior 1.5): a ray goes into the interior at one
# crossing and out at the next, whichever triangles they are.  We let
# the rays through unbent (68 of the 192 pixels off, up to 255 levels;
# the corpus' diamond.pov showed a clear outline).  The pixels are
# povray 3.7's (16x12), recorded below.
# Case 2 (Declare=F=1) gives the interior fade_distance 1, fade_power
# 1001, as glass.inc's I_Glass_Dispersion1 in the corpus' diamond.pov:
# povray 3.7.0.10 fades the stretch from the triangle a ray entered by to
# the one it leaves by as in a box (3,2 41,51,84; 4,7 97,97,97).  The
# tree before this case faded no stretch that ended at another triangle
# than the one it began at (124,149,231 and 255,255,255 there: 106 of the
# 192 pixels off, up to 179 levels; diamond.pov's SSIM 0.898).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
fail=0
echo "case 1:"
pixel_case "$srcdir/tests/flat_interior.pov" cube UNUSED=0 \
  2,1=255,255,255 2,2=255,255,255 3,2=124,149,231 3,3=255,255,255 \
  3,10=124,149,231 0,5=0,0,0 0,6=0,0,0 || fail=1
echo "case 2:"
pixel_case "$srcdir/tests/flat_interior.pov" fade F=1 \
  3,2=41,51,84 3,10=44,55,89 5,5=42,52,85 6,8=42,53,87 8,6=41,51,84 \
  4,7=97,97,97 2,1=93,93,93 0,5=0,0,0 || fail=1
exit $fail
