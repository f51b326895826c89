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
# More than 10 waves are not reproduced: a ripples or waves normal under
# number_of_waves 12 is named in a warning at its place, and none is
# given for 10 or for a waves pigment.
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
pixel_cases "$srcdir/tests/camera_normal.pov" Case "5 6 7" "$px" || fail=1
for n in 12 10; do
  printf 'global_settings { number_of_waves %s }\nplane { y, 0 pigment { waves } }\nplane { z, 5 normal {\n  waves 0.3 } }\ncamera { location <0,1,-3> look_at 0 }\n' \
    $n >nw$n.pov
  timeout 60 "$zrcube" +Inw$n.pov +Onw$n.png +W8 +H6 -D </dev/null \
    >nw$n.log 2>&1 || { cat nw$n.log >&2; fail=1; continue; }
  got=$(grep -c 'warning: number_of_waves' nw$n.log)
  if [ $n = 12 ]; then
    if grep -q "^nw12.pov:4:9: warning: number_of_waves 12: this waves normal sums only 10 waves" nw12.log; then
      echo "ok: number_of_waves 12 is named at nw12.pov:4:9"
    else
      echo "FAIL: no located warning for number_of_waves 12:"; cat nw12.log; fail=1
    fi
  elif [ "$got" != 0 ]; then
    echo "FAIL: a warning for number_of_waves 10"; fail=1
  else
    echo "ok: no warning for number_of_waves 10"
  fi
done
exit $fail
