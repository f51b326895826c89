#!/bin/sh
# test_media_shell.sh - media in a CSG shell whose interior was moved after
# it was given, and media lit by a shadowless light
# (tests/media_shell.pov; lib/sdl/build.c transform_interior, lib/trace/
# media.c lights_media).  A difference hands its interior down to its
# parts; a transform then gave every part a moved copy of its own, so a
# ray leaving the shell through the inner sphere went into that sphere's
# copy and carried its media on through the hole and out into the open
# (benchmark.pov's clouds: a white sky).  povray 3.7 lights no media with
# a shadowless light.  A media sample on the surface where its ray went
# in starts its shadow ray inside the container, and that ray goes back
# into a container it left only where it goes in (lib/trace/media.c
# zr__media_sample_shadow).  povray 3.7.0.10's pixels (16x12, -A +WT1 -GA), and
# what the tree before this test gave:
#   1 absorbing shell from outside, through the hole: 102,123,170
#     (before 17,23,36: the hole absorbed)
#   2 scattering shell: 194,198,223 (before 255,255,255)
#   3 camera in the hole, a sky sphere around: 120,145,198 (before 3,5,10)
#   4 box of scattering media, shadowless light: 51,63,89 (before 255)
#   5 atmospheric scattering media, shadowless light: 89 (before 189)
#   6 case 4 with a light that casts shadows: 204,207,214 (unchanged)
#   7 camera in the hole of a flattened shell, the rays whose first
#     sample's shadow ray goes back into the hole: 79 85 93 109 along the
#     middle row (before 74 76 79 86); the rest of the row unchanged
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
recorded_1="102,123,170 76,92,128 75,91,126 124,149,203"
recorded_2="194,198,223 249,242,243 247,241,242 124,149,203"
recorded_3="120,145,198 120,145,198 120,145,198 120,145,198"
recorded_4="51,63,89 50,62,88 124,149,203 124,149,203"
recorded_5="89,89,89 86,86,86 86,86,86 93,93,93"
recorded_6="204,207,214 202,204,211 124,149,203 124,149,203"
recorded_7="79,79,79 93,93,93 109,109,109 139,139,139"
fail=0
pixel_cases "$srcdir/tests/media_shell.pov" Case "1 2 3 4 5 6" \
  "6,8 6,4 2,8 9,12" || fail=1
pixel_cases "$srcdir/tests/media_shell.pov" Case "7" "6,0 6,2 6,3 6,6" ||
  fail=1
exit $fail
