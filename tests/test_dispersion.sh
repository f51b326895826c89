#!/bin/sh
# test_dispersion.sh - interior { dispersion } splits a refracted ray into
# the spectrum (lib/trace/dispersion.c; tests/dispersion.pov: a clear slab
# at 45 degrees before an emitting edge, white for x < 0).  The tree
# before this test refracted with the mean ior and warned: one edge from
# white to black at column 16 (up to 253 levels off).  povray 3.7.0.10's
# pixels (32x4, -A +WT1 -GA, row 1), each column seeing white in fewer
# colours of the spectrum from left to right:
#   1 dispersion 1.2, 7 samples: 0 254,255,255; 9 250,255,230;
#     11 250,255,174; 14 250,242,88; 16 249,192,0; 19 214,108,0;
#     21 139,0,0; 24 0,0,0
#   2 dispersion_samples 3: 10 254,255,255; 11 250,255,149;
#     16 230,140,0; 22 0,0,0
#   3 dispersion 0.8 (violet bends less than red), dispersion_samples 2.7
#     (taken as 2): 10 254,255,255; 11 56,142,253; 21 56,142,253; 22 0,0,0
#   4 dispersion without an ior: none, and no tint (255 through column 31)
# With povray installed its whole picture is compared too (identical).
# A dispersion_samples below 2 is an error, as in povray (which says only
# "Cannot parse input").
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
scene=$srcdir/tests/dispersion.pov
recorded_1="1,0=254,255,255 1,9=250,255,230 1,11=250,255,174 1,14=250,242,88 1,16=249,192,0 1,19=214,108,0 1,21=139,0,0 1,24=0,0,0"
recorded_2="1,10=254,255,255 1,11=250,255,149 1,16=230,140,0 1,22=0,0,0"
recorded_3="1,10=254,255,255 1,11=56,142,253 1,21=56,142,253 1,22=0,0,0"
recorded_4="1,0=255,255,255 1,16=255,255,255 1,31=255,255,255"
pixel_w=32 pixel_h=4
fail=0
pixel_cases "$scene" K "1 2 3 4" || fail=1
echo "dispersion_samples 1:"
printf 'sphere { 0, 1 pigment { rgbf 1 }\n  interior { ior 1.5 dispersion 1.1 dispersion_samples 1 } }\n' >bad.pov
if timeout 60 "$zrcube" +Ibad.pov +Obad.png +W8 +H6 -D +WT1 </dev/null \
     >bad.log 2>&1; then
  echo "accepted dispersion_samples 1" >&2
  fail=1
elif ! grep -q 'bad.pov:2:56: error: dispersion_samples must be between 2' bad.log; then
  cat bad.log >&2
  fail=1
else
  echo ok
fi
exit $fail
