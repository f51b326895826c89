#!/bin/sh
# test_photons.sh - photon mapping (lib/trace/photons.c) on
# tests/photons_check.pov:
#   1. photons through a clear slab of ior 1 bring the floor the light it
#      gets without the slab (within 3%, linear PFM, tests/imgcmp
#      --rmse), for a slab near the floor and one three times nearer the
#      light: a photon's power follows its whole path length, as
#      povray's photons do (a fixed power would light the far case nine
#      times less);
#   2. a light whose photons are switched off renders the lens scene
#      byte for byte as without photons; misplaced items and impossible
#      values stop with a located error;
#   3. with povray installed, the lens's caustic and photon shadow match
#      povray's picture (SSIM >= 0.95, 160x120).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/photons_check.pov" . || exit 99
scene() { # name case far lights
  printf '#declare Case = %s; #declare Far = %s; #declare Lights = %s;\n#include "photons_check.pov"\n' \
    "$2" "$3" "$4" >"$1.pov"
}
render() { # name size format
  timeout 120 "$zrcube" +I"$1.pov" +O"$1.$3" +W"$2" +H"$2" -D +WT1 \
    >"$1.log" 2>&1 || { echo "zrcube failed on $1:" >&2; cat "$1.log" >&2; exit 1; }
}
fail=0
scene bare 0 0 1; scene near_floor 1 0 1; scene near_light 1 1 1
for s in bare near_floor near_light; do render $s 16 pfm; done
for s in near_floor near_light; do
  if out=$("$imgcmp" $s.pfm bare.pfm --rmse --rmse-max 0.03); then
    echo "ok: slab $s: photons give the unshadowed floor: $out"
  else
    echo "FAIL: slab $s: photons do not give the unshadowed floor: $out"
    fail=1
  fi
done
scene lens 2 0 1; scene lens_off 2 0 0; scene lens_none 3 0 1
for s in lens_off lens_none; do render $s 48 png; done
if cmp -s lens_off.png lens_none.png; then
  echo "ok: a light without photons shades as without photons"
else
  echo "FAIL: a light without photons changes the picture"
  fail=1
fi
# Bad blocks stop with a located message.
while IFS='|' read -r text expect; do
  printf '%s\nsphere { 0, 1 }\n' "$text" >bad.pov
  if "$zrcube" +Ibad.pov +Obad.png +W8 +H8 -D >bad.log 2>&1; then
    echo "FAIL: '$text' was accepted"
    fail=1
  elif grep -q "bad.pov:[0-9]*:[0-9]*: error: .*$expect" bad.log; then
    echo "ok: '$text': $(head -1 bad.log)"
  else
    echo "FAIL: '$text': $(head -1 bad.log)"
    fail=1
  fi
done <<'BAD'
global_settings { photons { spacing -1 } }|must be above 0
global_settings { photons { jitter 0.2 } }|needs 'spacing' or 'count'
global_settings { photons { count 10 gather 50, 20 } }|must not exceed
global_settings { photons { target } }|'target' does not belong
light_source { 0, 1 photons { collect off } }|'collect' does not belong
sphere { 0, 1 photons { spacing 0.1 } }|'spacing' does not belong
BAD
if command -v povray >/dev/null 2>&1; then
  render lens 160 png
  timeout 120 povray +Ilens.pov +Opov.png +W160 +H160 -D -A +WT1 -GA \
    </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
  if out=$("$imgcmp" lens.png pov.png --ssim-min 0.95); then
    echo "ok: the lens's caustic against povray: $out"
  else
    echo "FAIL: the lens's caustic against povray: $out"
    fail=1
  fi
else
  echo "no povray: the picture comparison is skipped"
fi
exit $fail
