#!/bin/sh
# test_flat_interior.sh - a union of triangles with an interior of its
# own is refracted as a solid (tests/flat_interior.pov, a cube of twelve
# clear triangles of ior 1.5): a ray goes into the interior at one
# crossing and out at the next, whichever triangles they are.  We let
# the rays through unbent (68 of the 192 pixels off, up to 255 levels;
# the corpus' diamond.pov showed a clear outline).  The pixels are
# povray 3.7's (16x12), recorded below.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
pixel_case "$srcdir/tests/flat_interior.pov" cube UNUSED=0 \
  2,1=255,255,255 2,2=255,255,255 3,2=124,149,231 3,3=255,255,255 \
  3,10=124,149,231 0,5=0,0,0 0,6=0,0,0
