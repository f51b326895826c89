#!/bin/sh
# test_hf_inside.sh - whether a ray goes into an object or out of it is
# decided by the objects its path is in, not by the side of the surface
# it meets (tests/hf_inside.pov: an upside-down clear height field,
# whose solid camera rays enter through the open side).  povray 3.7
# refracts them into the glass at the first surface they meet; we
# passed them through unbent, showing the floor 126 levels off in 92 of
# the 192 pixels (and advanced/glasschess.pov's board without its
# reflections).  The pixels are povray's (16x12, recorded below).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
fail=0
echo "upside down:"
pixel_case "$srcdir/tests/hf_inside.pov" neg NEG=1 \
  2,6=113,136,212 4,9=115,139,216 6,3=238,238,238 8,9=242,242,242 \
  10,3=116,140,217 3,12=237,237,237 || fail=1
echo "the right way up:"
pixel_case "$srcdir/tests/hf_inside.pov" pos NEG=0 || fail=1
exit $fail
