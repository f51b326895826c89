#!/bin/sh
# test_layer_tir.sh - total internal reflection under a layered texture
# (tests/layer_tir.pov) spawns one mirrored ray, not one per layer:
# povray 3.7 counts 72046 reflected rays for this scene at 160x120
# (its +GS statistics, recorded below; rerun when povray is present).
# Before, every layer traced its own reflection of weight near 1 at each
# bounce inside the glass: 7.45 million rays and a glowing block.  When
# povray is installed the picture is compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/layer_tir.pov" . || exit 99
pov_reflected=72046 # povray 3.7.0.10, +W160 +H120 -A +WT1 +GS +GR -GD
if command -v povray >/dev/null 2>&1; then
  timeout 120 povray +Ilayer_tir.pov +Opov.png +W160 +H120 -D -A +WT1 \
    +GS +GR -GD </dev/null >pov.log 2>&1 || { tail -3 pov.log >&2; exit 99; }
  pov_reflected=$(awk '/^Reflected Rays:/ { print $3 }' pov.log)
fi
timeout 120 "$zrcube" +Ilayer_tir.pov +Ozr.png +W160 +H120 -D +WT1 +V +GS \
  >zr.log 2>&1 || { cat zr.log >&2; exit 1; }
zr_reflected=$(awk '/^Reflected Rays:/ { print $3 }' zr.log)
fail=0
# Within 25% of povray's count (we trace 58471).
if [ -n "$zr_reflected" ] && [ -n "$pov_reflected" ] &&
   [ "$zr_reflected" -le $((pov_reflected * 5 / 4)) ]; then
  echo "ok: $zr_reflected reflected rays (povray: $pov_reflected)"
else
  echo "FAIL: ${zr_reflected:-?} reflected rays (povray: $pov_reflected)"
  fail=1
fi
if [ -f pov.png ]; then
  if out=$("$imgcmp" zr.png pov.png --ssim-min 0.85); then
    echo "ok: against povray's picture: $out"
  else
    echo "FAIL: against povray's picture: $out"
    fail=1
  fi
else
  echo "no povray: the picture comparison is skipped"
fi
exit $fail
