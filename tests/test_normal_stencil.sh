#!/bin/sh
# test_normal_stencil.sh - a pattern's normal from its height at the
# corners of a regular tetrahedron, accuracy around the point, one
# corner on +y (lib/scene/texture.c slope_corner,
# bench/conform/normal_stencil_probe.sh).  tests/normal_stencil.pov
# shows the normal as colour; pixels recorded from povray 3.7.0.10
# (16x12, -A +WT1 -GA), each channel within 2 levels:
#   case 1: radial 0.5 frequency 20 sine_wave (objects/quartic/witch.pov,
#           SSIM 0.896 -> 0.9999); central differences were up to 200
#           levels off;
#   case 2: across gradient x's jump: povray disturbs x from -0.94 to
#           +0.47 accuracy, in two tilts (central differences: -1 to 1,
#           one tilt);
#   case 3: across gradient y's jump: -1 to +1/3, one tilt.
# With povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/normal_stencil.pov
flat2=212,225,219 flat3=219,219,212
fail=0
echo "case 1:"
pixel_case "$scene" r Case=1 5,8=212,0,206 5,7=241,0,141 6,7=57,255,197 \
  3,8=130,249,223 5,9=194,145,0 7,5=222,140,64 || fail=1
echo "case 2:"
pixel_case "$scene" x Case=2 6,4=$flat2 6,5=241,0,60 6,7=241,0,60 \
  6,8=228,0,208 6,9=$flat2 6,10=$flat2 || fail=1
echo "case 3:"
pixel_case "$scene" y Case=3 3,8=$flat3 4,8=$flat3 5,8=142,142,246 \
  8,8=142,142,246 9,8=$flat3 || fail=1
exit $fail
