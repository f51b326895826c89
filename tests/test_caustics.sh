#!/bin/sh
# test_caustics.sh - simulated caustics (interior { caustics P }) follow
# the law measured from povray 3.7 (bench/conform/caustics_probe.sh):
# light through each crossed surface gains by 1 + |cos|^(45 P).  Part 1
# renders tests/caustics_check.pov with the caustic disc or slab, and
# without it under a light made brighter by the factor povray's
# renders gave (recorded below); the two must agree to 0.2% (linear
# PFM, tests/imgcmp --rmse).  Part 2, when povray is installed, compares
# a bumpy water surface's caustics with povray's picture (SSIM >= 0.99).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/caustics_check.pov" "$srcdir/tests/caustics_bumps.pov" . ||
  exit 99
fail=0
# angle power slab povray's ratio (bench/conform/caustics_probe.sh)
while read -r th p slab ratio; do
  printf '#declare TH = %s; #declare P = %s; #declare Slab = %s;\n#include "caustics_check.pov"\n' \
    "$th" "$p" "$slab" >a.pov
  printf '#declare TH = %s; #declare P = -1; #declare Gain = %s;\n#include "caustics_check.pov"\n' \
    "$th" "$ratio" >b.pov
  for s in a b; do
    timeout 60 "$zrcube" +I$s.pov +O$s.pfm +W16 +H16 -D +WT1 >$s.log 2>&1 || {
      echo "zrcube failed on $s.pov:" >&2; cat $s.log >&2; exit 1; }
  done
  if out=$("$imgcmp" a.pfm b.pfm --rmse --rmse-max 0.002); then
    echo "ok: $th degrees, caustics $p, slab $slab: $out"
  else
    echo "FAIL: $th degrees, caustics $p, slab $slab (povray: x$ratio): $out"
    fail=1
  fi
done <<'CASES'
0 0.25 0 2.0000
0 1 0 2.0000
10 1 0 1.5021
20 0.25 0 1.4967
20 0.5 0 1.2467
20 1 0 1.0609
40 0.25 0 1.0499
20 0.5 1 1.5543
CASES
if command -v povray >/dev/null 2>&1; then
  timeout 120 povray +Icaustics_bumps.pov +Opov.png +W160 +H160 -D -A +WT1 \
    -GA </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
  timeout 120 "$zrcube" +Icaustics_bumps.pov +Ozr.png +W160 +H160 -D +WT1 \
    >zr.log 2>&1 || { cat zr.log >&2; exit 1; }
  if out=$("$imgcmp" zr.png pov.png --ssim-min 0.99); then
    echo "ok: bumpy water against povray: $out"
  else
    echo "FAIL: bumpy water against povray: $out"
    fail=1
  fi
else
  echo "no povray: the picture comparison is skipped"
fi
exit $fail
