#!/bin/sh
# test_waves_normal.sh - ripples and waves normals: povray 3.7 tilts the
# normal by amount / 10 times the sum over its ten waves of the unit
# vector from the wave's centre times the sine of the wave's phase (over
# the wave's spatial frequency for waves; lib/scene/texture.c,
# bench/conform/waves_normal_fit.py).  A camera's normal { } shows the
# tilt as ray directions (tests/camera_normal.pov, cases 5 to 7: waves,
# ripples, and waves under number_of_waves 3, which takes the first 3
# centres in povray's order, lib/scene/pattern.c); seven pixels of each
# are povray's, recorded below
# (povray 3.7.0.10, 16x12, -A +WT1 -GA), each channel within 2 levels.
# Before (the cosine, all ten waves), they were 25 to 65 levels off and
# textures/patterns/waves.pov and ripples.pov scored SSIM 0.93 (1.00
# now).  With povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
px="0,0 0,15 6,8 11,0 11,15 3,4 8,11"
recorded_5="127,216,239 201,186,254 184,174,254 130,141,237 227,137,236 179,200,254 187,197,255"
recorded_6="140,216,243 223,216,243 199,181,254 130,153,240 219,160,247 166,202,253 203,177,253"
recorded_7="162,208,251 226,212,243 194,180,255 133,132,235 231,136,232 127,221,237 174,206,253"
fail=0
for c in 5 6 7; do
  timeout 60 "$zrcube" +I"$srcdir/tests/camera_normal.pov" +Oz$c.png +W16 \
    +H12 -D +WT1 Declare=Case=$c </dev/null >z$c.log 2>&1 ||
    { cat z$c.log >&2; fail=1; continue; }
  eval "values=\$recorded_$c"
  set -- $values
  args=""
  for p in $px; do args="$args $p=$1"; shift; done
  ref=""
  if command -v povray >/dev/null 2>&1 &&
     timeout 60 povray +I"$srcdir/tests/camera_normal.pov" +Op$c.png +W16 \
       +H12 -D -A +WT1 -GA Declare=Case=$c </dev/null >p$c.log 2>&1; then
    ref="--ref p$c.png"
  fi
  echo "case $c:"
  /usr/bin/python3 "$srcdir/tests/pixel_check.py" z$c.png $args $ref || fail=1
done
exit $fail
