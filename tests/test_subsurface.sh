#!/bin/sh
# test_subsurface.sh - subsurface light transport (finish { subsurface {
# translucency C } }, global_settings { mm_per_unit subsurface { } }).
# Part 1: a broad lit slab or plane must render what povray 3.7 rendered
# (recorded below as the ratio of its subsurface picture to the plain
# diffuse one, in linear light, from bench/conform/sslt_probe.py's
# scenes): each case renders tests/subsurface_check.pov with subsurface,
# and without it under a light made brighter by povray's ratio; the two
# must agree to 1.5% (linear PFM, tests/imgcmp --rmse).  Then: the same
# bytes with 1 and 2 threads, no subsurface light below +Q9 (the
# manual), and a located error for a bad mm_per_unit.  Part 2, with
# povray installed, compares a shadow edge softened by the light under
# the surface, and a translucent sphere, with povray's picture (1000
# samples: at 200, povray's own grain alone costs 0.05 of SSIM).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/subsurface_check.pov" . || exit 99
fail=0
render() { # name, declarations, options...
  n=$1; d=$2; shift 2
  printf '%s\n#include "subsurface_check.pov"\n' "$d" >"$n.pov"
  timeout 120 "$zrcube" +I"$n.pov" +O"$n.${OUTEXT:-pfm}" +W16 +H16 -D "$@" \
    >"$n.log" 2>&1 || { echo "zrcube failed on $n:" >&2; cat "$n.log" >&2; exit 1; }
}
# plane pigment diffuse tilt povray's ratio (subsurface / plain)
while read -r plane pc dif la ratio; do
  common="#declare Plane = $plane; #declare PC = $pc; #declare Dif = $dif; #declare LA = $la;"
  render a "$common #declare SSS = 1; #declare Gain = 1;"
  render b "$common #declare SSS = 0; #declare Gain = $ratio;"
  if out=$("$imgcmp" a.pfm b.pfm --rmse --rmse-max 0.015); then
    echo "ok: plane $plane, R $pc x $dif, light at $la: $out"
  else
    echo "FAIL: plane $plane, R $pc x $dif, light at $la (povray: x$ratio): $out"
    fail=1
  fi
done <<'CASES'
0 0.83 0.8 0 0.9738
0 0.83 0.8 55 0.9388
1 0.3 1 0 1.951
CASES
common='#declare Plane = 0; #declare PC = 0.5; #declare Dif = 1; #declare LA = 30; #declare Gain = 1;'
render t1 "$common #declare SSS = 1;" +WT1
render t2 "$common #declare SSS = 1;" +WT2
if cmp -s t1.pfm t2.pfm; then echo "ok: same bytes with 1 and 2 threads"
else echo "FAIL: 1 and 2 threads differ"; fail=1; fi
render q8 "$common #declare SSS = 1;" +Q8
render plain "$common #declare SSS = 0;" +Q8
if cmp -s q8.pfm plain.pfm; then echo "ok: no subsurface light at +Q8"
else echo "FAIL: +Q8 still computes subsurface light"; fail=1; fi
if cmp -s t1.pfm plain.pfm; then
  echo "FAIL: subsurface made no difference at +Q9"; fail=1
fi
printf 'global_settings {\n  mm_per_unit -2 }\n' >bad.pov
if "$zrcube" +Ibad.pov +Obad.png +W8 +H8 -D >bad.log 2>&1; then
  echo "FAIL: mm_per_unit -2 was accepted"; fail=1
elif grep -q 'bad.pov:2:15: .*mm_per_unit must be positive' bad.log; then
  echo "ok: mm_per_unit -2 is a located error"
else
  echo "FAIL: unexpected message for mm_per_unit -2:"; cat bad.log; fail=1
fi
if command -v povray >/dev/null 2>&1; then
  cat >edge.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 0 mm_per_unit 10
  subsurface { samples 1000, 50 } }
camera { location <0, 6, -1> look_at <0, 0, 0> angle 40 }
light_source { <20, 40, -10> rgb 1 }
box { <0, 1, -100>, <100, 1.2, 100> pigment { rgb 0 } no_image }
box { <-100, -10, -100>, <100, 0, 100> pigment { rgb <0.8, 0.5, 0.3> }
  finish { ambient 0 diffuse 0.9 subsurface { translucency <2, 1, 0.5> } }
  interior { ior 1.4 } }
sphere { <-1, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.6, 0.4> }
  finish { ambient 0 diffuse 0.8 subsurface { translucency 3 } }
  interior { ior 1.3 } }
POV
  timeout 300 povray +Iedge.pov +Opov.png +W96 +H72 -D -A +WT1 -GA \
    </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
  timeout 300 "$zrcube" +Iedge.pov +Ozr.png +W96 +H72 -D +WT1 \
    >zr.log 2>&1 || { cat zr.log >&2; exit 1; }
  if out=$("$imgcmp" zr.png pov.png --ssim-min 0.96); then
    echo "ok: soft shadow edge and translucent sphere against povray: $out"
  else
    echo "FAIL: soft shadow edge and translucent sphere against povray: $out"
    fail=1
  fi
else
  echo "no povray: the picture comparison is skipped"
fi
exit $fail
