#!/bin/sh
# test_negative_transmit.sh - a negative transmit (tests/
# negative_transmit.pov): povray 3.7 traces the ray behind and shows
# (1 - t) C + t B with t < 0 as with t > 1.  A thin box of rgb 0.5 over
# a checker, its two faces each weighing what is behind by t (t^2 in
# all: t = -1 renders as t = 1).  Pixels of row 5 are povray's,
# recorded below (povray 3.7.0.10, 16x12, -A +WT1 -GA), each channel
# within 2 levels.  Before, no ray was traced behind a negative transmit
# (textures/pigments/transmitfx.pov's sphere "t -1.0" was white).  With
# povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="5,0=231,149,89 5,2=89,170,243 5,6=231,149,89"
recorded_2="5,0=231,149,89 5,2=176,185,198 5,6=195,182,176"
recorded_3="5,0=231,149,89 5,2=0,143,255 5,6=255,63,0"
fail=0
for c in 1 2 3; do
  case $c in 1) t=-1 ;; 2) t=-0.4 ;; 3) t=1.5 ;; esac
  eval "values=\$recorded_$c"
  echo "transmit $t:"
  pixel_case "$srcdir/tests/negative_transmit.pov" $c T=$t $values ||
    fail=1
done
exit $fail
