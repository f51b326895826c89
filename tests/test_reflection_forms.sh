#!/bin/sh
# test_reflection_forms.sh - the one-value forms of reflection {}.
# povray 3.7 renders "reflection { R fresnel }" exactly as
# "reflection { 0, R fresnel }" (Fresnel's law from none up to R), while
# "reflection { R }" and "reflection { R falloff F }" stay a constant R
# (measured: a dark plane under a gradient sky, ior 1.5; the pixels of
# each pair were identical in povray's renders).  Part 1 checks those
# equalities and that the Fresnel form differs from the constant one;
# part 2, with povray installed, compares the picture (SSIM >= 0.99).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
scene() { # $1 = the reflection block
  cat <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2.5,-4> look_at <0.5,1,0> angle 50 right x*4/3 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6,0.7,1>] [0.7 rgb <0,0.1,0.8>] } } }
light_source { <-30,30,-30> rgb 1 }
plane { y, 0 pigment { rgb 0.01 }
  finish { diffuse 0.8 specular 0.6 $1 } interior { ior 1.5 } }
POV
}
render() { # name, reflection block
  scene "$2" >"$1.pov"
  timeout 60 "$zrcube" +I"$1.pov" +O"$1.png" +W64 +H48 -D +WT1 >"$1.log" 2>&1 || {
    echo "zrcube failed on $1:" >&2; cat "$1.log" >&2; exit 1; }
}
fail=0
render one_fresnel 'reflection { 0.5 fresnel }'
render two_fresnel 'reflection { 0, 0.5 fresnel }'
render one 'reflection { 0.5 }'
render one_falloff 'reflection { 0.5 falloff 3 }'
same() {
  if cmp -s "$1.png" "$2.png"; then echo "ok: $1 = $2"
  else echo "FAIL: $1 and $2 differ (povray renders them alike)"; fail=1; fi
}
same one_fresnel two_fresnel
same one one_falloff
if cmp -s one.png one_fresnel.png; then
  echo "FAIL: fresnel made no difference"; fail=1
else
  echo "ok: the fresnel form differs from the constant one"
fi
if command -v povray >/dev/null 2>&1; then
  timeout 120 povray +Ione_fresnel.pov +Opov.png +W64 +H48 -D -A +WT1 -GA \
    </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
  if out=$("$imgcmp" one_fresnel.png pov.png --ssim-min 0.99); then
    echo "ok: reflection { 0.5 fresnel } against povray: $out"
  else
    echo "FAIL: reflection { 0.5 fresnel } against povray: $out"; fail=1
  fi
else
  echo "no povray: the picture comparison is skipped"
fi
exit $fail
